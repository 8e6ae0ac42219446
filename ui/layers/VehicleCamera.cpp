#include "VehicleCamera.h"

#include "MapView.h"
#include "WebMercator.h"

#include <QScopedValueRollback>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
// A frame never zooms closer than about 400 m across (one vehicle alone, or all at one spot).
constexpr double kMinimumFrameDegrees = 0.004;
// How far from the map's edges fitAll() keeps the vehicles when autoFit frames them.
constexpr qreal kAutoFitMargin = 60;
} // namespace

VehicleCamera::VehicleCamera(const std::vector<VehicleMark> &vehicles, QObject *parent)
    : QObject(parent)
    , m_vehicles(vehicles)
{
}

void VehicleCamera::setMap(MapView *map)
{
    if (map == m_map)
        return;
    if (m_map)
        disconnect(m_map, nullptr, this, nullptr);
    m_map = map;
    if (!m_map)
        return;
    remember();
    connect(m_map, &MapView::viewportChanged, this, &VehicleCamera::onMapMoved);
    // A map that gets its size after the vehicles came (a page shown later) frames them then.
    auto refit = [this] {
        if (m_autoFit) {
            m_fittedCount = 0;
            keepInView();
        }
    };
    connect(m_map, &QQuickItem::widthChanged, this, refit);
    connect(m_map, &QQuickItem::heightChanged, this, refit);
}

void VehicleCamera::remember()
{
    m_framed = {m_map->latitude(), m_map->longitude(), m_map->zoomLevel()};
}

// The operator (or another layer framing its own things) moved the map: autoFit stops.
void VehicleCamera::onMapMoved()
{
    if (m_movingMap || !m_autoFit || !m_map)
        return;
    // A resize keeps the centre and zoom; only a pan or a zoom by the operator changes them.
    if (std::abs(m_map->zoomLevel() - m_framed.zoom) < 1e-9 && std::abs(m_map->latitude() - m_framed.latitude) < 1e-9
        && std::abs(m_map->longitude() - m_framed.longitude) < 1e-9)
        return;
    m_autoFit = false;
    emit autoFitChanged();
}

void VehicleCamera::setFollow(bool follow)
{
    if (follow == m_follow)
        return;
    m_follow = follow;
    emit followChanged();
    if (m_follow)
        centerOn(m_current);
}

void VehicleCamera::setAutoFit(bool on)
{
    if (on == m_autoFit)
        return;
    m_autoFit = on;
    m_fittedCount = 0;
    emit autoFitChanged();
    keepInView();
}

void VehicleCamera::setCurrent(int row)
{
    m_current = row;
    if (m_follow)
        centerOn(m_current);
}

int VehicleCamera::positionedCount() const
{
    return int(std::count_if(m_vehicles.begin(), m_vehicles.end(), [](const VehicleMark &v) { return v.hasPosition(); }));
}

bool VehicleCamera::fitAll(qreal margin)
{
    // A map not laid out yet (a page not shown) is framed once it has its size.
    if (!m_map || m_map->width() <= 2 * margin || m_map->height() <= 2 * margin)
        return false;
    double south = 90, north = -90, west = 180, east = -180;
    bool any = false;
    auto include = [&](QPointF normalised) {
        if (std::isnan(normalised.x()))
            return;
        const QGeoCoordinate c = WebMercator::unproject(normalised);
        south = std::min(south, c.latitude());
        north = std::max(north, c.latitude());
        west = std::min(west, c.longitude());
        east = std::max(east, c.longitude());
    };
    for (const VehicleMark &vehicle : m_vehicles) {
        if (!vehicle.hasPosition())
            continue;
        any = true;
        include(vehicle.position);
        include(vehicle.home);
    }
    if (!any)
        return false;
    const double padLatitude = std::max(0.0, kMinimumFrameDegrees - (north - south)) / 2;
    const double padLongitude = std::max(0.0, kMinimumFrameDegrees - (east - west)) / 2;
    {
        QScopedValueRollback moving(m_movingMap, true);
        m_map->fitBounds(south - padLatitude, west - padLongitude, north + padLatitude, east + padLongitude, margin);
    }
    remember();
    return true;
}

bool VehicleCamera::centerOn(int row)
{
    if (!m_map || row < 0 || row >= int(m_vehicles.size()) || !m_vehicles[size_t(row)].hasPosition())
        return false;
    {
        QScopedValueRollback moving(m_movingMap, true);
        m_map->setCenter(WebMercator::unproject(m_vehicles[size_t(row)].position));
    }
    remember();
    return true;
}

// autoFit frames the fleet when a vehicle reports its first position; follow brings the
// current vehicle back to the middle once it leaves the middle half.
void VehicleCamera::keepInView()
{
    if (m_autoFit) {
        const int positioned = positionedCount();
        if (positioned > m_fittedCount && fitAll(kAutoFitMargin))
            m_fittedCount = positioned;
    }
    if (m_follow && m_map && m_current >= 0 && m_current < int(m_vehicles.size())
        && m_vehicles[size_t(m_current)].hasPosition()) {
        const QPointF at = m_map->viewport().toScreen(m_vehicles[size_t(m_current)].position);
        const QRectF middle(m_map->width() / 4, m_map->height() / 4, m_map->width() / 2, m_map->height() / 2);
        if (!middle.contains(at))
            centerOn(m_current);
    }
}

} // namespace sortie::ui
