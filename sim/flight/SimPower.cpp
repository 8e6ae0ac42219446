#include "SimPower.h"

#include <algorithm>

namespace sortie::sim {

endurance::EnergyProfile simEnergyProfile()
{
    endurance::EnergyProfile p;
    p.name = QStringLiteral("sortie-sim multicopter");
    p.source = endurance::ProfileSource::File;
    p.batteryWh = 100;     // 4S 6.8 Ah
    p.reserve = 0.2;
    p.cruiseSpeed = 8;     // FlightModel::Limits
    p.climbRate = 3;
    p.descentRate = 2;
    p.hoverPowerW = 240;   // 100 Wh / 240 W: 25 min of hover, the sim's endurance before it had powers
    p.cruisePowerW = 210;  // translational lift: cheaper than hovering at 8 m/s
    p.climbPowerW = 320;
    p.descentPowerW = 180;
    return p;
}

double simPowerW(const endurance::EnergyProfile &profile, bool armed, bool airborne, double groundSpeed,
                 double verticalSpeed)
{
    if (!armed)
        return 0.0;
    if (!airborne && verticalSpeed <= 0)
        return 0.1 * profile.hoverPowerW;
    double power = profile.levelPowerW(groundSpeed);
    if (verticalSpeed > 0 && profile.climbRate > 0)
        power += (profile.climbPowerW - profile.hoverPowerW) * verticalSpeed / profile.climbRate;
    else if (verticalSpeed < 0 && profile.descentRate > 0)
        power += (profile.descentPowerW - profile.hoverPowerW) * -verticalSpeed / profile.descentRate;
    return std::max(0.0, power);
}

} // namespace sortie::sim
