#pragma once

#include "PlanCommands.h"

namespace sortie::plan {

// sortie-plan profile ROUTE_FILE --dem PATH [--step METERS] [--json]: ground, altitude and
// clearance along each route's flown path, from SRTM tiles.
int runProfile(const QStringList &args, Streams io);

} // namespace sortie::plan
