#pragma once

#include "ElevationSample.h"
#include "WaypointAction.h"

#include <optional>

namespace sortie::terrain {

// The altitude to give a point whose altitude type changes from `from` to `to` so that it still
// flies at the same height above the geoid: AGL → AMSL adds the ground, AMSL → AGL subtracts it.
// nullopt when the ground is not known (a conversion would be a guess): keep the number then.
std::optional<double> convertAltitude(double altitude, mission::AltitudeType from, mission::AltitudeType to,
                                      const ElevationSample &ground);

} // namespace sortie::terrain
