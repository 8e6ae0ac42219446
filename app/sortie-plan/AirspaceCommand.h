#pragma once

#include "PlanCommands.h"

namespace sortie::plan {

// sortie-plan airspace ROUTE_FILE --zones FILE [--zones FILE ...] [--dem PATH] [--buffer M] [--json]:
// every flown leg of each route checked in 3D against the zones (docs/airspace.md). Exit 2 when
// a leg enters an exclusion zone or leaves the inclusion zones.
int runAirspace(const QStringList &args, Streams io);

} // namespace sortie::plan
