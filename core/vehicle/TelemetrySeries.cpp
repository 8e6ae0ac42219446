#include "TelemetrySeries.h"

namespace sortie::vehicle {

size_t TelemetrySeries::lowerBound(int64_t t) const
{
    size_t lo = 0, hi = m_size;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (at(mid).time < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

size_t TelemetrySeries::copyBetween(int64_t from, int64_t to, std::vector<TelemetrySample> &out) const
{
    size_t n = 0;
    for (size_t i = lowerBound(from); i < m_size && at(i).time <= to; ++i, ++n)
        out.push_back(at(i));
    return n;
}

void TelemetrySeries::clear()
{
    m_data.clear(); // keeps the reservation
    m_head = m_size = 0;
}

} // namespace sortie::vehicle
