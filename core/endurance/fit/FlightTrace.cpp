#include "FlightTrace.h"

#include "FlightLog.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace sortie::endurance::fit {
namespace {

using vehicle::TelemetryField;
using vehicle::TelemetrySample;

constexpr int64_t kFreshMs = 2000;

// The latest value of a series at or before each of a rising sequence of times (a cursor that only
// moves forward), or NaN when there is none within `maxAgeMs`.
class HeldValue
{
public:
    HeldValue(std::vector<TelemetrySample> series, int64_t maxAgeMs)
        : m_series(inTimeOrder(std::move(series)))
        , m_maxAgeMs(maxAgeMs)
    {
    }
    // Blocks are in the order of their first sample; a vehicle whose state changes are stamped by
    // another clock than its telemetry (a sped-up sim's) can interleave them.
    static std::vector<TelemetrySample> inTimeOrder(std::vector<TelemetrySample> series)
    {
        std::stable_sort(series.begin(), series.end(), [](const TelemetrySample &a, const TelemetrySample &b) { return a.time < b.time; });
        return series;
    }
    double at(int64_t time)
    {
        while (m_next < m_series.size() && m_series[m_next].time <= time)
            ++m_next;
        if (m_next == 0)
            return kMissing;
        const TelemetrySample &s = m_series[m_next - 1];
        return time - s.time <= m_maxAgeMs ? s.value : kMissing;
    }

private:
    std::vector<TelemetrySample> m_series;
    int64_t m_maxAgeMs;
    size_t m_next = 0;
};

bool anyFinite(const std::vector<TelemetrySample> &series)
{
    for (const TelemetrySample &s : series)
        if (std::isfinite(s.value))
            return true;
    return false;
}

} // namespace

FlightTrace traceOf(const flightlog::FlightLog &log, int vehicle)
{
    FlightTrace trace;
    trace.name = QStringLiteral("%1: %2").arg(QFileInfo(log.path()).fileName(), log.vehicles()[size_t(vehicle)].name());
    std::vector<TelemetrySample> current = log.series(vehicle, TelemetryField::BatteryCurrent);
    trace.currentReported = anyFinite(current);
    const std::vector<TelemetrySample> grid =
        HeldValue::inTimeOrder(trace.currentReported ? current : log.series(vehicle, TelemetryField::BatteryRemaining));
    HeldValue groundSpeed(log.series(vehicle, TelemetryField::GroundSpeed), kFreshMs);
    HeldValue verticalSpeed(log.series(vehicle, TelemetryField::VerticalSpeed), kFreshMs);
    HeldValue altitude(log.series(vehicle, TelemetryField::AltitudeAgl), kFreshMs);
    HeldValue voltage(log.series(vehicle, TelemetryField::BatteryVoltage), kFreshMs);
    HeldValue remaining(log.series(vehicle, TelemetryField::BatteryRemaining), kFreshMs);
    // Arming is sent when it changes: it holds however old it is.
    HeldValue armed(log.series(vehicle, TelemetryField::Armed), INT64_MAX);
    trace.samples.reserve(grid.size());
    for (const TelemetrySample &g : grid) {
        PowerSample s;
        s.time = g.time;
        s.groundSpeed = groundSpeed.at(g.time);
        s.verticalSpeed = verticalSpeed.at(g.time);
        s.altitudeAgl = altitude.at(g.time);
        s.armed = armed.at(g.time);
        s.remaining = remaining.at(g.time);
        if (trace.currentReported)
            s.powerW = voltage.at(g.time) * g.value; // NaN when either is missing
        trace.samples.push_back(s);
    }
    return trace;
}

void powersFromRemaining(FlightTrace &trace, double capacityWh)
{
    std::vector<PowerSample> &s = trace.samples;
    constexpr int64_t kSide = 1000, kMaxSide = 5000;
    size_t before = 0, after = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        // The nearest sample at least kSide earlier, and the nearest at least kSide later.
        while (before + 1 < i && s[before + 1].time <= s[i].time - kSide)
            ++before;
        if (after < i)
            after = i;
        while (after < s.size() && s[after].time < s[i].time + kSide)
            ++after;
        s[i].powerW = kMissing;
        if (after >= s.size() || before >= i || s[i].time - s[before].time < kSide)
            continue;
        const int64_t span = s[after].time - s[before].time;
        const double drop = s[before].remaining - s[after].remaining;
        if (span > 2 * kMaxSide || !std::isfinite(drop))
            continue;
        s[i].powerW = std::max(0.0, drop) * capacityWh * 3600.0 / (double(span) / 1000.0);
    }
}

} // namespace sortie::endurance::fit
