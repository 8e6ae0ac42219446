#pragma once

#include "HciProto.h"

#include <string_view>

namespace sortie::hci {

// A parser for the one message that arrives thousands of times a second: a Notification carrying a
// TelemetryEvent (vehicle reference, telemetry values with their fields). It walks the wire format
// directly into a (reused) pb::Notification, without the general parser's bookkeeping, and gives up on
// anything it does not expect: another event, an unknown or repeated sub-message, an unknown enum
// value, a malformed length. When it gives up it returns false and the caller parses the payload the
// general way, so the result is always exactly what ParseFromArray would produce. Pure; no I/O.
class HciTelemetryFastPath
{
public:
    // True when `payload` was a telemetry notification and `out` now holds it, complete (its required
    // fields are present). False leaves `out` in an unspecified state.
    static bool parse(std::string_view payload, pb::Notification *out);
};

} // namespace sortie::hci
