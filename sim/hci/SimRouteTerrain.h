#pragma once

#include "HciProto.h"

namespace com::ugcs::ucs::proto {
class VehicleProfile;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class SimTerrain;

// Route processing's terrain pass, run over what SimRouteProcessor made (it knows the geometry;
// this knows the ground). Every processed waypoint, take-off and landing gets the ground under it as
// `elevation`; an AGL waypoint (altitudeFrame AF_AGL, processed as flat ground + AGL) and a take-off
// fly the real ground + their height as wgs84Altitude, a landing is on the ground. First, a segment
// of an area tool (an algorithm with `tolerance`) flown AGL follows the terrain, as UgCS's do: between
// its consecutive AGL waypoints, waypoints are added where the ground departs more than the tolerance
// from a straight climb (terrain::markFollowPoints, the rule the client's profile draws with). Then
// the legs are joined as they are flown (mission::flownLegs, SimFlownPoints.h): a take-off climbs
// straight up to the next point's height (its wgs84Altitude becomes that height), a landing is
// reached at the height the leg left at and descended to straight down. Each leg across is sampled
// every kStep metres: one closer to the ground than the profile's safe distance to terrain makes the
// segment it arrives in RPS_INVALID with an MS_ERROR naming the leg, the distance along it and the
// clearance; the vertical moves are not judged (they meet the ground on purpose). An AGL waypoint
// where the terrain has no data is an error too (its height is unknown).
class SimRouteTerrain
{
public:
    static constexpr double kStep = 10.0;
    static constexpr double kDefaultSafeDistance = 10.0;

    // VPT_SAFE_DISTANCE_TO_TERRAIN of the route's own profile, else of the stored one, else 10 m.
    static double safeDistance(const pb::VehicleProfile &routeProfile, const pb::VehicleProfile *stored);
    static void apply(pb::ProcessedRoute &route, const SimTerrain &terrain, double safeDistance);
};

} // namespace sortie::sim
