#include "SegmentWaypoints.h"

#include "AlgorithmCatalog.h"
#include "ScanPlanCache.h"
#include "SegmentPlanner.h"
#include "SegmentPlanning.h"

#include <QCoreApplication>
#include <QStringList>

namespace sortie::mission {

namespace {

MissionError failure(const QString &message)
{
    MissionError e;
    e.message = message;
    return e;
}

Waypoint pointAt(const GeoPoint &position, double altitude, AltitudeType type, double speed)
{
    Waypoint w;
    w.position = position;
    w.altitude = altitude;
    w.altitudeType = type;
    w.speed = speed;
    return w;
}

CameraSeriesByDistanceAction seriesEvery(double metres)
{
    CameraSeriesByDistanceAction a;
    a.intervalMeters = metres;
    a.shots = 0;
    a.startDelaySeconds = 0;
    return a;
}

Result<std::vector<Waypoint>> scanWaypoints(const AreaScan &scan, ScanPlanCache *cache)
{
    AreaScanOutcome scratch;
    const AreaScanOutcome &outcome = scanOutcome(scan, cache, scratch);
    if (!outcome.ok() || outcome.plan->path.empty())
        return failure(outcome.message.isEmpty() ? QCoreApplication::translate("SegmentWaypoints", "cannot be planned") : outcome.message);
    const AreaScanPlan &plan = *outcome.plan;
    std::vector<Waypoint> points;
    points.reserve(plan.path.size());
    for (const GeoPoint &p : plan.path)
        points.push_back(pointAt(p, plan.altitude, scan.parameters.altitudeType, scan.parameters.speed));
    points.front().actions.push_back(seriesEvery(plan.triggerDistance));
    points.back().actions.push_back(seriesEvery(0.0));
    return points;
}

Result<std::vector<Waypoint>> algorithmWaypoints(const AlgorithmSegment &segment, const Route &route, std::optional<GeoPoint> from)
{
    if (!AlgorithmCatalog::builtIn().byClassName(segment.algorithm))
        return failure(QCoreApplication::translate("SegmentWaypoints", "only a UgCS server that knows %1 can plan it").arg(segment.algorithm));
    PlanContext context = planContextOf(route.settings);
    context.previousPosition = from;
    const SegmentPlanOutcome outcome = planAlgorithmSegment(segment, AlgorithmCatalog::builtIn(), context);
    if (!outcome.ok() || outcome.plan->points.empty()) {
        const QStringList errors(outcome.errors.begin(), outcome.errors.end());
        return failure(errors.isEmpty() ? QCoreApplication::translate("SegmentWaypoints", "cannot be planned") : errors.join(QStringLiteral("; ")));
    }
    std::vector<Waypoint> points;
    points.reserve(outcome.plan->points.size());
    for (const PlannedPoint &p : outcome.plan->points) {
        Waypoint w = pointAt(p.position, p.height, p.frame == HeightFrame::Amsl ? AltitudeType::Amsl : AltitudeType::Agl,
                             p.speed > 0 ? p.speed : route.settings.initialSpeed);
        w.actions = cameraCommandActions(p.camera);
        if (p.userActions)
            w.actions.insert(w.actions.end(), segment.actions.begin(), segment.actions.end());
        if (p.kind == PlannedPoint::Kind::Landing)
            w.role = WaypointRole::Land;
        else if (p.kind == PlannedPoint::Kind::Takeoff)
            w.role = WaypointRole::Takeoff;
        points.push_back(std::move(w));
    }
    return points;
}

} // namespace

std::vector<WaypointAction> cameraCommandActions(const std::vector<CameraCommand> &commands)
{
    std::vector<WaypointAction> out;
    for (const CameraCommand &c : commands) {
        switch (c.kind) {
        case CameraCommand::Kind::FaceDown: {
            CameraControlAction down;
            down.tiltDeg = 90.0;  // UgCS: tilt 90° faces down
            down.rollDeg = 0.0;
            down.yawDeg = 0.0;
            out.emplace_back(down);
            break;
        }
        case CameraCommand::Kind::FaceHeading: {
            HeadingAction heading;
            heading.headingDeg = c.value;
            out.emplace_back(heading);
            CameraControlAction level;
            level.tiltDeg = 0.0;
            out.emplace_back(level);
            break;
        }
        case CameraCommand::Kind::StartSeries:
        case CameraCommand::Kind::StopSeries:
            out.emplace_back(seriesEvery(c.value));
            break;
        }
    }
    return out;
}

Result<std::vector<Waypoint>> segmentWaypoints(const Route &route, size_t row, std::optional<GeoPoint> from, ScanPlanCache *cache)
{
    if (row >= route.segments.size())
        return failure(QCoreApplication::translate("SegmentWaypoints", "no such segment"));
    const Segment &segment = route.segments[row];
    if (const Waypoint *w = asWaypoint(segment))
        return std::vector<Waypoint>{*w};
    if (const AreaScan *scan = asAreaScan(segment))
        return scanWaypoints(*scan, cache);
    if (const AlgorithmSegment *a = asAlgorithmSegment(segment))
        return algorithmWaypoints(*a, route, from);
    return failure(QCoreApplication::translate("SegmentWaypoints", "cannot be planned"));
}

} // namespace sortie::mission
