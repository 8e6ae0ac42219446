#pragma once

#include "MissionError.h"
#include "VehicleTypes.h"

#include <vector>

namespace sortie::mission {
struct Route;
class ScanPlanCache;
} // namespace sortie::mission

namespace sortie::vehicle {

// A route as the list of waypoints a vehicle flies by itself (a VCI vehicle, which has no server to
// process it): waypoints as they are, area scans expanded into their passes with the camera
// triggering by distance from the first point to the last, actions in the VCI profile's words.
// Refused, naming the waypoint, when something has no such form: AMSL altitudes (the profile
// flies above home), an action Sortie keeps only verbatim, a scan that cannot be planned.
mission::Result<std::vector<MissionItem>> missionItemsFor(const mission::Route &route, mission::ScanPlanCache *cache = nullptr);

// Empty when `readBack` is the mission that was sent, as a vehicle stores it: the same points (to a
// millimetre), altitudes, acceptance radii and actions, and the same speeds wherever one was given
// (a vehicle fills in its default where the speed was 0). Otherwise what differs first
// ("waypoint 3: altitude 40 m, sent 45 m").
QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &readBack);

} // namespace sortie::vehicle
