#include "CoverageSweep.h"

#include "PolygonGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <QCoreApplication>

namespace sortie::mission {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMinTransectLength = 0.01;  // metres: shorter crossings are grazes of a vertex

struct Interval { double u0, u1; };
struct Pass { int line; Interval interval; };
using Cell = std::vector<Pass>;  // one interval per line, consecutive lines

bool overlaps(const Interval &a, const Interval &b) { return a.u0 <= b.u1 && b.u0 <= a.u1; }

// Boustrophedon decomposition on the sampled sweep lines: an interval continues a cell when it is
// the only interval overlapping its predecessor and the predecessor overlaps only it.
std::vector<Cell> decompose(const std::vector<std::vector<Interval>> &lines)
{
    std::vector<Cell> cells;
    std::vector<int> previousCell;  // cell of each interval on the previous line
    for (size_t k = 0; k < lines.size(); ++k) {
        const auto &cur = lines[k];
        std::vector<int> currentCell(cur.size(), -1);
        if (k > 0) {
            const auto &prev = lines[k - 1];
            for (size_t j = 0; j < cur.size(); ++j) {
                int match = -1, count = 0;
                for (size_t i = 0; i < prev.size(); ++i)
                    if (overlaps(prev[i], cur[j])) { match = int(i); ++count; }
                if (count != 1)
                    continue;
                int back = 0;
                for (size_t jj = 0; jj < cur.size(); ++jj)
                    if (overlaps(prev[match], cur[jj])) ++back;
                if (back == 1 && previousCell[match] >= 0)
                    currentCell[j] = previousCell[match];
            }
        }
        for (size_t j = 0; j < cur.size(); ++j) {
            if (currentCell[j] < 0) {
                currentCell[j] = int(cells.size());
                cells.emplace_back();
            }
            cells[currentCell[j]].push_back({int(k), cur[j]});
        }
        previousCell = std::move(currentCell);
    }
    return cells;
}

struct PlaneSegment { double u0, v0, u1, v1; };  // in sweep coordinates (u along, v across)

// The passes of a cell in boustrophedon order, starting from the first or last line and from the
// low or high end of the first pass.
void flyCell(const Cell &cell, bool fromLastLine, bool fromHighEnd, double spacing, double v0, std::vector<PlaneSegment> &out)
{
    bool high = fromHighEnd;
    for (size_t n = 0; n < cell.size(); ++n) {
        const Pass &p = fromLastLine ? cell[cell.size() - 1 - n] : cell[n];
        const double v = v0 + p.line * spacing;
        out.push_back(high ? PlaneSegment{p.interval.u1, v, p.interval.u0, v} : PlaneSegment{p.interval.u0, v, p.interval.u1, v});
        high = !high;
    }
}

PlanarPolygonOutcome refusePolygon(ScanProblem problem, QString message, int vertex = -1)
{
    PlanarPolygonOutcome o;
    o.problem = problem;
    o.message = std::move(message);
    o.vertex = vertex;
    return o;
}

SweepOutcome refuseSweep(ScanProblem problem, QString message)
{
    SweepOutcome o;
    o.problem = problem;
    o.message = std::move(message);
    return o;
}
}

PlanarPolygonOutcome planarPolygon(std::vector<GeoPoint> polygon)
{
    if (polygon.size() > 1 && polygon.front() == polygon.back())
        polygon.pop_back();  // tolerate a closed ring (UgCS sends them closed)
    if (polygon.size() < 3)
        return refusePolygon(ScanProblem::TooFewVertices, QCoreApplication::translate("CoverageSweep", "An area scan needs a polygon of at least 3 vertices."));
    for (size_t i = 0; i < polygon.size(); ++i)
        if (!polygon[i].isValid())
            return refusePolygon(ScanProblem::InvalidVertex, QCoreApplication::translate("CoverageSweep", "Polygon vertex %1 is not a valid position.").arg(i + 1), int(i));

    const LocalTangentPlane plane(LocalTangentPlane::centroidOf(polygon));
    std::vector<PlanePoint> pts;
    pts.reserve(polygon.size());
    for (size_t i = 0; i < polygon.size(); ++i) {
        const PlanePoint p = plane.project(polygon[i]);
        if (std::hypot(p.x, p.y) > kMaxScanRadiusMeters)
            return refusePolygon(ScanProblem::TooLarge, QCoreApplication::translate("CoverageSweep", "The polygon spans more than 100 km; split it into smaller scans."), int(i));
        pts.push_back(p);
    }
    if (auto hit = polygon::firstSelfIntersection(pts))
        return refusePolygon(ScanProblem::SelfIntersecting, QCoreApplication::translate("CoverageSweep", "The scan polygon crosses itself (edges %1 and %2).")
                             .arg(hit->first + 1).arg(hit->second + 1), hit->second);
    const double area = std::abs(polygon::signedArea(pts));
    if (area < 1.0)
        return refusePolygon(ScanProblem::NoArea, QCoreApplication::translate("CoverageSweep", "The scan polygon has no area."));
    PlanarPolygonOutcome o;
    o.polygon = PlanarPolygon{plane, std::move(pts), area};
    return o;
}

