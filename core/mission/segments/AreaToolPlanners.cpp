// Planning the area and outline tools: passes over a polygon, along a corridor, a square spiral, a facade.
#include "AreaToolPlanners.h"

#include "Geodesy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::mission::toolplanning {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

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

SegmentPlanOutcome polygonFailure(const PlanarPolygonOutcome &o)
{
    return fail(o.message, o.vertex);
}

} // namespace

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

} // namespace sortie::mission::toolplanning
