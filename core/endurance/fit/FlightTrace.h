#pragma once

#include <QString>

#include <cstdint>
#include <limits>
#include <vector>

namespace sortie::flightlog {
class FlightLog;
}

namespace sortie::endurance::fit {

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// One moment of a recorded flight as the fit sees it: what the vehicle was doing and what it drew.
// A value the log did not have then is NaN, never 0.
struct PowerSample
{
    int64_t time = 0;               // ms since the epoch
    double groundSpeed = kMissing;  // m/s
    double verticalSpeed = kMissing;// m/s, up positive
    double altitudeAgl = kMissing;  // m
    double armed = kMissing;        // 1 or 0
    double remaining = kMissing;    // 0..1
    double powerW = kMissing;       // electrical power leaving the battery
};

// One vehicle's telemetry of one log, sampled at its battery reports.
struct FlightTrace
{
    QString name;                   // "log.sortielog: EMU-101"
    bool currentReported = false;   // powers are voltage × current; else they come from the remaining fraction
    std::vector<PowerSample> samples; // time order
};

// The trace of a log's vehicle: one sample per current report (per remaining report when the vehicle
// reports no current), with the latest speeds, height, arming, voltage and remaining at that time
// (each no older than 2 s, else missing). Powers are voltage × current where current is reported.
FlightTrace traceOf(const flightlog::FlightLog &log, int vehicle);

// Powers of a trace without current: the drop of the remaining fraction across about two seconds
// around each sample (the nearest reports at least a second away on each side) times the capacity.
void powersFromRemaining(FlightTrace &trace, double capacityWh);

} // namespace sortie::endurance::fit
