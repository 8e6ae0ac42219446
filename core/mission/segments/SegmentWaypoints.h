#pragma once

#include "MissionError.h"
#include "Route.h"
#include "SegmentPlanner.h"

#include <optional>
#include <vector>

namespace sortie::mission {

class ScanPlanCache;

// Segment `row` of `route` as the plain waypoints a vehicle that plans nothing itself flies (a VCI
// vehicle, a resumed mission), expanded as sortie-sim's ProcessRoute expands it:
// - a waypoint as it is;
// - Sortie's area scan as its passes, the camera series by distance started at the first point and
//   stopped at the last;
// - any other UgCS tool planned from `from` (where the previous segment ended), its camera commands
//   as actions (a gimbal facing down; a heading with the camera level; a series by distance and its
//   end) and the segment's own actions where the plan runs them; a planned take-off or landing keeps
//   its role.
// Refused, with the reason only (the caller names the segment), when the segment cannot be planned
// here (a UgCS tool this client does not know, a scan without a plan).
Result<std::vector<Waypoint>> segmentWaypoints(const Route &route, size_t row, std::optional<GeoPoint> from,
                                               ScanPlanCache *cache = nullptr);

// The actions a planned point's camera commands stand for, in the order given.
std::vector<WaypointAction> cameraCommandActions(const std::vector<CameraCommand> &commands);

} // namespace sortie::mission
