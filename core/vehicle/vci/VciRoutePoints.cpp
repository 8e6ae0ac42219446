#include "VciRoutePoints.h"

#include "AlgorithmCatalog.h"
#include "AlgorithmSegment.h"
#include "AreaScan.h"
#include "Route.h"
#include "ScanPlanCache.h"
#include "SegmentPlanning.h"
#include "SegmentPlanner.h"
#include "VciMissionActions.h"

namespace sortie::vehicle {

using namespace sortie::mission;

namespace {

MissionError missionError(const QString &message)
{
    MissionError e;
    e.message = message;
    return e;
}

// A waypoint as it is.
Result<std::vector<VciRoutePoint>> waypointPoints(const Waypoint &w)
{
    VciRoutePoint p{w.position, w.altitude, w.altitudeType, w.speed, w.acceptanceRadius, {}, w.role};
    for (const WaypointAction &a : w.actions) {
        auto action = vciAction(a);
        if (!action)
            return action.error();
        p.actions.push_back(*action);
    }
    if (w.role == WaypointRole::Land)
        p.actions.push_back({QStringLiteral("land"), {}});
    return std::vector<VciRoutePoint>{std::move(p)};
}

// Sortie's own area scan: its passes, the camera on from the first point to the last.
Result<std::vector<VciRoutePoint>> scanPoints(const AreaScan &scan, ScanPlanCache *cache)
{
    AreaScanOutcome scratch;
    const AreaScanOutcome &outcome = scanOutcome(scan, cache, scratch);
    if (!outcome.ok() || outcome.plan->path.empty())
        return missionError(outcome.message.isEmpty() ? QStringLiteral("cannot be planned") : outcome.message);
    const AreaScanPlan &plan = *outcome.plan;
    std::vector<VciRoutePoint> points;
    points.reserve(plan.path.size());
    for (const GeoPoint &p : plan.path)
        points.push_back({p, plan.altitude, scan.parameters.altitudeType, scan.parameters.speed, 0, {}});
    points.front().actions.push_back(seriesByDistance(plan.triggerDistance));
    points.back().actions.push_back(seriesByDistance(0.0));
    return points;
}

// Any other UgCS tool, planned as sortie-sim's ProcessRoute plans it: camera commands and the
// segment's own actions where the plan runs them, a landing's "land".
Result<std::vector<VciRoutePoint>> algorithmPoints(const AlgorithmSegment &segment, const Route &route, std::optional<GeoPoint> from)
{
    std::vector<MissionAction> own;
    for (const WaypointAction &a : segment.actions) {
        auto action = vciAction(a);
        if (!action)
            return action.error();
        own.push_back(*action);
    }
    if (!AlgorithmCatalog::builtIn().byClassName(segment.algorithm))
        return missionError(QStringLiteral("only a UgCS server that knows %1 can plan it, and a VCI vehicle flies planned points only")
                                .arg(segment.algorithm));
    PlanContext context = planContextOf(route.settings);
    context.previousPosition = from;
    const SegmentPlanOutcome outcome = planAlgorithmSegment(segment, AlgorithmCatalog::builtIn(), context);
    if (!outcome.ok() || outcome.plan->points.empty()) {
        const QStringList errors(outcome.errors.begin(), outcome.errors.end());
        return missionError(errors.isEmpty() ? QStringLiteral("cannot be planned") : errors.join(QStringLiteral("; ")));
    }
    std::vector<VciRoutePoint> points;
    points.reserve(outcome.plan->points.size());
    for (const PlannedPoint &p : outcome.plan->points) {
        VciRoutePoint point{p.position, p.height, p.frame == HeightFrame::Amsl ? AltitudeType::Amsl : AltitudeType::Agl,
                         p.speed > 0 ? p.speed : route.settings.initialSpeed, 0, cameraActions(p)};
        if (p.userActions)
            point.actions.insert(point.actions.end(), own.begin(), own.end());
        if (p.kind == PlannedPoint::Kind::Landing) {
            point.actions.push_back({QStringLiteral("land"), {}});
            point.role = WaypointRole::Land;
        }
        if (p.kind == PlannedPoint::Kind::Takeoff)
            point.role = WaypointRole::Takeoff;
        points.push_back(std::move(point));
    }
    return points;
}

} // namespace

Result<std::vector<VciRoutePoint>> vciRoutePoints(const Route &route, size_t row, std::optional<GeoPoint> from, ScanPlanCache *cache)
{
    const Segment &segment = route.segments[row];
    if (const Waypoint *w = asWaypoint(segment))
        return waypointPoints(*w);
    if (const AreaScan *scan = std::get_if<AreaScan>(&segment))
        return scanPoints(*scan, cache);
    if (const AlgorithmSegment *a = asAlgorithmSegment(segment))
        return algorithmPoints(*a, route, from);
    return missionError(QStringLiteral("cannot be planned"));
}

} // namespace sortie::vehicle
