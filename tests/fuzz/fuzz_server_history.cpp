// The server's telemetry history (HistoryPages.h): pages a server could send, one after another
// (each a 16-bit big-endian length and a GetTelemetryResponse), become a log or nothing more. The
// next page is asked only from a later time inside the range; every value the log holds is inside
// the range; every block it holds decodes; no value is lost between the pages and the log.
#include "HistoryPages.h"
#include "Messages.pb.h"
#include "TelemetryBlockCodec.h"

#include <cstdio>
#include <cstdlib>

namespace {
[[noreturn]] void fail(const char *why)
{
    std::fprintf(stderr, "fuzz_server_history: %s\n", why);
    std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::flightlog;
    namespace pb = com::ugcs::ucs::proto;
    constexpr int64_t from = 1764670000000, to = from + 3'600'000, received = to + 60'000;
    HistoryPages pages(from, to);
    int64_t asked = from;
    size_t at = 0;
    bool more = true;
    while (more && at + 2 <= size) {
        const size_t length = size_t(data[at]) << 8 | data[at + 1];
        at += 2;
        const size_t take = std::min(length, size - at);
        pb::GetTelemetryResponse page;
        if (!page.ParseFromArray(data + at, int(take)))
            return 0;
        at += take;
        const auto next = pages.add(page, received);
        if (pages.progress() < 0 || pages.progress() > 1)
            fail("progress outside 0..1");
        more = next.has_value();
        if (next) {
            if (*next <= asked || *next > to)
                fail("the next page asked from a time that does not move forward inside the range");
            asked = *next;
        }
    }
    const size_t values = pages.valueCount();
    pb::Vehicle vehicle;
    vehicle.set_id(7);
    vehicle.set_name("EMU-107");
    const auto log = pages.takeLog(vehicle);
    if (!log || log->vehicles().size() != 1)
        fail("no log of the one vehicle");
    const FlightLog::Vehicle &v = log->vehicles().front();
    if (v.sampleCount() != values)
        fail("values lost between the pages and the log");
    for (const FlightLog::Block &b : v.blocks) {
        std::string why;
        const auto fields = TelemetryBlockCodec::decode(b.data, &why);
        if (!fields)
            fail("a block of the log does not decode");
        for (const FieldSamples &f : *fields)
            for (const auto &s : f.samples)
                if (s.time < from || s.time > to)
                    fail("a value outside the range asked for");
    }
    return 0;
}
