#pragma once

#include "FlightModel.h"
#include "HciProto.h"
#include "SegmentPlanner.h"

#include <QString>

#include <string>
#include <vector>

namespace com::ugcs::ucs::proto {
class VehicleProfile;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// What ProcessRoute checks a route against and plans it with: the vehicle profile's limits (0 = no
// limit) and camera payloads.
struct SimRouteLimits
{
    double maxSpeed = 0;        // VPT_MAX_HORIZONTAL_SPEED, m/s
    double maxAltitudeAgl = 0;  // VPT_MAX_ALTITUDE_AGL, m
    double climbRate = 3;       // VPT_MAX_CLIMB_RATE, m/s
    double acceptanceRadius = 2;// VPT_WAYPOINT_ACCEPTANCE_RADIUS, m
    std::vector<mission::ProfileCamera> cameras;  // the profile's complete camera payloads

    // Cameras from the profile's payload links that carry their parameters (see profileCameras()).
    static SimRouteLimits of(const pb::VehicleProfile &profile);
};

// The simulator's route processing (pure, no I/O). Every segment is planned by the algorithm its class
// names (mission::planSegment, the planner the client previews with): waypoints, take-off and landing at
// their point, orbits, perimeters, area scans, photogrammetry and corridors with their camera series,
// and the SAR and facade tools. Each planned point becomes a SpeedChange where the speed changes, the
// Waypoint (Takeoff, Landing) action, its camera actions (OO_SYSTEM) and the segment's own actions where
// actionExecution puts them (OO_USER), with per-segment distance and time estimates.
// Validation names the segment ("Segment 3 (Photogrammetry): overlapForward: 95 is above the maximum of
// 90 %"): parameters out of their definition's range, an unknown algorithm, a figure without enough points,
// altitude above the route's maxAltitude or the profile's limit, below ground, speed above the route's
// maxSpeed or the profile's limit. A failing segment gets status RPS_INVALID, the failing point's index and
// MS_ERROR messages; an altitude below the route's safe altitude and a camera too slow for the speed are
// MS_WARNING; the calculated figures (passes, spacing, photos) are MS_INFORMATION.
class SimRouteProcessor
{
public:
    static constexpr const char *kWaypointAlgorithm = "com.ugcs.ucs.service.routing.impl.WaypointAlgorithm";

    static pb::ProcessedRoute process(const pb::Route &route, const SimRouteLimits &limits, double groundElevation);
    // A stable hex digest of the route as processed (ProcessRouteResponse.hash).
    static std::string hash(const pb::Route &route);
    // The waypoints a vehicle flies for an uploaded route, altitudes above its home ground, joined as
    // the terrain pass checked them (mission::flownLegs): over the Takeoff point at the height its
    // first leg leaves at (the vehicle climbs straight up to it), every Waypoint, over the Landing
    // point at the height the leg left at, landing there (straight down). Empty with `error` set
    // when the route cannot be flown (a segment not processed, no waypoint).
    static std::vector<FlightModel::Waypoint> flightPlan(const pb::ProcessedRoute &route, double homeGroundElevation,
                                                         QString *error);
};

} // namespace sortie::sim
