#pragma once

#include "AlgorithmDefinition.h"
#include "Route.h"

namespace sortie::mission {

// What a segment the operator adds starts with, so every way of adding one (a click, a drawing
// tool, the table) gives the same first values.

// 50 m, kept between the route's safe and maximum altitude: where a new point or tool flies.
double newFigureHeight(const RouteSettings &settings);

// A pass waypoint at `position`: the route's height and initial speed, or, after another pass
// waypoint, that one's altitude, altitude type, speed and turn.
Waypoint newWaypoint(const RouteSettings &settings, const Waypoint *previousPass, const GeoPoint &position);

// An area scan's flight values before the operator sets them: 60 m (kept within the route's
// altitudes) at the route's initial speed.
void applyAreaScanDefaults(AreaScan &scan, const RouteSettings &settings);

// An algorithm segment's figure heights, circle radius and parameter values from its definition:
// the definition's defaults, with the height, speed and a camera chosen for the route.
void applyToolDefaults(AlgorithmSegment &segment, const AlgorithmDefinition &definition, const RouteSettings &settings);

} // namespace sortie::mission
