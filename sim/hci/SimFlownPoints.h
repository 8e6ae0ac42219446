#pragma once

#include "FlownLegs.h"
#include "HciProto.h"

#include <optional>
#include <vector>

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// A processed route's flown points (its Waypoint, Takeoff and Landing actions, in order) as the one
// rule that joins them sees them (mission::flownLegs: straight up at a take-off, straight down at a
// landing). Read by the terrain pass and by the flight plan, so what is checked is what is flown.
struct SimFlownPoint
{
    double latitude = 0, longitude = 0;  // degrees
    double amsl = 0;                      // the action's wgs84Altitude
    std::optional<double> ground;         // its elevation, when set
    bool agl = false;                     // its height is above the ground under it (AF_AGL, a take-off)
    mission::WaypointRole role = mission::WaypointRole::Pass;
    int segment = -1;
    double speed = 0;                     // m/s of the last speed change before it
    pb::Action *action = nullptr;         // where it came from (mutable routes only)

    double heightAboveGround() const { return ground ? amsl - *ground : amsl; }
};

std::vector<SimFlownPoint> simFlownPoints(pb::ProcessedRoute &route);
std::vector<SimFlownPoint> simFlownPoints(const pb::ProcessedRoute &route);
std::vector<mission::LegShape> simFlownLegs(const std::vector<SimFlownPoint> &points);

// Point `whose` height over point `at` (AMSL): an AGL height rides the ground at `at`.
double amslOver(const std::vector<SimFlownPoint> &points, size_t whose, size_t at);

} // namespace sortie::sim
