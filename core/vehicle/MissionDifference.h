#pragma once

#include "VehicleTypes.h"

#include <QString>

#include <vector>

namespace sortie::vehicle {

// Empty when `readBack` is the mission that was sent, as a vehicle stores it: the same points (to a
// millimetre), altitudes, acceptance radii and actions, and the same speeds wherever one was given
// (a vehicle fills in its default where the speed was 0). Otherwise what differs first
// ("waypoint 3: altitude 40 m, sent 45 m"). Any link that reads its mission back verifies with it.
QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &readBack);

} // namespace sortie::vehicle
