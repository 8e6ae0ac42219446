#include "Segment.h"

namespace sortie::mission {

GeoPoint anchorOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->position;
    const AreaScan &scan = std::get<AreaScan>(s);
    return scan.polygon.empty() ? GeoPoint{} : scan.polygon.front();
}

double altitudeOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->altitude;
    return scanAltitude(std::get<AreaScan>(s).parameters);
}

AltitudeType altitudeTypeOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->altitudeType;
    return std::get<AreaScan>(s).parameters.altitudeType;
}

double speedOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->speed;
    return std::get<AreaScan>(s).parameters.speed;
}

} // namespace sortie::mission
