#pragma once

#include "WaypointAction.h"

namespace com::ugcs::ucs::proto { class ActionDefinition; }

namespace sortie::mission {

// Waypoint actions <-> UgCS ActionDefinition. Angles and positions are radians on the wire.
// Definitions Sortie has no type for become ServerAction: the definition itself, edited in place.
WaypointAction actionFromHci(const com::ugcs::ucs::proto::ActionDefinition &definition);
// Writes the action into def, which holds the server's original definition (or is empty for a
// new action). Only fields whose value differs from what def already says are written, so an
// unchanged action stays byte-identical.
void actionToHci(const WaypointAction &action, com::ugcs::ucs::proto::ActionDefinition &def);

} // namespace sortie::mission
