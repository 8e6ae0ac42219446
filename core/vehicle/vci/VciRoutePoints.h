#pragma once

#include "GeoPoint.h"
#include "MissionError.h"
#include "MissionEnums.h"
#include "Waypoint.h"
#include "VehicleTypes.h"

#include <optional>
#include <vector>

namespace sortie::mission {
struct Route;
class ScanPlanCache;
} // namespace sortie::mission

namespace sortie::vehicle {

// A point to fly, its height still in the route's terms (VciMissionBuilder makes it one above home).
struct VciRoutePoint
{
    mission::GeoPoint position;
    double height = 0.0;
    mission::AltitudeType type = mission::AltitudeType::Agl;
    double speed = 0.0;
    double acceptanceRadius = 0.0;
    std::vector<MissionAction> actions;
    mission::WaypointRole role = mission::WaypointRole::Pass;  // a take-off climbs, a landing descends, straight (FlownLegs.h)
};

// The points a VCI vehicle flies for segment `row` of `route`, expanded as sortie-sim's ProcessRoute
// expands it: a waypoint as it is; Sortie's area scan as its passes, the camera on from the first
// point to the last; any other UgCS tool planned from `from` (where the previous segment ended), with
// camera commands and the segment's own actions where the plan runs them, a landing's "land".
// Refused, with the reason only (the caller names the segment), where something has no VCI form.
mission::Result<std::vector<VciRoutePoint>> vciRoutePoints(const mission::Route &route, size_t row,
                                                           std::optional<mission::GeoPoint> from,
                                                           mission::ScanPlanCache *cache);

} // namespace sortie::vehicle
