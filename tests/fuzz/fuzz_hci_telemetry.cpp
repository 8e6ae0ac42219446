// HCI telemetry as decoded from a server's TelemetryEvent (HciTelemetryMapper.h): any event a
// server could send becomes telemetry or nothing. Every value is a known field with a finite value
// (NaN or infinity on the wire is no reading), and a value without a time gets the one given.
#include "Domain.pb.h"
#include "HciTelemetryMapper.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::vehicle;
    com::ugcs::ucs::proto::TelemetryEvent event;
    if (!event.ParseFromArray(data, int(size)))
        return 0;
    constexpr int64_t now = 1764670000000;
    const TelemetryBatch batch = hciTelemetry(event, now);
    if (batch.size() > size_t(event.telemetry_size()))
        std::abort();
    for (const TelemetryUpdate &u : batch)
        if (u.field >= TelemetryField::Count_ || !std::isfinite(u.value))
            std::abort();
    return 0;
}
