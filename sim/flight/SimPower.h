#pragma once

#include "EnergyProfile.h"

namespace sortie::sim {

// The energy profile every simulated vehicle flies with unless its configuration names another
// (docs/endurance-fit.md): a 4S quadcopter with a 100 Wh battery. Its speeds and rates are the
// FlightModel's default limits, so what the sim flies is what the profile describes.
endurance::EnergyProfile simEnergyProfile();

// What the motors and avionics draw from the battery, in watts, doing what the vehicle does. The
// profile's figures are the truth a fit of the sim's logs must recover:
//   disarmed: 0 (a sim left standing keeps its battery); armed on the ground: idle, 10 % of hover;
//   airborne: the profile's level curve at the ground speed (no wind: air speed is ground speed),
//   plus, climbing at vz, (climbPowerW − hoverPowerW)·vz/climbRate, and descending at vz,
//   (descentPowerW − hoverPowerW)·|vz|/descentRate. So a pure climb at climbRate draws climbPowerW
//   and level flight at cruiseSpeed draws cruisePowerW, exactly.
double simPowerW(const endurance::EnergyProfile &profile, bool armed, bool airborne, double groundSpeed,
                 double verticalSpeed);

} // namespace sortie::sim
