#pragma once

#include "VciRoutePoints.h"

#include <vector>

namespace sortie::terrain {
class ElevationService;
} // namespace sortie::terrain

namespace sortie::vehicle {

// An AGL area tool's points as a VCI vehicle flies them over the ground (terrain::followTerrain):
// each point at its height above the ground under it, and the points following adds between them
// where the ground departs by more than the tolerance (flying the leg's speed, no actions).
struct VciFollowedPoints
{
    std::vector<MissionItem> items; // heights above home
    bool ok = false;                // false: the ground is not known everywhere; items is empty
    bool pending = false;           // some ground is still being fetched
};

VciFollowedPoints followGround(const std::vector<VciRoutePoint> &points, double tolerance,
                               terrain::ElevationService &elevation, double homeAmsl);

} // namespace sortie::vehicle
