// Telemetry block codec (the .sortielog's blocks). The input is a block without its CRC-32: the
// target closes it with the right one, so the fuzzer reaches the decoder rather than the CRC check
// (the bytes as given, with whatever their last four bytes say, are decoded too). A block either
// decodes or is refused with a reason; when both decode and summarize accept it they agree on the
// time span and the count of every field.
#include "TelemetryBlockCodec.h"

#include <cstdlib>
#include <cstring>

using namespace sortie::flightlog;

namespace {
void check(std::string_view block)
{
    std::string why;
    const auto summary = TelemetryBlockCodec::summarize(block, &why);
    if (!summary && why.empty())
        std::abort();
    why.clear();
    const auto fields = TelemetryBlockCodec::decode(block, &why);
    if (!fields) {
        if (why.empty())
            std::abort();
        return;
    }
    if (!summary)
        std::abort();  // decode read what summarize refused
    uint32_t total = 0;
    for (const FieldSamples &f : *fields) {
        if (summary->counts[size_t(f.field)] != f.samples.size())
            std::abort();
        total += uint32_t(f.samples.size());
    }
    if (total != summary->total)
        std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string_view raw(reinterpret_cast<const char *>(data), size);
    check(raw);
    std::string closed(raw);
    const uint32_t crc = crc32(closed);
    closed.append(reinterpret_cast<const char *>(&crc), 4);
    check(closed);
    return 0;
}
