#include "TileArea.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace sortie::maptiles {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMetresPerDegree = 2 * kPi * 6378137.0 / 360.0; // along a meridian of the Web Mercator sphere
// Tiles that an area only touches along an edge or at a corner hold none of it: spans are shrunk
// by this fraction of a tile before rounding outwards.
constexpr double kTouch = 1e-9;


double mercatorU(double longitude) { return (longitude + 180.0) / 360.0; }
double mercatorV(double latitude)
{
    const double lat = std::clamp(latitude, -TileArea::kMaximumLatitude, TileArea::kMaximumLatitude) * kPi / 180.0;
    return 0.5 - std::log(std::tan(kPi / 4 + lat / 2)) / (2 * kPi);
}

struct Interval { double from; double to; };

// Which side of the line a→b the point p lies on: +1 left, -1 right, 0 on it.
int sideOf(QPointF a, QPointF b, QPointF p)
{
    const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
    return cross > 0 ? 1 : cross < 0 ? -1 : 0;
}

// The first pair of edges (i, j), i < j, that cross each other's interior; {-1, -1} if none. Edges
// that only touch are not crossings: their tiles are counted the same either way. Quadratic, for
// the few dozen corners an operator draws.
std::pair<qsizetype, qsizetype> firstCrossing(const QList<QPointF> &ring)
{
    const qsizetype n = ring.size();
    for (qsizetype i = 0; i < n; ++i) {
        const QPointF a = ring.at(i), b = ring.at((i + 1) % n);
        for (qsizetype j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1)
                continue; // the two edges meeting at the first corner
            const QPointF c = ring.at(j), d = ring.at((j + 1) % n);
            if (sideOf(a, b, c) * sideOf(a, b, d) < 0 && sideOf(c, d, a) * sideOf(c, d, b) < 0)
                return {i, j};
        }
    }
    return {-1, -1};
}

// Closed column interval covering (from, to) in tile units, never empty.
std::pair<int, int> columnsOf(double from, double to)
{
    const int first = int(std::floor(from + kTouch));
    const int last = std::max(first, int(std::ceil(to - kTouch)) - 1);
    return {first, last};
}

// Merges column intervals (possibly beyond n across the antimeridian) into sorted spans of one row.
void appendSpans(QList<TileSpan> &out, int row, int n, std::vector<std::pair<int, int>> columns)
{
    std::vector<std::pair<int, int>> wrapped;
    for (auto [first, last] : columns) {
        first = std::max(first, 0);
        last = std::min(last, 2 * n - 1);
        if (first > last)
            continue;
        if (last - first + 1 >= n) {
            wrapped.push_back({0, n - 1});
        } else if (first >= n) {
            wrapped.push_back({first - n, last - n});
        } else if (last >= n) {
            wrapped.push_back({first, n - 1});
            wrapped.push_back({0, last - n});
        } else {
            wrapped.push_back({first, last});
        }
    }
    std::sort(wrapped.begin(), wrapped.end());
    for (const auto &[first, last] : wrapped) {
        if (!out.isEmpty() && out.last().row == row && first <= out.last().lastColumn + 1)
            out.last().lastColumn = std::max(out.last().lastColumn, last);
        else
            out.append({row, first, last});
    }
}
} // namespace

bool GeoBounds::isValid() const
{
    return std::isfinite(south) && std::isfinite(north) && std::isfinite(west) && std::isfinite(east)
        && south < north && south >= -90 && north <= 90 && west >= -180 && west <= 180 && east >= -180 && east <= 180
        && west != east;
}

GeoBounds GeoBounds::grown(double metres) const
{
    const double dLat = metres / kMetresPerDegree;
    GeoBounds out = *this;
    out.south = std::max(-TileArea::kMaximumLatitude, south - dLat);
    out.north = std::min(TileArea::kMaximumLatitude, north + dLat);
    const double widestLat = std::max(std::abs(out.south), std::abs(out.north)) * kPi / 180.0;
    const double dLon = dLat / std::max(0.01, std::cos(widestLat));
    const double width = (east >= west ? east - west : east + 360 - west) + 2 * dLon;
    if (width >= 360) {
        out.west = -180;
        out.east = 180;
        return out;
    }
    auto wrap = [](double lon) { return lon < -180 ? lon + 360 : lon > 180 ? lon - 360 : lon; };
    out.west = wrap(west - dLon);
    out.east = wrap(east + dLon);
    return out;
}

TileArea TileArea::rectangle(const GeoBounds &bounds)
{
    TileArea area;
    if (!bounds.isValid()) {
        area.m_problem = QCoreApplication::translate("TileArea", "The area is not a valid latitude/longitude box (south %1, west %2, north %3, east %4).")
                             .arg(bounds.south).arg(bounds.west).arg(bounds.north).arg(bounds.east);
        return area;
    }
    const double east = bounds.east > bounds.west ? bounds.east : bounds.east + 360;
    const double u0 = mercatorU(bounds.west), u1 = mercatorU(east);
    const double v0 = mercatorV(bounds.north), v1 = mercatorV(bounds.south);
    area.m_corners = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    area.m_bounds = bounds;
    area.m_isRectangle = true;
    return area;
}

