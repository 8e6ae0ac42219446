#pragma once

#include "GeoPoint.h"
#include "Route.h"

#include <cmath>

namespace sortie::mission {

class ScanPlanCache;

// Figures of a route. Length is the sum of WGS-84 geodesics between consecutive points of the
// flown path (area scans expanded into their transects and turnarounds), horizontal only; each
// geodesic is exact to 0.5 mm (Vincenty). Flight time is the time model's (RouteTiming.h) with the
// route's own figures (timingOf): each leg at its speed (the route's initial speed where unset)
// while climbing or descending at the profile's rates, whichever takes longer, plus waits and
// panoramas, take-off climbs and landing descents; no wind, no acceleration. NaN when a leg has
// no speed at all.
struct RouteStatistics
{
    int waypointCount = 0;
    int areaScanCount = 0;
    int pathPointCount = 0;         // points of the flown path
    double lengthMeters = 0.0;
    double flightTimeSeconds = 0.0;  // NaN: cannot be timed
    double climbMeters = 0.0;       // total ascent between points of the same altitude type
    double descentMeters = 0.0;
    int photoCount = 0;             // from scans and the waypoints' camera actions
    GeoBox boundingBox;
    bool operator==(const RouteStatistics &o) const
    {
        // NaN flight times compare equal: the statistics did not change.
        const bool sameTime = flightTimeSeconds == o.flightTimeSeconds || (std::isnan(flightTimeSeconds) && std::isnan(o.flightTimeSeconds));
        return sameTime && waypointCount == o.waypointCount && areaScanCount == o.areaScanCount && pathPointCount == o.pathPointCount
            && lengthMeters == o.lengthMeters && climbMeters == o.climbMeters && descentMeters == o.descentMeters
            && photoCount == o.photoCount && boundingBox == o.boundingBox;
    }
};

RouteStatistics computeStatistics(const Route &route, ScanPlanCache *cache = nullptr);

// Smallest box holding the points; crosses the antimeridian when that is smaller.
GeoBox boundingBoxOf(const std::vector<GeoPoint> &points);

} // namespace sortie::mission
