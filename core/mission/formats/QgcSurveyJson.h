#pragma once

#include "AreaScanPlanner.h"
#include "JsonCursor.h"

#include <QStringList>

namespace sortie::mission::formats {

// A QGroundControl "survey" complex item <-> an area scan (polygon, CameraCalc, angle,
// turnaround). The scan's speed is not part of the item: it is the mission's speed at that point.
AreaScan surveyFromJson(const JsonCursor &item, QStringList *notices);  // throws JsonPathError
// firstJumpId numbers the generated mission items inside it; returns how many it used.
Json surveyToJson(const AreaScan &scan, const AreaScanPlan &plan, int firstJumpId, int *itemsUsed);

} // namespace sortie::mission::formats
