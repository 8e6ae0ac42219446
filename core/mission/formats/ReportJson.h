#pragma once

#include "AreaScanPlanner.h"
#include "JsonCursor.h"
#include "RouteStatistics.h"
#include "RouteValidator.h"

namespace sortie::mission::formats {

// Machine-readable reports (sortie-plan --json, scripts): plain JSON objects with SI units in
// the key names.
Json statisticsJson(const RouteStatistics &statistics);
Json validationJson(const ValidationReport &report);
Json scanPlanJson(const AreaScanPlan &plan);

} // namespace sortie::mission::formats
