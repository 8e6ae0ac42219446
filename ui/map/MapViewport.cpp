#include "MapViewport.h"

#include "WebMercator.h"

#include <algorithm>
#include <cmath>

namespace sortie::ui {

MapViewport::MapViewport(QPointF centre, double zoom, QSizeF size)
    : m_size(size)
{
    setZoom(zoom);
    setCentre(centre);
}

void MapViewport::setCentre(QPointF normalised)
{
    const double x = normalised.x() - std::floor(normalised.x());
    m_centre = QPointF(x, std::clamp(normalised.y(), 0.0, 1.0));
}

void MapViewport::setZoom(double zoom)
{
    m_zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    m_scale = WebMercator::worldSize(m_zoom);
}

QPointF MapViewport::toScreen(QPointF normalised) const
{
    double dx = normalised.x() - m_centre.x();
    dx -= std::round(dx);
    return {dx * m_scale + m_size.width() / 2.0, (normalised.y() - m_centre.y()) * m_scale + m_size.height() / 2.0};
}

QPointF MapViewport::toScreenUnwrapped(QPointF normalised) const
{
    return (normalised - m_centre) * m_scale + QPointF(m_size.width() / 2.0, m_size.height() / 2.0);
}

QPointF MapViewport::toNormalised(QPointF screen) const
{
    return m_centre + (screen - QPointF(m_size.width() / 2.0, m_size.height() / 2.0)) / m_scale;
}

QPointF MapViewport::geoToScreen(const QGeoCoordinate &coordinate) const
{
    return toScreen(WebMercator::project(coordinate));
}

QGeoCoordinate MapViewport::screenToGeo(QPointF screen) const
{
    return WebMercator::unproject(toNormalised(screen));
}

QRectF MapViewport::visibleNormalised() const
{
    const QPointF half(m_size.width() / 2.0 / m_scale, m_size.height() / 2.0 / m_scale);
    return QRectF(m_centre - half, m_centre + half);
}

double MapViewport::metersPerPixel() const
{
    return WebMercator::metersPerPixel(WebMercator::unproject(m_centre).latitude(), m_zoom);
}

void MapViewport::panByPixels(QPointF delta)
{
    setCentre(m_centre - delta / m_scale);
}

void MapViewport::zoomAround(QPointF screen, double zoom)
{
    const QPointF anchor = toNormalised(screen);
    setZoom(zoom);
    const QPointF offset = (screen - QPointF(m_size.width() / 2.0, m_size.height() / 2.0)) / m_scale;
    setCentre(anchor - offset);
}

} // namespace sortie::ui
