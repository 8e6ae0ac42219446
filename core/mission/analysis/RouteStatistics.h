#pragma once

#include "GeoPoint.h"
#include "Route.h"

namespace sortie::mission {

class ScanPlanCache;

// Figures of a route. Length is the sum of WGS-84 geodesics between consecutive points of the
// flown path (area scans expanded into their transects and turnarounds), horizontal only; each
// geodesic is exact to 0.5 mm (Vincenty). Flight time assumes each leg is flown at its speed
// while climbing or descending at the profile's rates, whichever takes longer, plus waits,
// take-off climbs and landing descents; it ignores acceleration and wind.
struct RouteStatistics
{
    int waypointCount = 0;
    int areaScanCount = 0;
    int pathPointCount = 0;         // points of the flown path
    double lengthMeters = 0.0;
    double flightTimeSeconds = 0.0;
    double climbMeters = 0.0;       // total ascent between points of the same altitude type
    double descentMeters = 0.0;
    int photoCount = 0;             // from scans and the waypoints' camera actions
    GeoBox boundingBox;
    bool operator==(const RouteStatistics &) const = default;
};

RouteStatistics computeStatistics(const Route &route, ScanPlanCache *cache = nullptr);

// Smallest box holding the points; crosses the antimeridian when that is smaller.
GeoBox boundingBoxOf(const std::vector<GeoPoint> &points);

} // namespace sortie::mission
