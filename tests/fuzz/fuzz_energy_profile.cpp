// Energy profile file (docs/endurance.md): any bytes are read or refused; a profile that is read
// writes a file that reads back equal, and its level-power curve is finite at any speed.
#include "EnergyProfile.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::endurance;
    const auto profile = readEnergyProfile(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!profile.ok())
        return 0;
    const auto back = readEnergyProfile(writeEnergyProfile(profile.value()));
    if (!back.ok() || !(back.value() == profile.value()))
        std::abort();
    for (double v : {0.0, 1.0, profile->cruiseSpeed, 3 * profile->cruiseSpeed})
        if (!std::isfinite(profile->levelPowerW(v)))
            std::abort();
    return 0;
}
