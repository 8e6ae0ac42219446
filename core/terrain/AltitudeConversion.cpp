#include "AltitudeConversion.h"

namespace sortie::terrain {

std::optional<double> convertAltitude(double altitude, mission::AltitudeType from, mission::AltitudeType to,
                                      const ElevationSample &ground)
{
    if (from == to)
        return altitude;
    if (!ground.hasValue())
        return std::nullopt;
    return to == mission::AltitudeType::Amsl ? altitude + ground.ground : altitude - ground.ground;
}

} // namespace sortie::terrain
