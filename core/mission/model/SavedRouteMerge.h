#pragma once

#include "Route.h"

namespace sortie::mission {

// The edits made while a save was in flight, laid over what the server stored: `current` (the
// route as it is now) with the route origin of `saved` (the server's copy: its new version, so
// the next save is not taken for someone else's), and each of its segments that is unchanged
// since `sent` (what the save sent) with the origin the server gave that segment (its id). A
// segment edited meanwhile keeps its own origin. Pure.
Route overSavedRoute(Route current, const Route &sent, const Route &saved);

} // namespace sortie::mission
