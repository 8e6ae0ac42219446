#include "VciMissionPlanner.h"

#include "Route.h"
#include "TerrainFollow.h"
#include "VciMissionBuilder.h"
#include "VciRoutePoints.h"

namespace sortie::vehicle {

using namespace sortie::mission;

Result<VciMission> vciMissionFor(const Route &route, const VciHeights &heights, ScanPlanCache *cache)
{
    VciMissionBuilder builder(route, heights);
    for (size_t row = 0; row < route.segments.size(); ++row) {
        const Result<std::vector<VciRoutePoint>> points = vciRoutePoints(route, row, builder.lastPosition(), cache);
        if (!points)
            return builder.at(int(row), points.error().message);
        if (auto error = builder.add(int(row), *points, terrain::terrainFollowTolerance(route.segments[row])))
            return *error;
    }
    VciMission mission = builder.finish();
    if (mission.items.empty()) {
        MissionError e;
        e.message = QStringLiteral("the route has no waypoints to fly");
        return e;
    }
    return mission;
}

} // namespace sortie::vehicle
