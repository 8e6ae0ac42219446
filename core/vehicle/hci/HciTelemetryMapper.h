#pragma once

#include "TelemetrySample.h"

#include <optional>
#include <string>

namespace com::ugcs::ucs::proto {
class Telemetry;
class TelemetryEvent;
} // namespace com::ugcs::ucs::proto

namespace sortie::vehicle {

// Turns an HCI TelemetryEvent into normalised telemetry. Flight-controller fields only (a gimbal's
// roll is not the vehicle's), chosen by their Semantic, with the field code where the semantic is
// generic (S_BOOL "is_armed"). HCI sends SI units and radians: angles become degrees here, the one
// conversion on the HCI side (TelemetryField.h); S_CAPACITY_LEVEL (percent) is divided by 100 and S_FLIGHT_MODE names ("RTL", "LOITER", ...) become a FlightMode. Values without a
// number (or a string for the mode), or not finite, are skipped; S_CONTROL_MODE (manual/auto/guided as a coarse
// number) is left out because S_FLIGHT_MODE says the same more precisely. A value without a time
// gets `now` (ms since the epoch).
TelemetryBatch hciTelemetry(const com::ugcs::ucs::proto::TelemetryEvent &event, int64_t now);
void appendHciTelemetry(const com::ugcs::ucs::proto::Telemetry &telemetry, int64_t now, TelemetryBatch &out);
// The camera's `video_stream_uri` (a string field, UgCS's camera subsystem) when the event carries
// one (the last, if several); nullopt otherwise. docs/video.md.
std::optional<std::string> hciVideoStreamUri(const com::ugcs::ucs::proto::TelemetryEvent &event);

} // namespace sortie::vehicle
