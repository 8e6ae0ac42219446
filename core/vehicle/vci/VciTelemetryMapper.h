#pragma once

#include "TelemetrySample.h"

#include <nlohmann/json.hpp>

#include <string_view>

namespace sortie::vehicle {

// Turns the body of a VCI profile resource (docs/vci-profile.md) into normalised telemetry. The
// profile speaks SI and radians, so this is a renaming (/telemetry/attitude "yaw" becomes Heading,
// /state/mode "loiter" becomes FlightMode::Hold, and so on) and the one conversion on the VCI side:
// angles become degrees (TelemetryField.h). Fields missing from a body, of the wrong JSON type, or
// not finite once converted, are skipped. Each value gets the body's "time" (ms since the epoch)
// when it has one an int64 holds, else `now`. Resources that carry no telemetry give an empty batch.
TelemetryBatch vciTelemetry(std::string_view uri, const nlohmann::json &body, int64_t now);

} // namespace sortie::vehicle
