#pragma once

#include "TelemetryField.h"
#include "TelemetrySample.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sortie::flightlog {

// The on-disk form of one vehicle's telemetry over about one second: a block. Pure C++ (no Qt, no
// I/O), so it is unit-tested and fuzzed on byte strings. See docs/flightlog.md for the layout.
//
// Every value is quantised to its field's step (fieldStep: 1e-9 rad for positions, 1 mm for
// altitudes, 1e-5 rad for attitude and course, ...; the values themselves in degrees, as the store), then stored as zig-zag varints of its first or second
// difference (whichever is shorter for that field in that block); times as varints of their second
// difference, written once for all the fields that share them (a telemetry message gives its fields
// one time). Regular 10 Hz telemetry therefore takes one or two bytes per value. NaN (missing) is
// kept as missing in a bitmap, never turned into 0. A CRC-32 closes the block.
struct FieldSamples
{
    vehicle::TelemetryField field = vehicle::TelemetryField::Latitude;
    std::vector<vehicle::TelemetrySample> samples; // in arrival order, times ascending
};

using BlockFields = std::vector<FieldSamples>;

// The quantum of a field, in its unit in the store (TelemetryField.h): a value is stored as
// round(value / step). Angles' quanta are whole radians' fractions (1e-9 rad, 1e-5 rad), as the log
// has always stored them, given here in degrees.
double fieldStep(vehicle::TelemetryField field);
// The value a stored value reads back as (what a reader and a replay see).
double quantize(vehicle::TelemetryField field, double value);

// A summary of a block that does not decode any value: its time span and count per field.
struct BlockSummary
{
    int64_t t0 = 0;
    int64_t t1 = 0;
    std::array<uint32_t, vehicle::kTelemetryFieldCount> counts{};
    uint32_t total = 0;
};

class TelemetryBlockCodec
{
public:
    // Fields with no samples are left out. Samples must be in ascending time per field.
    static std::string encode(const BlockFields &fields);

    // nullopt (and why in *error) when the block is damaged: bad CRC, cut short, an impossible count.
    static std::optional<BlockSummary> summarize(std::string_view block, std::string *error = nullptr);
    // Decodes every field, or only `only` when given.
    static std::optional<BlockFields> decode(std::string_view block, std::string *error = nullptr,
                                             std::optional<vehicle::TelemetryField> only = std::nullopt);
};

// CRC-32 (IEEE 802.3, as zlib computes it).
uint32_t crc32(std::string_view data);

} // namespace sortie::flightlog
