#pragma once

#include "AlgorithmSegment.h"
#include "AreaScan.h"
#include "Waypoint.h"

#include <optional>
#include <variant>

namespace sortie::mission {

// One element of a route: a waypoint (take-off and landing points included), an area scan, or a
// segment of any other UgCS algorithm (photogrammetry, circle, perimeter, corridor, unknown ones).
using Segment = std::variant<Waypoint, AreaScan, AlgorithmSegment>;

inline bool isWaypoint(const Segment &s) { return s.index() == 0; }
inline bool isAreaScan(const Segment &s) { return s.index() == 1; }
inline bool isAlgorithmSegment(const Segment &s) { return s.index() == 2; }
inline const Waypoint *asWaypoint(const Segment &s) { return std::get_if<Waypoint>(&s); }
inline Waypoint *asWaypoint(Segment &s) { return std::get_if<Waypoint>(&s); }
inline const AreaScan *asAreaScan(const Segment &s) { return std::get_if<AreaScan>(&s); }
inline AreaScan *asAreaScan(Segment &s) { return std::get_if<AreaScan>(&s); }
inline const AlgorithmSegment *asAlgorithmSegment(const Segment &s) { return std::get_if<AlgorithmSegment>(&s); }
inline AlgorithmSegment *asAlgorithmSegment(Segment &s) { return std::get_if<AlgorithmSegment>(&s); }

// A representative point: the waypoint itself, the polygon's first vertex, the figure's first point.
GeoPoint anchorOf(const Segment &s);
// Moves the whole segment so that its anchor lands on `anchor`: a waypoint goes there, a figure
// keeps its shape and size (each point keeps its east/north offset from the anchor).
void moveSegmentTo(Segment &s, const GeoPoint &anchor);
// The flight altitude; NaN when a segment does not say (an unknown algorithm without `height`).
double altitudeOf(const Segment &s);
AltitudeType altitudeTypeOf(const Segment &s);
// m/s; NaN when the segment does not say.
double speedOf(const Segment &s);
const ServerOrigin &originOf(const Segment &s);
// "Waypoint 3", "Area scan 4", "Circle 5": what messages call a row.
QString segmentLabel(int row, const Segment &s);
// "waypoint", "takeoff", "land", "areaScan", "circle", "photogrammetry", ... "unknown".
QString segmentKindName(const Segment &s);
// The vertices of an area (scan, photogrammetry, perimeter...), the corridor's centre line, the
// circle's centre: the points a map lets the operator drag. Empty for a waypoint.
std::vector<GeoPoint> figureOf(const Segment &s);
// The lawnmower Sortie plans for a segment: an area scan itself, or a photogrammetry segment as
// the scan its parameters describe (its camera resolved against the profile's `cameras`, else the
// built-in list by name; GSD, overlaps, direction, overshoot, speed); nullopt for anything else.
std::optional<AreaScan> scanOf(const Segment &s, const std::vector<ProfileCamera> &cameras = {});

} // namespace sortie::mission
