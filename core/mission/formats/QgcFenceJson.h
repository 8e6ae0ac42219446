#pragma once

#include "JsonCursor.h"
#include "RouteFence.h"

#include <QStringList>

namespace sortie::mission::formats {

// A .plan's "geoFence" (polygons and circles with their inclusion flag, breachReturn) and
// "rallyPoints" sections. A bad polygon, circle or point is left out with a notice naming its JSON
// path and the reason; the rest is kept. Absent sections are an empty fence.
RouteFence fenceFromPlanJson(const JsonCursor &root, QStringList *notices);

// The two sections as QGroundControl writes them (version 2).
Json geoFenceJson(const RouteFence &fence);
Json rallyPointsJson(const RouteFence &fence);

} // namespace sortie::mission::formats
