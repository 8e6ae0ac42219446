#pragma once

#include "AreaScanPlanner.h"
#include "JsonCursor.h"
#include "Segment.h"
#include "SegmentPlanner.h"

#include <QStringList>

namespace sortie::mission::formats {

// A QGroundControl "survey" complex item <-> an area scan (polygon, CameraCalc, angle,
// turnaround). The scan's speed is not part of the item: it is the mission's speed at that point.
AreaScan surveyFromJson(const JsonCursor &item, QStringList *notices);  // throws JsonPathError
// firstJumpId numbers the generated mission items inside it; returns how many it used.
Json surveyToJson(const AreaScan &scan, const AreaScanPlan &plan, int firstJumpId, int *itemsUsed);

// A "CorridorScan" complex item <-> a corridor-mapping segment (centre polyline, CorridorWidth ->
// `width`, CameraCalc -> `camera` (by name), `groundSampleDistance`, `overlapForward`,
// `overlapSide`, `altitudeType`). A camera only QGroundControl knows is kept by name, with a notice.
AlgorithmSegment corridorFromJson(const JsonCursor &item, QStringList *notices);  // throws JsonPathError
Json corridorToJson(const AlgorithmSegment &corridor, const SegmentPlan &plan, int firstJumpId, int *itemsUsed);
// A "StructureScan" as far as it maps: a perimeter around the structure's polygon at the scan's
// altitude, one loop per layer (UgCS flies the loops at one height: a notice says so).
AlgorithmSegment structureScanFromJson(const JsonCursor &item, QStringList *notices);  // throws JsonPathError

} // namespace sortie::mission::formats
