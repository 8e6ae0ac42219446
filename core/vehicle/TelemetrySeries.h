#pragma once

#include "TelemetrySample.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace sortie::vehicle {

// A bounded, time-ordered history of one field: a ring buffer of TelemetrySample that overwrites its
// oldest sample when full. Storage is reserved on the first sample, so unused fields cost nothing.
// A sample older than the newest one is not added (a history for plots must stay ordered); it is
// counted in rejected().
class TelemetrySeries
{
public:
    explicit TelemetrySeries(size_t capacity = 0) : m_capacity(capacity) {}

    // The hot path: one store, no allocation once the buffer exists.
    bool push(int64_t time, double value)
    {
        if (m_size && time < newest().time) {
            ++m_rejected;
            return false;
        }
        if (m_data.size() < m_capacity) {
            // Reserved whole on the first sample but filled as samples come: the pages of a
            // buffer not yet full are never touched, so a new vehicle costs little resident memory.
            if (m_data.capacity() == 0)
                m_data.reserve(m_capacity);
            m_data.push_back({time, value});
        } else {
            if (!m_capacity)
                return false;
            m_data[m_head] = {time, value};
        }
        m_head = m_head + 1 == m_capacity ? 0 : m_head + 1;
        if (m_size < m_capacity)
            ++m_size;
        return true;
    }

    size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    size_t capacity() const { return m_capacity; }
    uint64_t rejected() const { return m_rejected; }
    size_t memoryBytes() const { return m_data.capacity() * sizeof(TelemetrySample); }

    // i = 0 is the oldest sample kept.
    const TelemetrySample &at(size_t i) const { return m_data[(m_head + m_capacity - m_size + i) % m_capacity]; }
    const TelemetrySample &newest() const { return at(m_size - 1); }
    const TelemetrySample &oldest() const { return at(0); }

    // Index of the first sample with time >= t (size() when none).
    size_t lowerBound(int64_t t) const;
    // Appends the samples with from <= time <= to, oldest first; returns how many.
    size_t copyBetween(int64_t from, int64_t to, std::vector<TelemetrySample> &out) const;
    void clear();

private:
    size_t m_capacity;
    std::vector<TelemetrySample> m_data;
    size_t m_head = 0; // where the next sample goes
    size_t m_size = 0;
    uint64_t m_rejected = 0;
};

} // namespace sortie::vehicle
