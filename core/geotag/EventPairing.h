#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace sortie::geotag {

// Photos paired with the photo events of a flight (the shutter as the vehicle reported it), by
// the pattern of their times: the camera's clock is off the vehicle's by an unknown offset, some
// events have no photo (a card full, a frame lost) and some photos no event (test shots on the
// ground, another flight's). Found as the offset under which most photos fall within a tolerance
// of an event, each photo and event used once, then refined to the median of the pairs' differences.
struct EventPairing
{
    int64_t offsetMs = 0;     // add to a camera time to get the vehicle's: the median over the pairs
    int64_t toleranceMs = 0;  // how far apart a pair may be after the offset
    std::vector<std::pair<size_t, size_t>> pairs; // (photo, event) indices, both in time order
    std::vector<size_t> unpairedPhotos;
    std::vector<size_t> unpairedEvents;
};

struct EventPairingOptions
{
    // 0: 40 % of the events' median interval, at most 1 s (a camera that stamps whole seconds is
    // still within it for series a second apart or more).
    int64_t toleranceMs = 0;
    // Where an offset is looked for: each of this many events spread over the flight tried against
    // the photos around its place in the sequence (as many either side as the counts differ, and 20).
    int sampledEvents = 64;
};

// `cameraTimes` and `eventTimes` each in time order (ms). nullopt when either is empty or fewer than
// two photos (or a third of the smaller count) pair under any offset: no pattern to trust. The
// pattern is all it goes by: photos of another flight with the same rhythm pair as well, so the
// folder should hold this flight's (the report names every photo and event left over).
std::optional<EventPairing> pairWithEvents(const std::vector<int64_t> &cameraTimes, const std::vector<int64_t> &eventTimes,
                                           const EventPairingOptions &options = {});

} // namespace sortie::geotag
