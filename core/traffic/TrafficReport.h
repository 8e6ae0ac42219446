#pragma once

#include <QString>

#include <optional>

namespace sortie::traffic {

namespace sbs {
struct SbsMessage;
}

// Which zero an altitude counts from: an SBS-1 feed gives pressure altitude (Mode C, against the
// standard 1013.25 hPa, as a flight level does), the UgCS server an altitude above mean sea level.
// The two differ by the day's pressure (about 8 m per hPa): never compared as if they were one.
enum class AltitudeReference { Barometric, MeanSeaLevel };
enum class TrafficSource { Receiver, Server }; // an SBS-1 feed, or the UgCS server's list

// What one source said about one aircraft at one time, in SI units and degrees; what it did not
// say is absent. The picture merges reports by address (TrafficPicture::report).
struct TrafficReport
{
    quint32 address = 0;          // the 24-bit address
    bool nonIcaoAddress = false;  // an address that is not an ICAO one (TIS-B, anonymous)
    TrafficSource source = TrafficSource::Receiver;
    std::optional<QString> callsign;
    std::optional<double> latitude;  // degrees
    std::optional<double> longitude; // degrees
    std::optional<double> altitudeM;
    AltitudeReference altitudeReference = AltitudeReference::Barometric;
    std::optional<double> groundSpeedMps;
    std::optional<double> trackDeg;        // degrees clockwise from true north
    std::optional<double> verticalRateMps; // up positive
    std::optional<QString> squawk;
    std::optional<bool> onGround;
    std::optional<qint64> sourceTimeMs; // when the source heard it (the server's updateTime)
};

// An SBS message in SI units (feet, knots and feet per minute converted).
TrafficReport reportFromSbs(const sbs::SbsMessage &message);

constexpr double kMetresPerFoot = 0.3048;
constexpr double kMetresPerSecondPerKnot = 1852.0 / 3600.0;

} // namespace sortie::traffic