TileArea TileArea::polygon(const QList<QPointF> &lonLat)
{
    TileArea area;
    if (lonLat.size() < 3) {
        area.m_problem = QCoreApplication::translate("TileArea", "An area needs at least three corners (it has %1).").arg(lonLat.size());
        return area;
    }
    GeoBounds box{90, 180, -90, -180};
    for (qsizetype i = 0; i < lonLat.size(); ++i) {
        const QPointF p = lonLat.at(i);
        const QPointF next = lonLat.at((i + 1) % lonLat.size());
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || std::abs(p.y()) > 90 || std::abs(p.x()) > 180) {
            area.m_problem = QCoreApplication::translate("TileArea", "Corner %1 of the area is not a latitude/longitude (%2, %3).").arg(i + 1).arg(p.y()).arg(p.x());
            return area;
        }
        if (std::abs(next.x() - p.x()) > 180) {
            area.m_problem = QCoreApplication::translate("TileArea", "The area's edge from corner %1 crosses the antimeridian: draw it as two areas.").arg(i + 1);
            return area;
        }
        box = {std::min(box.south, p.y()), std::min(box.west, p.x()), std::max(box.north, p.y()), std::max(box.east, p.x())};
        area.m_corners.append({mercatorU(p.x()), mercatorV(p.y())});
    }
    if (const auto [first, second] = firstCrossing(lonLat); first >= 0) {
        area.m_corners.clear();
        area.m_problem = QCoreApplication::translate("TileArea", "The area's edges from corner %1 and corner %2 cross: draw it without crossing.").arg(first + 1).arg(second + 1);
        return area;
    }
    area.m_bounds = box;
    area.m_lonLat = lonLat;
    return area;
}

QList<QPointF> TileArea::corners() const
{
    if (isEmpty())
        return {};
    if (!m_isRectangle)
        return m_lonLat;
    const GeoBounds &b = m_bounds;
    return {{b.west, b.north}, {b.east, b.north}, {b.east, b.south}, {b.west, b.south}};
}

QList<TileSpan> TileArea::spans(int zoom) const
{
    QList<TileSpan> out;
    if (isEmpty() || zoom < 0 || zoom > kMaximumZoom)
        return out;
    const int n = 1 << zoom;
    double vMin = 1, vMax = 0;
    for (const QPointF &c : m_corners)
        vMin = std::min(vMin, c.y()), vMax = std::max(vMax, c.y());
    const auto [firstRow, lastRowUnclamped] = columnsOf(vMin * n, vMax * n);
    const int lastRow = std::min(lastRowUnclamped, n - 1);
    if (m_isRectangle) {
        const auto cols = columnsOf(m_corners.at(0).x() * n, m_corners.at(1).x() * n);
        for (int row = std::max(0, firstRow); row <= lastRow; ++row)
            appendSpans(out, row, n, {cols});
        return out;
    }
    const qsizetype count = m_corners.size();
    std::vector<double> crossings;
    std::vector<std::pair<int, int>> columns;
    for (int row = std::max(0, firstRow); row <= lastRow; ++row) {
        const double top = double(row) / n, bottom = double(row + 1) / n, middle = (row + 0.5) / n;
        const double touch = kTouch / n;
        columns.clear();
        crossings.clear();
        for (qsizetype i = 0; i < count; ++i) {
            const QPointF a = m_corners.at(i), b = m_corners.at((i + 1) % count);
            const double lo = std::min(a.y(), b.y()), hi = std::max(a.y(), b.y());
            if ((a.y() > middle) != (b.y() > middle))
                crossings.push_back(a.x() + (middle - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
            if (hi <= top + touch || lo >= bottom - touch)
                continue;
            // The part of the edge inside the row: its columns hold some of the area's boundary.
            double u0 = a.x(), u1 = b.x();
            if (a.y() != b.y()) {
                const auto uAt = [&](double v) { return a.x() + (v - a.y()) * (b.x() - a.x()) / (b.y() - a.y()); };
                u0 = uAt(std::max(top, lo));
                u1 = uAt(std::min(bottom, hi));
            }
            const double from = std::min(u0, u1) * n, to = std::max(u0, u1) * n;
            if (to - from < kTouch && std::abs(from - std::round(from)) < kTouch)
                continue; // along a column's edge: the tiles on the area's side come from the crossings
            columns.push_back(columnsOf(from, to));
        }
        // Between crossings of the row's middle line the tiles lie inside the area.
        std::sort(crossings.begin(), crossings.end());
        for (size_t k = 0; k + 1 < crossings.size(); k += 2)
            columns.push_back(columnsOf(crossings[k] * n, crossings[k + 1] * n));
        appendSpans(out, row, n, columns);
    }
    return out;
}

qint64 TileArea::tileCount(int zoom) const
{
    if (m_isRectangle && zoom >= 0 && zoom <= kMaximumZoom) {
        // Every row alike: one row's spans times the rows.
        const int n = 1 << zoom;
        const double vMin = m_corners.at(0).y(), vMax = m_corners.at(2).y();
        const auto [firstRow, lastRow] = columnsOf(vMin * n, vMax * n);
        const qint64 rows = std::min(lastRow, n - 1) - std::max(0, firstRow) + 1;
        QList<TileSpan> row;
        appendSpans(row, 0, n, {columnsOf(m_corners.at(0).x() * n, m_corners.at(1).x() * n)});
        qint64 perRow = 0;
        for (const TileSpan &span : row)
            perRow += span.count();
        return rows * perRow;
    }
    qint64 total = 0;
    for (const TileSpan &span : spans(zoom))
        total += span.count();
    return total;
}

qint64 TileArea::tileCount(int minZoom, int maxZoom) const
{
    qint64 total = 0;
    for (int z = std::max(0, minZoom); z <= std::min(maxZoom, kMaximumZoom); ++z)
        total += tileCount(z);
    return total;
}

} // namespace sortie::maptiles
