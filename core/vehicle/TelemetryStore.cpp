#include "TelemetryStore.h"

namespace sortie::vehicle {

TelemetryStore::TelemetryStore(size_t capacityPerField)
    : m_capacity(capacityPerField)
{
    for (auto &s : m_series)
        s = TelemetrySeries(capacityPerField);
}

std::optional<TelemetrySample> TelemetryStore::last(TelemetryField field) const
{
    const TelemetrySeries &s = series(field);
    if (s.empty())
        return std::nullopt;
    return s.newest();
}

size_t TelemetryStore::memoryBytes() const
{
    size_t total = 0;
    for (const auto &s : m_series)
        total += s.memoryBytes();
    return total;
}

void TelemetryStore::clear()
{
    for (auto &s : m_series)
        s.clear();
}

} // namespace sortie::vehicle
