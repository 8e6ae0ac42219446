#include "AreaScanPlanner.h"

#include "PolygonGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sortie::mission {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMinTransectLength = 0.01;  // metres: shorter crossings are grazes of a vertex

AreaScanOutcome refuse(ScanProblem problem, QString message)
{
    AreaScanOutcome o;
    o.problem = problem;
    o.message = std::move(message);
    return o;
}

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
std::vector<PlaneSegment> flyCell(const Cell &cell, bool fromLastLine, bool fromHighEnd, double spacing, double v0)
{
    std::vector<PlaneSegment> out;
    bool high = fromHighEnd;
    for (size_t n = 0; n < cell.size(); ++n) {
        const Pass &p = fromLastLine ? cell[cell.size() - 1 - n] : cell[n];
        const double v = v0 + p.line * spacing;
        out.push_back(high ? PlaneSegment{p.interval.u1, v, p.interval.u0, v} : PlaneSegment{p.interval.u0, v, p.interval.u1, v});
        high = !high;
    }
    return out;
}
}

AreaScanOutcome planAreaScan(const AreaScan &scan)
{
    const AreaScanParameters &params = scan.parameters;
    std::vector<GeoPoint> polygon = scan.polygon;
    if (polygon.size() > 1 && polygon.front() == polygon.back())
        polygon.pop_back();  // tolerate a closed ring
    if (polygon.size() < 3)
        return refuse(ScanProblem::TooFewVertices, QStringLiteral("An area scan needs a polygon of at least 3 vertices."));
    for (size_t i = 0; i < polygon.size(); ++i)
        if (!polygon[i].isValid())
            return refuse(ScanProblem::InvalidVertex, QStringLiteral("Polygon vertex %1 is not a valid position.").arg(i + 1));

    const Camera &cam = params.camera;
    if (!(cam.sensorWidthMm > 0 && cam.sensorHeightMm > 0 && cam.focalLengthMm > 0 && cam.imageWidthPx > 0 && cam.imageHeightPx > 0))
        return refuse(ScanProblem::InvalidCamera, QStringLiteral("The camera needs a positive sensor size, focal length and image size."));
    for (double o : {params.frontOverlapPercent, params.sideOverlapPercent})
        if (!(o >= 0 && o <= 95))
            return refuse(ScanProblem::InvalidOverlap, QStringLiteral("Overlaps must be between 0 and 95 %."));
    const double altitude = scanAltitude(params);
    if (!(altitude > 0) || !std::isfinite(altitude))
        return refuse(ScanProblem::InvalidAltitude, QStringLiteral("The scan altitude (or ground sample distance) must be positive."));
    if (!(params.turnaroundMeters >= 0) || !std::isfinite(params.turnaroundMeters))
        return refuse(ScanProblem::InvalidTurnaround, QStringLiteral("The turnaround distance must not be negative."));

    const LocalTangentPlane plane(LocalTangentPlane::centroidOf(polygon));
    std::vector<PlanePoint> pts;
    pts.reserve(polygon.size());
    for (const auto &g : polygon) {
        const PlanePoint p = plane.project(g);
        if (std::hypot(p.x, p.y) > kMaxScanRadiusMeters)
            return refuse(ScanProblem::TooLarge, QStringLiteral("The polygon spans more than 100 km; split it into smaller scans."));
        pts.push_back(p);
    }
    if (auto hit = polygon::firstSelfIntersection(pts))
        return refuse(ScanProblem::SelfIntersecting, QStringLiteral("The scan polygon crosses itself (edges %1 and %2).")
                      .arg(hit->first + 1).arg(hit->second + 1));
    const double area = std::abs(polygon::signedArea(pts));
    if (area < 1.0)
        return refuse(ScanProblem::NoArea, QStringLiteral("The scan polygon has no area."));

    AreaScanPlan plan;
    plan.altitude = altitude;
    plan.groundSampleDistanceCm = scanGroundSampleDistanceCm(params);
    plan.transectSpacing = params.sideDistanceMeters > 0 ? params.sideDistanceMeters
                                                         : footprintAcrossMeters(params) * (1 - params.sideOverlapPercent / 100.0);
    plan.triggerDistance = footprintAlongMeters(params) * (1 - params.frontOverlapPercent / 100.0);
    plan.areaSquareMeters = area;

    // Sweep coordinates: u along the transects (bearing directionDeg), v to their right.
    const double theta = params.directionDeg * kDeg;
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
    const double lineCount = std::max(1.0, std::ceil(height / plan.transectSpacing - 1e-9));
    if (lineCount > kMaxTransects)
        return refuse(ScanProblem::TooManyTransects, QStringLiteral("The scan would need %1 transects; raise the altitude or lower the side overlap.")
                      .arg(qint64(lineCount)));
    const int lines = int(lineCount);
    const double v0 = vmin + (height - (lines - 1) * plan.transectSpacing) / 2;  // centred

    std::vector<std::vector<Interval>> intervals(lines);
    for (int k = 0; k < lines; ++k) {
        const std::vector<double> xs = polygon::crossingsAt(sweep, v0 + k * plan.transectSpacing);
        for (size_t i = 0; i + 1 < xs.size(); i += 2)
            if (xs[i + 1] - xs[i] >= kMinTransectLength)
                intervals[k].push_back({xs[i], xs[i + 1]});
    }
    const std::vector<Cell> cells = decompose(intervals);
    if (cells.empty())
        return refuse(ScanProblem::NoTransects, QStringLiteral("The scan yields no transects: the polygon is too narrow."));
    plan.cells = int(cells.size());

    // Fly the cells, each time entering the unvisited cell whose entry is nearest.
    std::vector<PlaneSegment> order;
    std::vector<bool> done(cells.size(), false);
    bool havePosition = false;
    double cu = 0, cv = 0;
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
                    const double v = v0 + p.line * plan.transectSpacing;
                    const double d = havePosition ? std::hypot(u - cu, v - cv) : (last ? 1.0 : 0.0) + (high ? 0.5 : 0.0);
                    if (d < best) { best = d; bestCell = c; bestLast = last; bestHigh = high; }
                }
            }
        }
        done[bestCell] = true;
        for (const PlaneSegment &s : flyCell(cells[bestCell], bestLast, bestHigh, plan.transectSpacing, v0))
            order.push_back(s);
        cu = order.back().u1;
        cv = order.back().v1;
        havePosition = true;
    }

    auto toGeo = [&](double u, double v) {
        // inverse of the sweep rotation, then off the plane
        return plane.unproject({u * dx + v * dy, u * dy - v * dx});
    };
    const double turn = params.turnaroundMeters;
    for (const PlaneSegment &s : order) {
        Transect t;
        t.start = toGeo(s.u0, s.v0);
        t.end = toGeo(s.u1, s.v1);
        t.length = std::abs(s.u1 - s.u0);
        t.photos = plan.triggerDistance > 0 ? int(std::floor(t.length / plan.triggerDistance)) + 1 : 1;
        plan.photoCount += t.photos;
        const double dir = s.u1 >= s.u0 ? 1.0 : -1.0;
        if (turn > 0)
            plan.path.push_back(toGeo(s.u0 - dir * turn, s.v0));
        plan.path.push_back(t.start);
        plan.path.push_back(t.end);
        if (turn > 0)
            plan.path.push_back(toGeo(s.u1 + dir * turn, s.v1));
        plan.transects.push_back(t);
    }
    for (size_t i = 1; i < plan.path.size(); ++i)
        plan.pathLength += geodesicDistance(plan.path[i - 1], plan.path[i]);
    return AreaScanOutcome{std::move(plan), ScanProblem::None, {}};
}

} // namespace sortie::mission
