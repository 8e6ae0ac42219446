#include "Graticule.h"

#include "WebMercator.h"

#include <QFontMetrics>
#include <QPainter>

#include <array>
#include <cmath>

namespace sortie::ui {

double Graticule::interval(const MapViewport &viewport, double minimumPixels)
{
    static constexpr std::array kSteps{0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05,
                                       0.1,    0.2,    0.5,    1.0,   2.0,   5.0,   10.0, 15.0, 30.0};
    const double pixelsPerDegree = viewport.scale() / 360.0;
    for (double step : kSteps) {
        if (step * pixelsPerDegree >= minimumPixels)
            return step;
    }
    return 30.0;
}

QString Graticule::label(double degrees, double interval, bool latitude)
{
    const int decimals = interval >= 1.0 ? 0 : int(std::ceil(-std::log10(interval) - 1e-9));
    const QChar hemisphere = latitude ? (degrees < 0 ? u'S' : u'N') : (degrees < 0 ? u'W' : u'E');
    const double magnitude = std::abs(degrees);
    if (magnitude < interval / 2.0)
        return QStringLiteral("0°");
    return QStringLiteral("%1°%2").arg(magnitude, 0, 'f', decimals).arg(hemisphere);
}

QFont Graticule::labelFont(const QFont &base)
{
    QFont font = base;
    font.setPixelSize(10);
    return font;
}

QMarginsF Graticule::labelBands(const QFontMetrics &metrics)
{
    // The longest latitude label: two digits, four decimals (the finest interval), a hemisphere.
    const qreal left = 3 + metrics.horizontalAdvance(QStringLiteral("88.8888°N")) + 3;
    const qreal top = metrics.ascent() + 2 + metrics.descent() + 2;
    return {left, top, 0, 0};
}

std::vector<Graticule::Label> Graticule::labels(const MapViewport &viewport, const QFontMetrics &metrics)
{
    std::vector<Label> out;
    const double step = interval(viewport);
    const QRectF visible = viewport.visibleNormalised();
    // Each label whole inside the view, longitudes right of the latitudes' band and latitudes
    // below the longitudes' band, so that no two labels cross.
    const QMarginsF bands = labelBands(metrics);
    const QRectF view(QPointF(0, 0), viewport.size());
    auto add = [&](QPointF baseline, QString text, bool latitude) {
        const QRectF rect(baseline.x(), baseline.y() - metrics.ascent(), metrics.horizontalAdvance(text), metrics.height());
        if (!view.contains(rect) || (latitude ? rect.top() < bands.top() : rect.left() < bands.left()))
            return;
        out.push_back({baseline, rect, std::move(text)});
    };
    const double westLon = visible.left() * 360.0 - 180.0;
    const double eastLon = visible.right() * 360.0 - 180.0;
    for (double k = std::ceil(westLon / step); k * step <= eastLon; k += 1.0) {
        const double lon = k * step;
        const double x = viewport.toScreenUnwrapped(QPointF((lon + 180.0) / 360.0, 0)).x();
        double wrapped = std::fmod(lon + 180.0, 360.0);
        if (wrapped < 0)
            wrapped += 360.0;
        add(QPointF(x + 3, metrics.ascent() + 2), label(wrapped - 180.0, step, false), false);
    }
    const double north = WebMercator::unproject(QPointF(0, std::max(0.0, visible.top()))).latitude();
    const double south = WebMercator::unproject(QPointF(0, std::min(1.0, visible.bottom()))).latitude();
    for (double k = std::ceil(south / step); k * step <= north; k += 1.0) {
        const double lat = k * step;
        const double y = viewport.toScreenUnwrapped(WebMercator::project(lat, 0)).y();
        add(QPointF(3, y - 3), label(lat, step, true), true);
    }
    return out;
}

void Graticule::paint(QPainter &painter, const MapViewport &viewport, const MapPalette &palette)
{
    const double step = interval(viewport);
    const QSizeF size = viewport.size();
    const QRectF visible = viewport.visibleNormalised();
    const QFont font = labelFont(painter.font());
    painter.setFont(font);
    const QFontMetrics metrics(font);
    painter.setPen(QPen(palette.graticule, 1.0));

    // Meridians: vertical lines; parallels: horizontal lines, unevenly spaced in Mercator.
    const double westLon = visible.left() * 360.0 - 180.0;
    const double eastLon = visible.right() * 360.0 - 180.0;
    for (double k = std::ceil(westLon / step); k * step <= eastLon; k += 1.0) {
        const double x = viewport.toScreenUnwrapped(QPointF((k * step + 180.0) / 360.0, 0)).x();
        painter.drawLine(QPointF(x, 0), QPointF(x, size.height()));
    }
    const double north = WebMercator::unproject(QPointF(0, std::max(0.0, visible.top()))).latitude();
    const double south = WebMercator::unproject(QPointF(0, std::min(1.0, visible.bottom()))).latitude();
    for (double k = std::ceil(south / step); k * step <= north; k += 1.0) {
        const double y = viewport.toScreenUnwrapped(WebMercator::project(k * step, 0)).y();
        painter.drawLine(QPointF(0, y), QPointF(size.width(), y));
    }
    painter.setPen(palette.label);
    for (const Label &l : labels(viewport, metrics))
        painter.drawText(l.baseline, l.text);
}

} // namespace sortie::ui