SweepOutcome sweepPolygon(const std::vector<PlanePoint> &pts, double spacing, double directionDeg,
                          const std::optional<PlanePoint> &start)
{
    if (!(spacing > 0) || !std::isfinite(spacing))
        return refuseSweep(ScanProblem::NoTransects, QCoreApplication::translate("CoverageSweep", "The distance between passes must be positive."));
    // Sweep coordinates: u along the passes (bearing directionDeg), v to their right.
    const double theta = directionDeg * kDeg;
    const double dx = std::sin(theta), dy = std::cos(theta);
    std::vector<PlanePoint> sweep;
    sweep.reserve(pts.size());
    double vmin = std::numeric_limits<double>::max(), vmax = std::numeric_limits<double>::lowest();
    for (const auto &p : pts) {
        const PlanePoint s{p.x * dx + p.y * dy, p.x * dy - p.y * dx};
        vmin = std::min(vmin, s.y);
        vmax = std::max(vmax, s.y);
        sweep.push_back(s);
    }
    const double height = vmax - vmin;
    const double lineCount = std::max(1.0, std::ceil(height / spacing - 1e-9));
    if (lineCount > kMaxTransects)
        return refuseSweep(ScanProblem::TooManyTransects, QCoreApplication::translate("CoverageSweep", "The scan would need %1 transects; raise the altitude or lower the side overlap.")
                           .arg(qint64(lineCount)));
    const int lines = int(lineCount);
    const double v0 = vmin + (height - (lines - 1) * spacing) / 2;  // centred

    std::vector<std::vector<Interval>> intervals(lines);
    for (int k = 0; k < lines; ++k) {
        const std::vector<double> xs = polygon::crossingsAt(sweep, v0 + k * spacing);
        for (size_t i = 0; i + 1 < xs.size(); i += 2)
            if (xs[i + 1] - xs[i] >= kMinTransectLength)
                intervals[k].push_back({xs[i], xs[i + 1]});
    }
    const std::vector<Cell> cells = decompose(intervals);
    if (cells.empty())
        return refuseSweep(ScanProblem::NoTransects, QCoreApplication::translate("CoverageSweep", "The scan yields no transects: the polygon is too narrow."));

    // Fly the cells, each time entering the unvisited cell whose entry is nearest.
    std::vector<PlaneSegment> order;
    std::vector<bool> done(cells.size(), false);
    bool havePosition = start.has_value();
    double cu = start ? start->x * dx + start->y * dy : 0, cv = start ? start->x * dy - start->y * dx : 0;
    for (size_t visited = 0; visited < cells.size(); ++visited) {
        double best = std::numeric_limits<double>::max();
        size_t bestCell = 0;
        bool bestLast = false, bestHigh = false;
        for (size_t c = 0; c < cells.size(); ++c) {
            if (done[c])
                continue;
            for (bool last : {false, true}) {
                for (bool high : {false, true}) {
                    const Pass &p = last ? cells[c].back() : cells[c].front();
                    const double u = high ? p.interval.u1 : p.interval.u0;
                    const double v = v0 + p.line * spacing;
                    const double d = havePosition ? std::hypot(u - cu, v - cv) : (last ? 1.0 : 0.0) + (high ? 0.5 : 0.0);
                    if (d < best) { best = d; bestCell = c; bestLast = last; bestHigh = high; }
                }
            }
        }
        done[bestCell] = true;
        flyCell(cells[bestCell], bestLast, bestHigh, spacing, v0, order);
        cu = order.back().u1;
        cv = order.back().v1;
        havePosition = true;
    }

    SweepOutcome out;
    out.cells = int(cells.size());
    out.passes.reserve(order.size());
    for (const PlaneSegment &s : order) {
        // inverse of the sweep rotation
        out.passes.push_back({{s.u0 * dx + s.v0 * dy, s.u0 * dy - s.v0 * dx},
                              {s.u1 * dx + s.v1 * dy, s.u1 * dy - s.v1 * dx},
                              std::abs(s.u1 - s.u0)});
    }
    return out;
}

} // namespace sortie::mission
