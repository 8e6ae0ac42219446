#pragma once

#include "PlanCommands.h"

namespace sortie::plan {

// sortie-plan conflicts ROUTE_FILE ROUTE_FILE [ROUTE_FILE ...] [--start SECONDS,...] [--speed M/S]
// [--separation H,V] [--json]: where the routes, flown on one clock, come closer than the separation
// (docs/deconfliction.md). Exit 2 when there is a conflict.
int runConflicts(const QStringList &args, Streams io);

} // namespace sortie::plan
