#pragma once

#include "AreaScan.h"
#include "Waypoint.h"

#include <variant>

namespace sortie::mission {

// One element of a route: a waypoint or an area scan.
using Segment = std::variant<Waypoint, AreaScan>;

inline bool isWaypoint(const Segment &s) { return s.index() == 0; }
inline bool isAreaScan(const Segment &s) { return s.index() == 1; }
inline const Waypoint *asWaypoint(const Segment &s) { return std::get_if<Waypoint>(&s); }
inline Waypoint *asWaypoint(Segment &s) { return std::get_if<Waypoint>(&s); }
inline const AreaScan *asAreaScan(const Segment &s) { return std::get_if<AreaScan>(&s); }
inline AreaScan *asAreaScan(Segment &s) { return std::get_if<AreaScan>(&s); }

// A representative point: the waypoint itself or the polygon's first vertex.
GeoPoint anchorOf(const Segment &s);
double altitudeOf(const Segment &s);
AltitudeType altitudeTypeOf(const Segment &s);
double speedOf(const Segment &s);

} // namespace sortie::mission
