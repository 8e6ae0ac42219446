#include "VciMissionPlanner.h"

#include "FlownLegs.h"
#include "Route.h"
#include "RouteValidator.h"
#include "TerrainFollow.h"
#include "VciMissionBuilder.h"
#include "VciRoutePoints.h"

#include <tuple>
#include <QCoreApplication>

namespace sortie::vehicle {

using namespace sortie::mission;

namespace {

// Joins the points by the one rule (mission::flownLegs): a take-off point is flown at the height
// its first leg leaves at (the vehicle climbs straight up to it there), a landing point at the height
// its leg arrives at (then "land" takes it straight down). An AGL height rides the ground under the
// point it is flown over, as every AGL height does.
void flyVertically(std::vector<std::vector<VciRoutePoint>> &rows)
{
    std::vector<VciRoutePoint *> points;
    for (auto &row : rows)
        for (VciRoutePoint &p : row)
            points.push_back(&p);
    std::vector<VerticalPoint> vertical;
    vertical.reserve(points.size());
    for (const VciRoutePoint *p : points)
        vertical.push_back({p->role, onGround(p->height, p->type)});
    std::vector<std::pair<double, AltitudeType>> heights(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        heights[i] = {points[i]->height, points[i]->type};
    for (const LegShape &leg : flownLegs(vertical)) {
        if (leg.climbAtStart && leg.departHeight != leg.from)
            std::tie(points[leg.from]->height, points[leg.from]->type) = heights[leg.departHeight];
        if (leg.descentAtEnd && leg.arriveHeight != leg.to)
            std::tie(points[leg.to]->height, points[leg.to]->type) = heights[leg.arriveHeight];
    }
}

} // namespace

Result<VciMission> vciMissionFor(const Route &route, const VciHeights &heights, ScanPlanCache *cache)
{
    std::vector<std::vector<VciRoutePoint>> rows(route.segments.size());
    std::optional<GeoPoint> from;
    for (size_t row = 0; row < route.segments.size(); ++row) {
        Result<std::vector<VciRoutePoint>> points = vciRoutePoints(route, row, from, cache);
        if (!points) {
            MissionError e;
            e.message = QStringLiteral("%1: %2").arg(segmentLabel(route, int(row)), points.error().message);
            return e;
        }
        rows[row] = std::move(*points);
        if (!rows[row].empty())
            from = rows[row].back().position;
    }
    flyVertically(rows);
    VciMissionBuilder builder(route, heights);
    for (size_t row = 0; row < route.segments.size(); ++row)
        if (auto error = builder.add(int(row), rows[row], terrain::terrainFollowTolerance(route.segments[row])))
            return *error;
    VciMission mission = builder.finish();
    if (mission.items.empty()) {
        MissionError e;
        e.message = QCoreApplication::translate("VciMissionPlanner", "the route has no waypoints to fly");
        return e;
    }
    return mission;
}

} // namespace sortie::vehicle
