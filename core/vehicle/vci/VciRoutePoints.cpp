#include "VciRoutePoints.h"

#include "Route.h"
#include "SegmentWaypoints.h"
#include "VciMissionActions.h"

namespace sortie::vehicle {

using namespace sortie::mission;

Result<std::vector<VciRoutePoint>> vciRoutePoints(const Route &route, size_t row, std::optional<GeoPoint> from, ScanPlanCache *cache)
{
    auto waypoints = segmentWaypoints(route, row, from, cache);
    if (!waypoints)
        return waypoints.error();
    std::vector<VciRoutePoint> points;
    points.reserve(waypoints->size());
    for (const Waypoint &w : *waypoints) {
        VciRoutePoint p{w.position, w.altitude, w.altitudeType, w.speed, w.acceptanceRadius, {}, w.role};
        for (const WaypointAction &a : w.actions) {
            auto action = vciAction(a);
            if (!action)
                return action.error();
            p.actions.push_back(*action);
        }
        if (w.role == WaypointRole::Land)
            p.actions.push_back({QStringLiteral("land"), {}});
        points.push_back(std::move(p));
    }
    return points;
}

} // namespace sortie::vehicle
