// Fuzzes the VCI parser: any bytes, fed whole and again in chunks the input chooses, must parse
// without a crash, a leak or undefined behaviour, give the same messages and errors both ways, keep
// at most one line buffered, and every message must survive a write-and-parse round trip.
#include "VciParser.h"
#include "VciWriter.h"

#include <cstdlib>
#include <string>
#include <vector>

using namespace sortie::vci;

namespace {

VciLimits smallLimits()
{
    VciLimits l; // small, so the fuzzer reaches every limit
    l.maxLineLength = 256;
    l.maxHeaders = 8;
    l.maxBodySize = 4096;
    l.maxJsonDepth = 32;
    l.maxNumberLength = 40;
    return l;
}

std::string key(const VciParser::Result &r)
{
    if (const auto *m = std::get_if<VciMessage>(&r)) {
        std::string k = "M" + std::to_string(m->offset) + ":" + std::to_string(m->size) + ":" + m->uri + ":" + std::to_string(m->status);
        if (m->jsonBody)
            k += m->body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        return k + m->rawBody;
    }
    const auto &e = std::get<VciParseError>(r);
    return "E" + std::to_string(e.offset) + ":" + e.message;
}

std::vector<std::string> parse(std::string_view bytes, const std::vector<size_t> &cuts, size_t *maxBuffered)
{
    VciParser parser(smallLimits());
    std::vector<std::string> out;
    uint64_t lastOffset = 0;
    size_t from = 0;
    auto drain = [&] {
        while (auto r = parser.next()) {
            const uint64_t offset = std::visit([](const auto &x) { return x.offset; }, *r);
            if (offset < lastOffset)
                std::abort(); // results come in stream order
            lastOffset = offset;
            if (const auto *m = std::get_if<VciMessage>(&*r); m && (m->jsonBody || !m->hasBody)) {
                // Written again, it reads back the same.
                const VciWriter writer(m->size % 2 ? VciFraming::JsonOnly : VciFraming::ContentLength);
                const std::string again = m->isRequest()
                    ? writer.request(m->verb, m->uri, m->jsonBody ? &m->body : nullptr)
                    : writer.response(m->status, m->jsonBody ? &m->body : nullptr);
                VciParser second;
                second.feed(again);
                auto back = second.next();
                if (!back || !std::holds_alternative<VciMessage>(*back))
                    std::abort();
                const auto &b = std::get<VciMessage>(*back);
                if (b.uri != m->uri || b.status != m->status || b.body != m->body)
                    std::abort();
            }
            out.push_back(key(*r));
        }
        if (parser.buffered() >= smallLimits().maxLineLength)
            std::abort(); // never more than a line's worth waits
        *maxBuffered = std::max(*maxBuffered, parser.buffered());
    };
    for (size_t cut : cuts) {
        parser.feed(bytes.substr(from, cut - from));
        drain();
        from = cut;
    }
    parser.feed(bytes.substr(from));
    drain();
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    const std::string_view bytes(reinterpret_cast<const char *>(data) + 2, size - 2);
    const size_t step = 1 + data[0] % 64; // chunk sizes chosen by the input
    const size_t first = bytes.empty() ? 0 : data[1] % bytes.size();
    std::vector<size_t> cuts;
    for (size_t c = first; c < bytes.size(); c += step) {
        if (c > 0)
            cuts.push_back(c);
    }
    size_t maxBuffered = 0;
    if (parse(bytes, {}, &maxBuffered) != parse(bytes, cuts, &maxBuffered))
        std::abort(); // chunking must not change anything
    return 0;
}
