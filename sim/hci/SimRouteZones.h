#pragma once

#include "HciProto.h"

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class SimObjectStore;
class SimTerrain;

// ProcessRoute's no-fly-zone pass, run after the terrain pass, as a UgCS server refuses a route
// through a zone it was asked to check: when the route's checkAerodromeNfz / checkCustomNfz is
// set, the processed flown path (every Waypoint, Takeoff and Landing action at its wgs84Altitude,
// the take-off climb and the landing descent included, over the world's ground) is checked in 3D
// against the store's zones of those types (core/airspace's check). Each stretch inside a zone
// makes the segment it arrives in RPS_INVALID with an MS_ERROR naming the zone and where:
// "Segment 2: the route crosses the aerodrome no-fly zone 'Spilve airfield': Leg 2 enters
// 'Spilve airfield' from 410 m to 1,520 m (floor ground, ceiling 150 m AGL)."
class SimRouteZones
{
public:
    static void apply(pb::ProcessedRoute &processed, const pb::Route &route, const SimObjectStore &store, const SimTerrain &terrain);
};

} // namespace sortie::sim
