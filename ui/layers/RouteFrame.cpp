#include "RouteFrame.h"

#include "ModelCoordinates.h"
#include "Polyline.h"

#include <QRectF>

#include <cmath>
#include <unordered_set>

namespace sortie::ui {

namespace {

// A coarse occupancy grid: a label goes where no other label is.
class LabelGrid
{
public:
    LabelGrid(QSizeF size, double cell) : m_cell(cell), m_columns(int(size.width() / cell) + 3), m_rows(int(size.height() / cell) + 3),
        m_used(size_t(m_columns) * size_t(m_rows), false) {}

    bool claim(QPointF p)
    {
        const int c = int(std::floor(p.x() / m_cell)) + 1;
        const int r = int(std::floor(p.y() / m_cell)) + 1;
        if (c < 0 || r < 0 || c >= m_columns || r >= m_rows)
            return false;
        // A label is about two cells wide: check the neighbours too.
        for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) {
                const int cc = c + dc, rr = r + dr;
                if (cc >= 0 && rr >= 0 && cc < m_columns && rr < m_rows && m_used[size_t(rr) * size_t(m_columns) + size_t(cc)])
                    return false;
            }
        }
        m_used[size_t(r) * size_t(m_columns) + size_t(c)] = true;
        return true;
    }

private:
    double m_cell;
    int m_columns;
    int m_rows;
    std::vector<bool> m_used;
};

} // namespace

RouteFrame RouteFrame::build(const Input &input, const MapViewport &viewport)
{
    RouteFrame frame;
    if (!input.points || input.points->empty())
        return frame;
    const std::vector<QPointF> &points = *input.points;
    const size_t n = points.size();
    std::vector<bool> moving(n, false);
    for (int row : input.draggedRows) {
        if (row >= 0 && size_t(row) < n)
            moving[size_t(row)] = true;
    }
    auto isSelected = [&](size_t i) { return input.selected && i < input.selected->size() && (*input.selected)[i]; };
    auto marksOf = [&](size_t i) { return input.marks && i < input.marks->size() ? (*input.marks)[i] : quint8(0); };

    // Screen positions, each leg taking the copy of the world nearest its previous point.
    std::vector<QPointF> screen(n);
    std::vector<bool> valid(n, false);
    QPointF previous;
    bool havePrevious = false;
    for (size_t i = 0; i < n; ++i) {
        const QPointF p = points[i];
        if (std::isnan(p.x())) {
            havePrevious = false;
            continue;
        }
        if (havePrevious) {
            previous = nearestCopy(previous, p);
            screen[i] = viewport.toScreenUnwrapped(previous);
        } else {
            screen[i] = viewport.toScreen(p);
            previous = viewport.toNormalised(screen[i]); // the copy toScreen picked
        }
        havePrevious = true;
        valid[i] = true;
    }

    const double margin = input.markerRadius * 2 + 4;
    const QRectF view = QRectF(QPointF(0, 0), viewport.size()).adjusted(-margin, -margin, margin, margin);

    QPolygonF run;
    auto flush = [&] {
        if (run.size() >= 2)
            frame.legs.push_back(simplifyPolyline(run, 0.3));
        run.clear();
    };
    for (size_t i = 1; i < n; ++i) {
        if (!valid[i - 1] || !valid[i] || moving[i - 1] || moving[i]) {
            flush();
            continue;
        }
        const QPointF a = screen[i - 1];
        const QPointF b = screen[i];
        const QRectF box = QRectF(a, b).normalized().adjusted(-1, -1, 1, 1);
        if (!box.intersects(view)) {
            flush();
            continue;
        }
        if (run.isEmpty())
            run.append(a);
        run.append(b);
    }
    flush();

    std::vector<int> visible;
    for (size_t i = 0; i < n; ++i) {
        if (valid[i] && !moving[i] && view.contains(screen[i]))
            visible.push_back(int(i));
    }
    LabelGrid grid(viewport.size(), input.markerRadius * 1.6);
    std::vector<Marker> onTop;
    // Selected and current markers claim their label space first.
    for (int row : visible) {
        const quint8 flags = quint8((isSelected(size_t(row)) ? Selected : 0) | (row == input.current ? Current : 0));
        if (flags)
            onTop.push_back({screen[size_t(row)], row, flags, marksOf(size_t(row))});
    }
    for (Marker &marker : onTop) {
        if (grid.claim(marker.position))
            marker.flags |= Labelled;
    }
    // Dots under labelled markers, labelled markers under selected ones.
    std::vector<Marker> labelled;
    frame.markers.reserve(visible.size());
    for (int row : visible) {
        if (isSelected(size_t(row)) || row == input.current)
            continue;
        const Marker marker{screen[size_t(row)], row, 0, marksOf(size_t(row))};
        if (grid.claim(marker.position))
            labelled.push_back({marker.position, row, Labelled, marker.marks});
        else
            frame.markers.push_back(marker);
    }
    frame.markers.insert(frame.markers.end(), labelled.begin(), labelled.end());
    frame.markers.insert(frame.markers.end(), onTop.begin(), onTop.end());
    for (const Marker &marker : frame.markers)
        frame.labelledWaypoints += (marker.flags & Labelled) ? 1 : 0;
    const QRectF counted = input.visibleArea.isEmpty() ? view : input.visibleArea.adjusted(-margin, -margin, margin, margin);
    for (int row : visible)
        frame.visibleWaypoints += counted.contains(screen[size_t(row)]) ? 1 : 0;
    frame.updateMoving(input, viewport);
    return frame;
}

void RouteFrame::updateMoving(const Input &input, const MapViewport &viewport)
{
    const int movingVisibleBefore = int(movingMarkers.size());
    movingLegs.clear();
    movingMarkers.clear();
    if (!input.points || input.draggedRows.empty()) {
        visibleWaypoints -= movingVisibleBefore;
        return;
    }
    const std::vector<QPointF> &points = *input.points;
    const int n = int(points.size());
    const std::unordered_set<int> moving(input.draggedRows.begin(), input.draggedRows.end());
    auto at = [&](int row) { return moving.count(row) ? points[size_t(row)] + input.dragOffset : points[size_t(row)]; };
    auto isSelected = [&](int i) { return input.selected && size_t(i) < input.selected->size() && (*input.selected)[size_t(i)]; };
    // Each leg with a moving end, once.
    for (int row : input.draggedRows) {
        for (int first : {row - 1, row}) {
            const int second = first + 1;
            if (first < 0 || second >= n || (first == row - 1 && moving.count(first)))
                continue;
            if (std::isnan(points[size_t(first)].x()) || std::isnan(points[size_t(second)].x()))
                continue;
            const QPointF a = viewport.toScreen(at(first));
            const QPointF b = viewport.toScreenUnwrapped(nearestCopy(viewport.toNormalised(a), at(second)));
            movingLegs.push_back(QPolygonF{a, b});
        }
    }
    for (int row : input.draggedRows) {
        if (row < 0 || row >= n || std::isnan(points[size_t(row)].x()))
            continue;
        const quint8 flags = quint8(Labelled | (isSelected(row) ? Selected : 0) | (row == input.current ? Current : 0));
        const quint8 marks = input.marks && size_t(row) < input.marks->size() ? (*input.marks)[size_t(row)] : quint8(0);
        movingMarkers.push_back({viewport.toScreen(at(row)), row, flags, marks});
    }
    visibleWaypoints += int(movingMarkers.size()) - movingVisibleBefore;
}

} // namespace sortie::ui
