#include "EventPairing.h"

#include <algorithm>
#include <cstdlib>

namespace sortie::geotag {

namespace {

// Pairs each photo with the nearest unused event within the tolerance, walking both in order.
EventPairing pairUnder(const std::vector<int64_t> &photos, const std::vector<int64_t> &events, int64_t offset, int64_t tolerance)
{
    EventPairing p;
    p.offsetMs = offset;
    p.toleranceMs = tolerance;
    size_t e = 0;
    for (size_t i = 0; i < photos.size(); ++i) {
        const int64_t t = photos[i] + offset;
        while (e < events.size() && events[e] < t - tolerance)
            p.unpairedEvents.push_back(e++);
        // Of the events within reach, the nearest.
        if (e < events.size() && events[e] <= t + tolerance) {
            while (e + 1 < events.size() && std::llabs(events[e + 1] - t) < std::llabs(events[e] - t))
                p.unpairedEvents.push_back(e++);
            p.pairs.emplace_back(i, e++);
        } else {
            p.unpairedPhotos.push_back(i);
        }
    }
    while (e < events.size())
        p.unpairedEvents.push_back(e++);
    return p;
}

int64_t residual(const EventPairing &p, const std::vector<int64_t> &photos, const std::vector<int64_t> &events)
{
    int64_t sum = 0;
    for (const auto &[i, e] : p.pairs)
        sum += std::llabs(events[e] - photos[i] - p.offsetMs);
    return sum;
}

int64_t medianInterval(const std::vector<int64_t> &times)
{
    std::vector<int64_t> gaps;
    for (size_t i = 1; i < times.size(); ++i)
        gaps.push_back(times[i] - times[i - 1]);
    if (gaps.empty())
        return 0;
    std::nth_element(gaps.begin(), gaps.begin() + ptrdiff_t(gaps.size() / 2), gaps.end());
    return gaps[gaps.size() / 2];
}

} // namespace

std::optional<EventPairing> pairWithEvents(const std::vector<int64_t> &photos, const std::vector<int64_t> &events, const EventPairingOptions &options)
{
    if (photos.empty() || events.empty())
        return std::nullopt;
    const int64_t interval = medianInterval(events);
    const int64_t tolerance = options.toleranceMs > 0 ? options.toleranceMs : std::clamp<int64_t>(interval * 2 / 5, 1, 1000);
    // Offsets to try: a sample of events against the photos near their place in the sequence.
    const ptrdiff_t window = std::abs(ptrdiff_t(photos.size()) - ptrdiff_t(events.size())) + 20;
    const size_t samples = std::min<size_t>(events.size(), size_t(std::max(1, options.sampledEvents)));
    std::optional<EventPairing> best;
    int64_t bestResidual = 0;
    for (size_t s = 0; s < samples; ++s) {
        const size_t e = samples == 1 ? 0 : s * (events.size() - 1) / (samples - 1);
        const ptrdiff_t centre = ptrdiff_t(e * photos.size() / events.size());
        for (ptrdiff_t i = std::max<ptrdiff_t>(0, centre - window); i <= std::min<ptrdiff_t>(ptrdiff_t(photos.size()) - 1, centre + window); ++i) {
            EventPairing candidate = pairUnder(photos, events, events[e] - photos[size_t(i)], tolerance);
            if (best && candidate.pairs.size() < best->pairs.size())
                continue;
            const int64_t r = residual(candidate, photos, events);
            if (!best || candidate.pairs.size() > best->pairs.size() || r < bestResidual) {
                bestResidual = r;
                best = std::move(candidate);
            }
        }
    }
    const size_t needed = std::max<size_t>(2, std::min(photos.size(), events.size()) / 3);
    if (!best || best->pairs.size() < needed)
        return std::nullopt;
    // The offset the pairs agree on, and the pairs under it.
    std::vector<int64_t> differences;
    for (const auto &[i, e] : best->pairs)
        differences.push_back(events[e] - photos[i]);
    std::nth_element(differences.begin(), differences.begin() + ptrdiff_t(differences.size() / 2), differences.end());
    EventPairing refined = pairUnder(photos, events, differences[differences.size() / 2], tolerance);
    return refined.pairs.size() >= best->pairs.size() ? refined : *best;
}

} // namespace sortie::geotag
