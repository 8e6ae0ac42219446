#pragma once

#include "Route.h"

#include <vector>

namespace sortie::mission {

class ScanPlanCache;

// One point of the path a route flies: waypoints as they are, area scans expanded.
struct PathPoint
{
    GeoPoint position;
    double altitude = 0.0;
    AltitudeType altitudeType = AltitudeType::Agl;
    double speed = 0.0;       // m/s on the leg arriving here
    double holdSeconds = 0.0; // waits at this point
    WaypointRole role = WaypointRole::Pass;
    int segment = -1;         // row of the segment this point belongs to
};

// The flown path. Scans that cannot be planned contribute their polygon's first vertex only.
std::vector<PathPoint> flightPath(const Route &route, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission
