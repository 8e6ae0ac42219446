#pragma once

#include "MissionError.h"
#include "VehicleTypes.h"
#include "WaypointAction.h"

#include <vector>

namespace sortie::vehicle {

// A route's action in the VCI profile's words (docs/vci-profile.md, "Mission actions": SI units,
// radians), or why it has none: a wait for the operator, an AMSL point of interest, a UgCS server's
// own action.
mission::Result<MissionAction> vciAction(const mission::WaypointAction &action);

} // namespace sortie::vehicle
