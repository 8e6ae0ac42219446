// Fuzzes the SBS-1 reader: any bytes, fed whole and again in chunks the input chooses, must read
// without a crash, a leak or undefined behaviour, give the same messages and errors both ways, never
// buffer more than the line limit, and every message must survive a write-and-read round trip.
#include "SbsReader.h"
#include "SbsWriter.h"

#include <cstdlib>
#include <string>
#include <vector>

using namespace sortie::traffic::sbs;

namespace {

constexpr size_t kLimit = 128; // small, so the fuzzer reaches it

std::vector<SbsReader::Result> read(std::string_view bytes, const std::vector<size_t> &cuts)
{
    SbsReader reader(kLimit);
    std::vector<SbsReader::Result> out;
    size_t at = 0;
    for (size_t cut : cuts) {
        const size_t end = std::min(bytes.size(), at + cut);
        reader.push(bytes.substr(at, end - at));
        if (reader.buffered() > kLimit)
            std::abort();
        at = end;
    }
    reader.push(bytes.substr(at));
    if (reader.buffered() > kLimit)
        std::abort();
    while (auto r = reader.next())
        out.push_back(std::move(*r));
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string_view bytes(reinterpret_cast<const char *>(data), size);
    // The first bytes choose the chunk sizes (1..16 each) for the second reading.
    std::vector<size_t> cuts;
    for (size_t i = 0; i < std::min<size_t>(size, 8); ++i)
        cuts.push_back(size_t(data[i] % 16) + 1);
    const auto whole = read(bytes, {});
    const auto chunked = read(bytes, cuts);
    if (whole != chunked)
        std::abort();
    for (const auto &r : whole) {
        const auto *m = std::get_if<SbsMessage>(&r);
        if (!m)
            continue;
        // Written back and read again, a message keeps what the writer keeps exactly (text and flags).
        const std::string line = writeSbsLine(*m, 1795718640123);
        const auto again = SbsReader::readLine(std::string_view(line).substr(0, line.size() - 2), 1);
        if (!again || !std::holds_alternative<SbsMessage>(*again))
            std::abort();
        const auto &back = std::get<SbsMessage>(*again);
        if (back.address != m->address || back.transmission != m->transmission || back.callsign != m->callsign
            || back.squawk != m->squawk || back.onGround != m->onGround || back.latitude.has_value() != m->latitude.has_value())
            std::abort();
    }
    return 0;
}
