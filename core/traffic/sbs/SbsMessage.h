#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sortie::traffic::sbs {

// One "MSG" line of the SBS-1 (BaseStation) text feed, as dump1090 and readsb serve it on TCP port
// 30003: 22 comma-separated fields. Only what the line carries is set; an empty field stays absent
// (never 0). Units are the feed's own (feet, knots, feet per minute, degrees); converting them is
// the caller's job (TrafficReport). Fields 3, 4 and 6 to 10 (session, aircraft and flight ids, the
// receiver's dates and times) are not read: the receiving side stamps what it hears with its own clock.
struct SbsMessage
{
    uint64_t line = 0;          // 1-based line number in the stream
    int transmission = 0;       // field 2: 1..8 (identification, surface/airborne position, velocity, ...)
    uint32_t address = 0;       // field 5: the 24-bit address
    bool nonIcaoAddress = false; // field 5 began with '~' (TIS-B or a non-ICAO address)
    std::optional<std::string> callsign; // field 11, trailing spaces removed
    std::optional<double> altitudeFt;    // field 12: pressure altitude (1013.25 hPa), feet
    std::optional<double> groundSpeedKt; // field 13
    std::optional<double> trackDeg;      // field 14: degrees clockwise from true north
    std::optional<double> latitude;      // field 15, degrees
    std::optional<double> longitude;     // field 16, degrees
    std::optional<double> verticalRateFpm; // field 17, feet per minute, up positive
    std::optional<std::string> squawk;   // field 18: four octal digits
    std::optional<bool> alert;           // field 19: squawk changed
    std::optional<bool> emergency;       // field 20
    std::optional<bool> ident;           // field 21: SPI
    std::optional<bool> onGround;        // field 22

    bool operator==(const SbsMessage &) const = default;
};

// A line the reader dropped, and why ("field 15 (latitude): '91.2' is out of -90..90").
struct SbsError
{
    uint64_t line = 0;
    std::string reason;

    bool operator==(const SbsError &) const = default;
};

} // namespace sortie::traffic::sbs
