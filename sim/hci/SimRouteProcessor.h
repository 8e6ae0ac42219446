#pragma once

#include "FlightModel.h"
#include "HciProto.h"

#include <QString>

#include <string>
#include <vector>

namespace com::ugcs::ucs::proto {
class VehicleProfile;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// What ProcessRoute checks a route against: the vehicle profile's limits (0 = no limit).
struct SimRouteLimits
{
    double maxSpeed = 0;        // VPT_MAX_HORIZONTAL_SPEED, m/s
    double maxAltitudeAgl = 0;  // VPT_MAX_ALTITUDE_AGL, m
    double climbRate = 3;       // VPT_MAX_CLIMB_RATE, m/s
    double acceptanceRadius = 2;// VPT_WAYPOINT_ACCEPTANCE_RADIUS, m

    static SimRouteLimits of(const pb::VehicleProfile &profile);
};

// The simulator's route processing (pure, no I/O): waypoint segments become SpeedChange + Waypoint
// actions (plus their Wait, Heading and camera actions) with per-segment distance and time estimates.
// Each segment is validated: altitude above the route's maxAltitude or the profile's limit, below
// ground, speed above the route's maxSpeed or the profile's limit, an unsupported algorithm, a figure
// without points. A failing segment gets status RPS_INVALID, the failing point's index and messages
// (MS_ERROR); an altitude below the route's safe altitude is a warning (MS_WARNING).
class SimRouteProcessor
{
public:
    static constexpr const char *kWaypointAlgorithm = "com.ugcs.ucs.service.routing.impl.WaypointAlgorithm";

    static pb::ProcessedRoute process(const pb::Route &route, const SimRouteLimits &limits, double groundElevation);
    // A stable hex digest of the route as processed (ProcessRouteResponse.hash).
    static std::string hash(const pb::Route &route);
    // The waypoints a vehicle flies for an uploaded route, altitudes above its home ground. Empty with
    // `error` set when the route cannot be flown (a segment not processed, no waypoint).
    static std::vector<FlightModel::Waypoint> flightPlan(const pb::ProcessedRoute &route, double homeGroundElevation,
                                                         QString *error);
};

} // namespace sortie::sim
