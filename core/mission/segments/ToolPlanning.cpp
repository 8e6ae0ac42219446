// The shared building blocks of the tool planners: common parameters, points, passes, the camera.
#include "ToolPlanning.h"

#include <algorithm>
#include <cmath>

namespace sortie::mission::toolplanning {

SegmentPlanOutcome fail(QString message, int point)
{
    SegmentPlanOutcome o;
    o.errors.push_back(std::move(message));
    o.wrongPoint = point;
    return o;
}

QString m1(double v) { return QString::number(v, 'f', 1); }

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

} // namespace sortie::mission::toolplanning
