#pragma once

#include "MissionError.h"
#include "VehicleTypes.h"
#include "WaypointAction.h"

#include <vector>

namespace sortie::mission {
struct PlannedPoint;
} // namespace sortie::mission

namespace sortie::vehicle {

// A route's action in the VCI profile's words (docs/vci-profile.md, "Mission actions": SI units,
// radians), or why it has none: a wait for the operator, an AMSL point of interest, a UgCS server's
// own action.
mission::Result<MissionAction> vciAction(const mission::WaypointAction &action);

// The camera commands of a planned point, as sortie-sim's ProcessRoute turns them into actions.
std::vector<MissionAction> cameraActions(const mission::PlannedPoint &point);

// A photo series by distance: `interval` metres between shots; 0 stops the series.
MissionAction seriesByDistance(double interval);

} // namespace sortie::vehicle
