#include "VehicleTrails.h"

#include "MapViewport.h"
#include "ModelCoordinates.h"
#include "Polyline.h"

#include <QPainter>

#include <cmath>

namespace sortie::ui {

namespace {
// Positions closer than this (about half a metre at the equator) add nothing to a trail.
constexpr double kTrailStep = 1.2e-8;
// Trails are drawn this translucent over the map (170 of 255).
constexpr qreal kTrailOpacity = 170.0 / 255.0;
} // namespace

bool VehicleTrails::setLength(int points)
{
    points = std::max(0, points);
    if (points == m_length)
        return false;
    m_length = points;
    for (Trail &trail : m_trails) {
        while (int(trail.points.size()) > m_length) {
            trail.points.pop_front();
            ++trail.dropped;
        }
    }
    redrawAll();
    return true;
}

bool VehicleTrails::setVisible(bool visible)
{
    if (visible == m_visible)
        return false;
    m_visible = visible;
    redrawAll();
    return true;
}

void VehicleTrails::record(const VehicleMark &vehicle)
{
    if (!vehicle.hasPosition() || m_length == 0)
        return;
    Trail &trail = m_trails[vehicle.id];
    if (!trail.points.empty()) {
        const QPointF d = vehicle.position - trail.points.back();
        if (std::abs(d.x()) < kTrailStep && std::abs(d.y()) < kTrailStep)
            return;
    }
    trail.points.push_back(vehicle.position);
    cut(trail);
}

void VehicleTrails::cut(Trail &trail)
{
    while (int(trail.points.size()) > m_length) {
        trail.points.pop_front();
        ++trail.dropped;
        // The picture still shows the cut points: redraw once they are a noticeable part.
        if (++m_cutSinceRedraw > std::max(16, m_length / 16))
            redrawAll();
    }
}

void VehicleTrails::clear()
{
    m_trails.clear();
    redrawAll();
}

void VehicleTrails::redrawAll()
{
    m_stale = true;
    m_cutSinceRedraw = 0;
}

int VehicleTrails::pointCount(const QString &vehicleId) const
{
    const auto it = m_trails.constFind(vehicleId);
    return it == m_trails.cend() ? 0 : int(it->points.size());
}

// Whole trails after a new layout, otherwise each trail's piece since the last layout.
void VehicleTrails::layOut(const MapViewport &view, const std::vector<VehicleMark> &vehicles)
{
    const bool whole = m_stale;
    const QRectF screen = QRectF(QPointF(0, 0), view.size()).adjusted(-30, -30, 30, 30);
    std::vector<TrailPicture::Stroke> strokes;
    for (const VehicleMark &vehicle : vehicles) {
        const auto found = m_trails.find(vehicle.id);
        if (found == m_trails.end() || !vehicle.hasPosition())
            continue;
        Trail &trail = *found;
        const qint64 end = trail.dropped + qint64(trail.points.size());
        const qint64 first = whole ? trail.dropped : std::max(trail.dropped, trail.drawn - 1);
        trail.drawn = end;
        if (!m_visible || end - first < 2)
            continue;
        // The trail is drawn beside the copy of the world its vehicle is drawn in.
        const QPointF anchor = view.toNormalised(view.toScreen(vehicle.position));
        const size_t n = size_t(end - first);
        std::vector<QPointF> points(n);
        std::vector<bool> inside(n);
        for (size_t i = 0; i < n; ++i) {
            points[i] = view.toScreenUnwrapped(nearestCopy(anchor, trail.points[size_t(first - trail.dropped) + i]));
            inside[i] = screen.contains(points[i]);
        }
        // Only the parts of the trail near the picture are kept for drawing.
        const QColor color = vehicle.shownColor();
        QPolygonF run;
        for (size_t i = 0; i < n; ++i) {
            const bool keep = inside[i] || (i > 0 && inside[i - 1]) || (i + 1 < n && inside[i + 1]);
            if (keep) {
                run.append(points[i]);
            } else if (!run.isEmpty()) {
                strokes.push_back({simplifyPolyline(run, 0.4), color});
                run.clear();
            }
        }
        if (run.size() > 1)
            strokes.push_back({simplifyPolyline(run, 0.4), color});
    }
    if (whole) {
        m_picture.restart(std::move(strokes));
        m_stale = false;
        m_cutSinceRedraw = 0;
    } else {
        for (TrailPicture::Stroke &stroke : strokes)
            m_picture.add(std::move(stroke));
    }
}

void VehicleTrails::paint(QPainter &painter)
{
    m_picture.paint(painter, kTrailOpacity);
}

} // namespace sortie::ui
