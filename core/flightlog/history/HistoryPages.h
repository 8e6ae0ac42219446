#pragma once

#include "FlightLog.h"
#include "TelemetrySample.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace com::ugcs::ucs::proto {
class GetTelemetryResponse;
class Vehicle;
}

namespace sortie::flightlog {

// The server's telemetry history between two times as it comes in, page after page, and the log it
// makes: what ServerHistory does with each answer, without the network, so it is tested and fuzzed
// on pages a server could send (fuzz_server_history). Trusts nothing in a page: the next time must
// move forward inside the range, a value out of the range is not kept, and the values are sorted
// by time before they are cut into one-second blocks.
class HistoryPages
{
public:
    HistoryPages(int64_t fromMs, int64_t toMs);

    // Takes a page's values; the time to ask the next page from, or nullopt when the history is
    // complete (the server says nothing further, or a time that does not move forward).
    std::optional<int64_t> add(const com::ugcs::ucs::proto::GetTelemetryResponse &page, int64_t receivedAtMs);
    double progress() const { return m_progress; }  // 0..1 of the range
    size_t valueCount() const { return m_updates.size(); }
    size_t outOfRange() const { return m_outOfRange; }  // values the server sent outside the range

    // The log of `vehicle`: one block per second of its time, as a recording writes them.
    std::unique_ptr<FlightLog> takeLog(const com::ugcs::ucs::proto::Vehicle &vehicle);

private:
    int64_t m_from, m_to, m_next;
    vehicle::TelemetryBatch m_updates;
    size_t m_outOfRange = 0;
    double m_progress = 0;
};

} // namespace sortie::flightlog
