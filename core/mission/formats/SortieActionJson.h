#pragma once

#include "JsonCursor.h"
#include "WaypointAction.h"

// A waypoint action in a .sortie file, both ways: one JSON object per action, "type" naming it; a
// server action keeps its definition's bytes as base64 under "hci".
namespace sortie::mission::formats {

Json actionJson(const WaypointAction &action);
WaypointAction readAction(const JsonCursor &c);  // fails at the cursor on an unknown or bad action

} // namespace sortie::mission::formats
