#include "RouteFrame.h"

#include "ModelCoordinates.h"

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
    const std::unordered_set<int> dragged(input.draggedRows.begin(), input.draggedRows.end());
    auto normalisedAt = [&](size_t i) {
        const QPointF p = points[i];
        return dragged.count(int(i)) ? p + input.dragOffset : p;
    };
    auto isSelected = [&](size_t i) { return input.selected && i < input.selected->size() && (*input.selected)[i]; };

    // Screen positions, each leg taking the copy of the world nearest its previous point.
    std::vector<QPointF> screen(n);
    std::vector<bool> valid(n, false);
    QPointF previous;
    bool havePrevious = false;
    for (size_t i = 0; i < n; ++i) {
        const QPointF p = normalisedAt(i);
        if (std::isnan(p.x())) {
            havePrevious = false;
            continue;
        }
        const QPointF unwrapped = havePrevious ? nearestCopy(previous, p) : p;
        screen[i] = havePrevious ? viewport.toScreenUnwrapped(unwrapped) : viewport.toScreen(p);
        if (!havePrevious) {
            // Re-anchor the chain on the copy toScreen picked.
            previous = viewport.toNormalised(screen[i]);
        } else {
            previous = unwrapped;
        }
        havePrevious = true;
        valid[i] = true;
    }

    const double margin = input.markerRadius * 2 + 4;
    const QRectF view = QRectF(QPointF(0, 0), viewport.size()).adjusted(-margin, -margin, margin, margin);

    QPolygonF run;
    auto flush = [&] {
        if (run.size() >= 2)
            frame.legs.push_back(run);
        run.clear();
    };
    for (size_t i = 1; i < n; ++i) {
        if (!valid[i - 1] || !valid[i]) {
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
        if (valid[i] && view.contains(screen[i]))
            visible.push_back(int(i));
    }
    frame.visibleWaypoints = int(visible.size());
    LabelGrid grid(viewport.size(), input.markerRadius * 1.6);
    std::vector<Marker> onTop;
    // Selected and current markers claim their label space first.
    for (int row : visible) {
        const quint8 flags = quint8((isSelected(size_t(row)) ? Selected : 0) | (row == input.current ? Current : 0));
        if (flags)
            onTop.push_back({screen[size_t(row)], row, flags});
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
        const Marker marker{screen[size_t(row)], row, 0};
        if (grid.claim(marker.position))
            labelled.push_back({marker.position, row, Labelled});
        else
            frame.markers.push_back(marker);
    }
    frame.markers.insert(frame.markers.end(), labelled.begin(), labelled.end());
    frame.markers.insert(frame.markers.end(), onTop.begin(), onTop.end());
    for (const Marker &marker : frame.markers)
        frame.labelledWaypoints += (marker.flags & Labelled) ? 1 : 0;
    return frame;
}

} // namespace sortie::ui
