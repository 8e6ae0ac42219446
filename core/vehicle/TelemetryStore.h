#pragma once

#include "TelemetrySeries.h"

#include <array>
#include <optional>

namespace sortie::vehicle {

// One vehicle's telemetry history: a TelemetrySeries per field. Plain C++ (no Qt, no signals):
// the Vehicle feeds it and views read it when they redraw.
//
// Memory: capacityPerField samples of 16 bytes per field that has received anything. The default,
// 30 minutes at 10 Hz (18,000 samples), is 281 KiB per field; all 26 fields take 7.1 MiB.
class TelemetryStore
{
public:
    static constexpr size_t kDefaultCapacity = 30 * 60 * 10;

    explicit TelemetryStore(size_t capacityPerField = kDefaultCapacity);

    void ingest(TelemetryField field, int64_t time, double value) { m_series[size_t(field)].push(time, value); }
    void ingest(const TelemetryBatch &batch)
    {
        for (const TelemetryUpdate &u : batch)
            m_series[size_t(u.field)].push(u.time, u.value);
    }

    const TelemetrySeries &series(TelemetryField field) const { return m_series[size_t(field)]; }
    std::optional<TelemetrySample> last(TelemetryField field) const;
    size_t copyBetween(TelemetryField field, int64_t from, int64_t to, std::vector<TelemetrySample> &out) const
    {
        return series(field).copyBetween(from, to, out);
    }

    size_t capacityPerField() const { return m_capacity; }
    size_t memoryBytes() const; // allocated now
    static size_t memoryBytesPerField(size_t capacity) { return capacity * sizeof(TelemetrySample); }
    void clear();

private:
    size_t m_capacity;
    std::array<TelemetrySeries, kTelemetryFieldCount> m_series;
};

} // namespace sortie::vehicle
