#include "SegmentPlanner.h"

#include "CoverageSweep.h"
#include "Geodesy.h"
#include "LocalTangentPlane.h"
#include "Photogrammetry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

namespace sortie::mission {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kMaxPlannedPoints = 200000;  // beyond this a segment is a mistake, not a plan

SegmentPlanOutcome fail(QString message, int point = -1)
{
    SegmentPlanOutcome o;
    o.errors.push_back(std::move(message));
    o.wrongPoint = point;
    return o;
}

QString m1(double v) { return QString::number(v, 'f', 1); }

HeightFrame frameOf(const QString &altitudeType)
{
    return altitudeType.compare(QLatin1String("AGL"), Qt::CaseInsensitive) == 0 ? HeightFrame::Agl : HeightFrame::Amsl;
}

std::vector<GeoPoint> openRing(std::vector<GeoPoint> points)
{
    if (points.size() > 1 && points.front() == points.back())
        points.pop_back();
    return points;
}

// The first figure point that is not a position, or -1.
int firstInvalidPoint(const SegmentFigure &f)
{
    for (size_t i = 0; i < f.points.size(); ++i)
        if (!f.points[i].isValid())
            return int(i);
    return -1;
}

double pointAltitude(const SegmentFigure &f, size_t i)
{
    return i < f.pointAltitudes.size() ? f.pointAltitudes[i] : 0.0;
}

// The segment's own parameters, read once.
struct Common
{
    double speed = 5.0;
    std::optional<double> overshoot, overshootSpeed;
    double direction = 0.0;
};

Common commonOf(const ParameterReader &r, const PlanContext &ctx)
{
    Common c;
    c.speed = r.number(QStringLiteral("speed")).value_or(ctx.defaultSpeed);
    c.overshoot = r.number(QStringLiteral("overshoot"));
    c.overshootSpeed = r.number(QStringLiteral("overshootSpeed"));
    c.direction = r.number(QStringLiteral("directionAngle"), 0.0);
    return c;
}

PlannedPoint point(const GeoPoint &p, double height, HeightFrame frame, double speed)
{
    PlannedPoint out;
    out.position = p;
    out.height = height;
    out.frame = frame;
    out.speed = speed;
    return out;
}

// Passes over a plane: what area scan, photogrammetry, creeping line and corridor share.
struct PassSpec
{
    double height = 0.0;
    HeightFrame frame = HeightFrame::Agl;
    double speed = 0.0;
    double overshoot = 0.0;
    double overshootSpeed = 0.0;
    double trigger = 0.0;        // metres between photos, 0 = no camera series
    bool extraPoints = false;    // a waypoint at every photo position
};

// Appends one pass (a polyline in the plane, flown from its first to its last point).
void appendPass(const LocalTangentPlane &plane, const std::vector<PlanePoint> &line, const PassSpec &spec, SegmentPlan &plan)
{
    if (line.size() < 2)
        return;
    double length = 0;
    for (size_t i = 1; i < line.size(); ++i)
        length += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    auto along = [](const PlanePoint &from, const PlanePoint &to, double d) {
        const double l = std::hypot(to.x - from.x, to.y - from.y);
        return l > 0 ? PlanePoint{to.x + (to.x - from.x) / l * d, to.y + (to.y - from.y) / l * d} : to;
    };
    const bool lead = spec.overshoot > 0;
    if (lead) {
        PlannedPoint o = point(plane.unproject(along(line[1], line[0], spec.overshoot)), spec.height, spec.frame, spec.overshootSpeed);
        o.overshoot = true;
        plan.points.push_back(o);
    }
    double carried = 0;  // distance since the last photo position, for the extra waypoints
    for (size_t i = 0; i < line.size(); ++i) {
        if (i > 0 && spec.extraPoints && spec.trigger > 0) {
            const double dx = line[i].x - line[i - 1].x, dy = line[i].y - line[i - 1].y;
            const double l = std::hypot(dx, dy);
            double d = spec.trigger - carried;
            for (; d < l - 1e-6; d += spec.trigger) {
                PlannedPoint p = point(plane.unproject({line[i - 1].x + dx / l * d, line[i - 1].y + dy / l * d}),
                                       spec.height, spec.frame, spec.speed);
                p.onPass = true;
                plan.points.push_back(p);
            }
            carried = l - (d - spec.trigger);
        }
        PlannedPoint p = point(plane.unproject(line[i]), spec.height, spec.frame,
                               i == 0 && lead ? spec.overshootSpeed : spec.speed);
        p.onPass = true;
        if (spec.trigger > 0 && i == 0)
            p.camera.push_back({CameraCommand::Kind::StartSeries, spec.trigger});
        if (spec.trigger > 0 && i + 1 == line.size())
            p.camera.push_back({CameraCommand::Kind::StopSeries, 0.0});
        plan.points.push_back(p);
    }
    if (lead) {
        PlannedPoint o = point(plane.unproject(along(line[line.size() - 2], line.back(), spec.overshoot)), spec.height,
                               spec.frame, spec.overshootSpeed);
        o.overshoot = true;
        plan.points.push_back(o);
    }
    ++plan.passes;
    if (spec.trigger > 0)
        plan.photos += photogrammetry::photosOnPass(length, spec.trigger);
}

// Parallel passes over a polygon; a double grid flies a second sweep across the first.
std::optional<QString> sweepArea(const PlanarPolygon &shape, double spacing, double direction, bool doubleGrid,
                                 const PassSpec &spec, const PlanContext &ctx, SegmentPlan &plan)
{
    std::optional<PlanePoint> start;
    if (ctx.previousPosition && ctx.previousPosition->isValid())
        start = shape.plane.project(*ctx.previousPosition);
    for (int grid = 0; grid < (doubleGrid ? 2 : 1); ++grid) {
        const SweepOutcome sweep = sweepPolygon(shape.points, spacing, direction + grid * 90.0, start);
        if (!sweep.ok())
            return sweep.message;
        if (sweep.passes.size() * 4 > size_t(kMaxPlannedPoints))
            return QStringLiteral("The scan would need %1 passes; widen the spacing.").arg(sweep.passes.size());
        for (const SweepPass &p : sweep.passes)
            appendPass(shape.plane, {p.start, p.end}, spec, plan);
        start = sweep.passes.back().end;
    }
    return std::nullopt;
}

// The polyline shifted `offset` metres to its right (negative: left), mitred at the joins; a join
// sharper than ~150° is bevelled so the offset line does not shoot far out.
std::vector<PlanePoint> offsetPolyline(const std::vector<PlanePoint> &line, double offset)
{
    const size_t n = line.size();
    std::vector<PlanePoint> out;
    auto normal = [&](size_t i) {  // right-hand normal of edge i -> i+1
        const double dx = line[i + 1].x - line[i].x, dy = line[i + 1].y - line[i].y;
        const double l = std::hypot(dx, dy);
        return PlanePoint{dy / l, -dx / l};
    };
    for (size_t i = 0; i < n; ++i) {
        if (i == 0 || i + 1 == n) {
            const PlanePoint nn = normal(i == 0 ? 0 : n - 2);
            out.push_back({line[i].x + nn.x * offset, line[i].y + nn.y * offset});
            continue;
        }
        const PlanePoint a = normal(i - 1), b = normal(i);
        PlanePoint m{a.x + b.x, a.y + b.y};
        const double ml = std::hypot(m.x, m.y);
        const double cosHalf = ml / 2;  // cos of half the turn
        if (cosHalf < 0.26) {
            out.push_back({line[i].x + a.x * offset, line[i].y + a.y * offset});
            out.push_back({line[i].x + b.x * offset, line[i].y + b.y * offset});
            continue;
        }
        m = {m.x / ml, m.y / ml};
        out.push_back({line[i].x + m.x * offset / cosHalf, line[i].y + m.y * offset / cosHalf});
    }
    return out;
}

struct CameraSetup
{
    Camera camera;
    photogrammetry::Figures figures;
};

// The camera and figures of a photo tool from its GSD and overlaps.
std::variant<CameraSetup, QString> photoSetup(const ParameterReader &r, const PlanContext &ctx, double speed)
{
    const QString name = r.selection(QStringLiteral("camera"));
    const std::optional<Camera> camera = resolveCamera(name, ctx.cameras);
    if (!camera)
        return name.isEmpty() ? QStringLiteral("camera: the vehicle profile has no camera payload with a focal length, sensor size and resolution")
                              : QStringLiteral("camera: '%1' is not a camera of the vehicle profile").arg(name);
    const auto gsd = r.number(QStringLiteral("groundSampleDistance"));
    if (!gsd || *gsd <= 0)
        return QStringLiteral("groundSampleDistance must be set to a positive number of cm/px");
    CameraSetup s;
    s.camera = *camera;
    s.figures = photogrammetry::figuresForGsd(*camera, *gsd, r.number(QStringLiteral("overlapForward"), 60.0),
                                              r.number(QStringLiteral("overlapSide"), 30.0),
                                              r.boolean(QStringLiteral("camTopFacingForward"), true), speed);
    if (!(s.figures.passSpacing > 0) || !(s.figures.triggerDistance > 0))
        return QStringLiteral("The overlaps leave no distance between photos");
    return s;
}

void noteCamera(const CameraSetup &s, double speed, SegmentPlan &plan)
{
    plan.camera = s.camera;
    plan.height = s.figures.height;
    plan.gsdCm = s.figures.gsdCm;
    plan.passSpacing = s.figures.passSpacing;
    plan.triggerDistance = s.figures.triggerDistance;
    if (s.figures.maxSpeed > 0 && speed > s.figures.maxSpeed + 1e-9)
        plan.warnings.push_back(QStringLiteral("The camera takes a photo at most every %1 s: at %2 m/s it cannot keep one every %3 m; fly at %4 m/s or less")
                                    .arg(s.camera.minTriggerIntervalS).arg(m1(speed), m1(s.figures.triggerDistance), m1(s.figures.maxSpeed)));
}

// ---- one function per tool ----

SegmentPlanOutcome planPointTool(AlgorithmKind kind, const SegmentFigure &f, const Common &c)
{
    if (f.points.empty())
        return fail(QStringLiteral("The segment has no point"), 0);
    if (!f.points[0].isValid())
        return fail(QStringLiteral("Point 1 is not a position on the globe"), 0);
    SegmentPlan plan;
    PlannedPoint p = point(f.points[0], pointAltitude(f, 0), f.pointFrame, c.speed);
    if (kind == AlgorithmKind::TakeOff)
        p.kind = PlannedPoint::Kind::Takeoff;
    if (kind == AlgorithmKind::Landing) {
        p.kind = PlannedPoint::Kind::Landing;
        p.height = 0.0;
        p.frame = HeightFrame::Agl;
    }
    plan.points.push_back(p);
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planCircle(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    if (f.points.empty())
        return fail(QStringLiteral("The circle has no centre point"), 0);
    const GeoPoint centre = f.points[0];
    if (!centre.isValid())
        return fail(QStringLiteral("The circle's centre is not a position on the globe"), 0);
    const double radius = f.parameters.empty() ? 0.0 : f.parameters[0];
    if (!(radius > 0) || !std::isfinite(radius))
        return fail(QStringLiteral("The circle needs a positive radius (metres, the figure's first parameter)"));
    if (radius > kMaxScanRadiusMeters)
        return fail(QStringLiteral("The circle's radius of %1 m is over the %2 m a segment may span").arg(m1(radius), m1(kMaxScanRadiusMeters)));
    const int loops = int(r.number(QStringLiteral("loops"), 1.0));
    const bool clockwise = r.boolean(QStringLiteral("flightClockwise"), true);
    const auto given = r.number(QStringLiteral("basePointsQnt"));
    const int perLap = given ? int(*given) : circlePointsPerLap(radius);
    if (size_t(perLap) * size_t(loops) > size_t(kMaxPlannedPoints))
        return fail(QStringLiteral("loops: %1 laps of %2 points are too many").arg(loops).arg(perLap));

    double start = 0.0;  // bearing of the first point from the centre: towards where the vehicle comes from
    if (ctx.previousPosition && ctx.previousPosition->isValid() && !(*ctx.previousPosition == centre))
        if (const auto inv = geodesicInverse(centre, *ctx.previousPosition))
            start = inv->azimuth1Deg;
    SegmentPlan plan;
    const double step = (clockwise ? 360.0 : -360.0) / perLap;
    const double height = pointAltitude(f, 0);
    for (int k = 0; k <= perLap * loops; ++k)
        plan.points.push_back(point(geodesicDirect(centre, start + step * (k % perLap), radius).point, height, f.pointFrame, c.speed));
    plan.passes = loops;
    plan.notes.push_back(QStringLiteral("Orbit of %1 m radius: %2 lap(s) of %3 points, %4")
                             .arg(m1(radius)).arg(loops).arg(perLap).arg(clockwise ? QStringLiteral("clockwise") : QStringLiteral("counter-clockwise")));
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome polygonFailure(const PlanarPolygonOutcome &o)
{
    return fail(o.message, o.vertex);
}

SegmentPlanOutcome planPerimeter(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    const PlanarPolygonOutcome shape = planarPolygon(f.points);
    if (!shape.polygon)
        return polygonFailure(shape);
    const std::vector<GeoPoint> ring = openRing(f.points);
    const double height = r.number(QStringLiteral("height"), 0.0);
    const HeightFrame frame = r.boolean(QStringLiteral("heightAgl"), true) ? HeightFrame::Agl : HeightFrame::Amsl;
    const int loops = int(r.number(QStringLiteral("loops"), 1.0));
    size_t first = 0;  // start at the vertex nearest to where the vehicle comes from
    if (ctx.previousPosition && ctx.previousPosition->isValid()) {
        double best = 1e300;
        for (size_t i = 0; i < ring.size(); ++i)
            if (const double d = geodesicDistance(ring[i], *ctx.previousPosition); d < best) {
                best = d;
                first = i;
            }
    }
    SegmentPlan plan;
    plan.height = height;
    for (int lap = 0; lap < loops; ++lap)
        for (size_t i = 0; i < ring.size(); ++i)
            plan.points.push_back(point(ring[(first + i) % ring.size()], height, frame, c.speed));
    plan.points.push_back(point(ring[first], height, frame, c.speed));
    plan.passes = loops;
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planAreaTool(AlgorithmKind kind, const SegmentFigure &f, const ParameterReader &r, const Common &c,
                                const PlanContext &ctx)
{
    const PlanarPolygonOutcome shape = planarPolygon(f.points);
    if (!shape.polygon)
        return polygonFailure(shape);
    SegmentPlan plan;
    PassSpec spec;
    spec.speed = c.speed;
    spec.overshoot = c.overshoot.value_or(0.0);
    spec.overshootSpeed = c.overshootSpeed.value_or(c.speed);
    double spacing = 0;
    if (kind == AlgorithmKind::AreaScan) {
        spec.height = r.number(QStringLiteral("height"), 0.0);
        spec.frame = frameOf(r.selection(QStringLiteral("altitudeType")));
        spacing = r.number(QStringLiteral("sideDistance"), 0.0);
        if (!(spacing > 0))
            return fail(QStringLiteral("sideDistance must be a positive number of metres"));
    } else if (kind == AlgorithmKind::Photogrammetry) {
        const auto setup = photoSetup(r, ctx, c.speed);
        if (const QString *error = std::get_if<QString>(&setup))
            return fail(*error);
        const CameraSetup &s = std::get<CameraSetup>(setup);
        noteCamera(s, c.speed, plan);
        spec.height = s.figures.height;
        spec.frame = HeightFrame::Agl;  // above the ground photographed; see SegmentPlan::altitudeType
        spec.trigger = s.figures.triggerDistance;
        spec.extraPoints = r.boolean(QStringLiteral("generateAdditionalWaypoints"), false);
        spacing = s.figures.passSpacing;
    } else {  // creeping line: spacing = height × sensor width / focal × (1 − side overlap)
        const std::optional<Camera> camera = resolveCamera(r.selection(QStringLiteral("camera")), ctx.cameras);
        if (!camera)
            return fail(QStringLiteral("camera: the creeping line needs a camera to space its passes"));
        spec.height = r.number(QStringLiteral("height"), 0.0);
        spec.frame = HeightFrame::Agl;
        spacing = photogrammetry::passSpacing(photogrammetry::footprint(*camera, spec.height).across,
                                              r.number(QStringLiteral("overlapSide"), 10.0));
        plan.camera = camera;
        if (!(spacing > 0))
            return fail(QStringLiteral("height: the passes need a positive height to be spaced"));
    }
    plan.height = spec.height;
    plan.passSpacing = spacing;
    if (auto error = sweepArea(*shape.polygon, spacing, c.direction, r.boolean(QStringLiteral("doubleGrid"), false), spec, ctx, plan))
        return fail(*error);
    if (plan.points.size() > size_t(kMaxPlannedPoints))
        return fail(QStringLiteral("The segment would need %1 waypoints; widen the spacing or the trigger distance").arg(plan.points.size()));
    if (plan.points.front().camera.empty() || plan.points.front().camera.front().kind != CameraCommand::Kind::FaceDown)
        if (spec.trigger > 0)
            plan.points.front().camera.insert(plan.points.front().camera.begin(), {CameraCommand::Kind::FaceDown, 0.0});
    QString figures = QStringLiteral("%1 passes %2 m apart at %3 m over %4 m²")
                          .arg(plan.passes).arg(m1(spacing), m1(spec.height)).arg(qint64(std::llround(shape.polygon->area)));
    if (spec.trigger > 0)
        figures += QStringLiteral(", GSD %1 cm/px, %2 photos every %3 m").arg(QString::number(plan.gsdCm, 'f', 2)).arg(plan.photos).arg(m1(spec.trigger));
    plan.notes.push_back(figures);
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planCorridor(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    std::vector<GeoPoint> line;
    for (size_t i = 0; i < f.points.size(); ++i) {
        if (!f.points[i].isValid())
            return fail(QStringLiteral("Point %1 of the centre line is not a position on the globe").arg(i + 1), int(i));
        if (line.empty() || !(line.back() == f.points[i]))
            line.push_back(f.points[i]);
    }
    if (line.size() < 2)
        return fail(QStringLiteral("The corridor needs a centre line of at least 2 distinct points"), 0);
    const LocalTangentPlane plane(LocalTangentPlane::centroidOf(line));
    std::vector<PlanePoint> centre;
    for (size_t i = 0; i < line.size(); ++i) {
        const PlanePoint p = plane.project(line[i]);
        if (std::hypot(p.x, p.y) > kMaxScanRadiusMeters)
            return fail(QStringLiteral("The corridor spans more than 100 km; split it"), int(i));
        centre.push_back(p);
    }
    SegmentPlan plan;
    const auto setup = photoSetup(r, ctx, c.speed);
    if (const QString *error = std::get_if<QString>(&setup))
        return fail(*error);
    const CameraSetup &s = std::get<CameraSetup>(setup);
    noteCamera(s, c.speed, plan);
    const double width = r.number(QStringLiteral("width"), 30.0);
    const int passes = std::max(1, int(std::ceil(width / s.figures.passSpacing - 1e-9)));
    if (passes > 1000)
        return fail(QStringLiteral("width: %1 m needs %2 passes; raise the GSD or lower the side overlap").arg(m1(width)).arg(passes));
    PassSpec spec;
    spec.height = s.figures.height;
    spec.frame = HeightFrame::Agl;  // above the ground photographed; see SegmentPlan::altitudeType
    spec.speed = c.speed;
    spec.overshoot = c.overshoot.value_or(0.0);
    spec.overshootSpeed = c.overshootSpeed.value_or(c.speed);
    spec.trigger = s.figures.triggerDistance;
    for (int k = 0; k < passes; ++k) {
        const double offset = (k - (passes - 1) / 2.0) * s.figures.passSpacing;
        std::vector<PlanePoint> pass = offsetPolyline(centre, offset);
        if (k % 2 == 1)
            std::reverse(pass.begin(), pass.end());
        appendPass(plane, pass, spec, plan);
    }
    plan.points.front().camera.insert(plan.points.front().camera.begin(), {CameraCommand::Kind::FaceDown, 0.0});
    plan.height = spec.height;
    plan.passSpacing = s.figures.passSpacing;
    plan.notes.push_back(QStringLiteral("%1 passes %2 m apart across %3 m at %4 m, GSD %5 cm/px, %6 photos every %7 m")
                             .arg(passes).arg(m1(s.figures.passSpacing), m1(width), m1(spec.height), QString::number(plan.gsdCm, 'f', 2))
                             .arg(plan.photos).arg(m1(spec.trigger)));
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planExpandingSquare(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    if (f.points.empty() || !f.points[0].isValid())
        return fail(QStringLiteral("The expanding square needs a valid centre point"), 0);
    const std::optional<Camera> camera = resolveCamera(r.selection(QStringLiteral("camera")), ctx.cameras);
    if (!camera)
        return fail(QStringLiteral("camera: the expanding square needs a camera to space its legs"));
    const double height = r.number(QStringLiteral("height"), 0.0);
    const double spacing = photogrammetry::passSpacing(photogrammetry::footprint(*camera, height).across,
                                                       r.number(QStringLiteral("overlapSide"), 10.0));
    const double radius = r.number(QStringLiteral("searchRadius"), 350.0);
    if (!(spacing > 0))
        return fail(QStringLiteral("height: the legs need a positive height to be spaced"));
    if (radius / spacing > 2000)
        return fail(QStringLiteral("searchRadius: %1 m needs too many legs at %2 m spacing").arg(m1(radius), m1(spacing)));
    const LocalTangentPlane plane(f.points[0]);
    SegmentPlan plan;
    plan.camera = camera;
    plan.height = height;
    plan.passSpacing = spacing;
    PlanePoint at{0, 0};
    plan.points.push_back(point(f.points[0], height, HeightFrame::Agl, c.speed));
    // Legs of 1, 1, 2, 2, 3, 3 … spacings, turning right, until the square reaches the search radius.
    for (int leg = 0;; ++leg) {
        const double length = spacing * (leg / 2 + 1);
        if (length > 2 * radius + 1e-9)
            break;
        const double bearing = (c.direction + 90.0 * leg) * kDeg;
        at = {at.x + std::sin(bearing) * length, at.y + std::cos(bearing) * length};
        plan.points.push_back(point(plane.unproject(at), height, HeightFrame::Agl, c.speed));
        ++plan.passes;
    }
    plan.notes.push_back(QStringLiteral("Expanding square: %1 legs %2 m apart to %3 m").arg(plan.passes).arg(m1(spacing), m1(radius)));
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planFacade(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    if (f.points.size() < 2 || !f.points[0].isValid() || !f.points[1].isValid())
        return fail(QStringLiteral("The facade needs its two corners A and B"), f.points.empty() ? 0 : 1);
    const LocalTangentPlane plane(LocalTangentPlane::centroidOf({f.points[0], f.points[1]}));
    const PlanePoint a = plane.project(f.points[0]), b = plane.project(f.points[1]);
    const double wall = std::hypot(b.x - a.x, b.y - a.y);
    if (wall < 1.0)
        return fail(QStringLiteral("Corners A and B of the facade are less than a metre apart"), 1);
    const double minH = r.number(QStringLiteral("minHeight"), 0.0), maxH = r.number(QStringLiteral("maxHeight"), 0.0);
    if (maxH < minH)
        return fail(QStringLiteral("maxHeight: %1 m is below minHeight %2 m").arg(m1(maxH), m1(minH)));
    const std::optional<Camera> camera = resolveCamera(r.selection(QStringLiteral("camera")), ctx.cameras);
    if (!camera)
        return fail(QStringLiteral("camera: the facade scan needs a camera"));
    const double distance = r.number(QStringLiteral("distanceToFacade"), 20.0);
    // The camera faces the wall, its top up: the footprint's width runs along the wall.
    const double footW = distance * camera->sensorWidthMm / camera->focalLengthMm;
    const double footH = distance * camera->sensorHeightMm / camera->focalLengthMm;
    const double forward = r.number(QStringLiteral("overlapForward"), 60.0), side = r.number(QStringLiteral("overlapSide"), 60.0);
    const bool vertical = r.selection(QStringLiteral("facadeScanPattern")) != QLatin1String("HORIZONTAL");
    const double vSpeed = r.number(QStringLiteral("verticalSpeed"), c.speed), hSpeed = r.number(QStringLiteral("horizontalSpeed"), c.speed);

    // The vehicle flies on the right of A→B, facing left onto the wall.
    const double ux = (b.x - a.x) / wall, uy = (b.y - a.y) / wall;
    const PlanePoint off{uy * distance, -ux * distance};
    const double facing = std::fmod(std::atan2(-uy, ux) / kDeg + 360.0, 360.0);  // bearing of the left normal, onto the wall
    auto at = [&](double t) { return plane.unproject({a.x + ux * t + off.x, a.y + uy * t + off.y}); };

    SegmentPlan plan;
    plan.camera = camera;
    plan.height = maxH;
    const double acrossSpacing = (vertical ? footW : footH) * (1 - side / 100.0);
    const double trigger = (vertical ? footH : footW) * (1 - forward / 100.0);
    const double span = vertical ? wall : maxH - minH;
    const int lines = span > 0 ? std::max(2, int(std::ceil(span / acrossSpacing - 1e-9)) + 1) : 1;
    if (lines > 5000)
        return fail(QStringLiteral("The facade would need %1 passes; move further from it or lower the side overlap").arg(lines));
    plan.passSpacing = lines > 1 ? span / (lines - 1) : 0.0;
    plan.triggerDistance = trigger;
    for (int k = 0; k < lines; ++k) {
        const bool reversed = k % 2 == 1;
        const double s = lines > 1 ? span * k / (lines - 1) : 0.0;
        PlannedPoint p0, p1;
        if (vertical) {
            p0 = point(at(s), reversed ? maxH : minH, HeightFrame::Agl, hSpeed);
            p1 = point(at(s), reversed ? minH : maxH, HeightFrame::Agl, vSpeed);
        } else {
            p0 = point(at(reversed ? wall : 0.0), minH + s, HeightFrame::Agl, vSpeed);
            p1 = point(at(reversed ? 0.0 : wall), minH + s, HeightFrame::Agl, hSpeed);
        }
        p0.onPass = p1.onPass = true;
        p0.camera = {{CameraCommand::Kind::StartSeries, trigger}};
        p1.camera = {{CameraCommand::Kind::StopSeries, 0.0}};
        plan.photos += photogrammetry::photosOnPass(vertical ? maxH - minH : wall, trigger);
        plan.points.push_back(p0);
        plan.points.push_back(p1);
        ++plan.passes;
    }
    plan.points.front().camera.insert(plan.points.front().camera.begin(), {CameraCommand::Kind::FaceHeading, facing});
    plan.notes.push_back(QStringLiteral("Facade %1 m long, %2 to %3 m high: %4 %5 passes, %6 photos")
                             .arg(m1(wall), m1(minH), m1(maxH)).arg(lines)
                             .arg(vertical ? QStringLiteral("vertical") : QStringLiteral("horizontal")).arg(plan.photos));
    return {std::move(plan), {}, -1};
}

void markUserActions(SegmentPlan &plan, const QString &execution, bool noActionsAtLastPoint)
{
    const bool forwardOnly = execution == QLatin1String("ACTIONS_ON_FORWARD_PASSES");
    const bool startOnly = execution == QLatin1String("ONLY_AT_START");
    for (size_t i = 0; i < plan.points.size(); ++i) {
        PlannedPoint &p = plan.points[i];
        p.userActions = startOnly ? i == 0 : forwardOnly ? p.onPass : true;
    }
    if (noActionsAtLastPoint && plan.points.size() > 1)
        plan.points.back().userActions = false;
}

} // namespace

int circlePointsPerLap(double radius)
{
    if (!(radius > 1.0))
        return 8;
    // sagitta r·(1 − cos(π/n)) ≤ 1 m
    const double n = std::numbers::pi / std::acos(1.0 - 1.0 / radius);
    return std::clamp(int(std::ceil(n)), 8, 360);
}

SegmentPlanOutcome planSegment(const AlgorithmDefinition &algorithm, const SegmentFigure &figure,
                               const ParameterValues &values, const PlanContext &context)
{
    const ParameterReader reader(algorithm, values);
    if (std::vector<QString> problems = reader.problems(); !problems.empty()) {
        SegmentPlanOutcome o;
        o.errors = std::move(problems);
        return o;
    }
    if (const int bad = firstInvalidPoint(figure); bad >= 0)
        return fail(QStringLiteral("Point %1 is not a position on the globe (latitude and longitude in range)").arg(bad + 1), bad);
    const Common common = commonOf(reader, context);
    if (!(common.speed > 0))
        return fail(QStringLiteral("speed: the segment needs a positive speed"));

    SegmentPlanOutcome out;
    switch (algorithm.kind) {
    case AlgorithmKind::Waypoint:
    case AlgorithmKind::TakeOff:
    case AlgorithmKind::Landing: out = planPointTool(algorithm.kind, figure, common); break;
    case AlgorithmKind::Circle: out = planCircle(figure, reader, common, context); break;
    case AlgorithmKind::Perimeter: out = planPerimeter(figure, reader, common, context); break;
    case AlgorithmKind::AreaScan:
    case AlgorithmKind::Photogrammetry:
    case AlgorithmKind::CreepingLine: out = planAreaTool(algorithm.kind, figure, reader, common, context); break;
    case AlgorithmKind::Corridor: out = planCorridor(figure, reader, common, context); break;
    case AlgorithmKind::ExpandingSquare: out = planExpandingSquare(figure, reader, common, context); break;
    case AlgorithmKind::FacadeScanner: out = planFacade(figure, reader, common, context); break;
    case AlgorithmKind::Unknown:
        return fail(QStringLiteral("No planner knows the algorithm '%1'").arg(algorithm.className));
    }
    if (!out.plan)
        return out;
    SegmentPlan &plan = *out.plan;
    plan.altitudeType = reader.selection(QStringLiteral("altitudeType"));
    markUserActions(plan, reader.selection(QStringLiteral("actionExecution")),
                    reader.boolean(QStringLiteral("noActionsAtLastPoint"), false));
    for (size_t i = 1; i < plan.points.size(); ++i)
        plan.length += geodesicDistance(plan.points[i - 1].position, plan.points[i].position);
    return out;
}

} // namespace sortie::mission
