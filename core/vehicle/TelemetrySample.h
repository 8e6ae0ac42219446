#pragma once

#include "TelemetryField.h"

#include <cstdint>
#include <vector>

namespace sortie::vehicle {

// One value of one field at one time (ms since the epoch). 16 bytes.
struct TelemetrySample
{
    int64_t time = 0;
    double value = 0;
};

// One value as a link delivers it.
struct TelemetryUpdate
{
    TelemetryField field = TelemetryField::Latitude;
    double value = 0;
    int64_t time = 0; // ms since the epoch: the vehicle's time when it sent one, else when it arrived
};

using TelemetryBatch = std::vector<TelemetryUpdate>;

} // namespace sortie::vehicle
