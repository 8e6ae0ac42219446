#pragma once

#include "GeoPoint.h"

#include <vector>

namespace sortie::mission {

// Whether corners make a polygon worth flying: three or more valid corners enclosing some area
// (1 m² on the local plane). A new area scan or polygon tool is refused without it.
bool enclosesArea(const std::vector<GeoPoint> &polygon);

} // namespace sortie::mission
