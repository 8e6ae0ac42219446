// Parser throughput: 1,000,000 NOTIFY messages with a ~150-byte JSON position body, fed in 64 KiB
// chunks and parsed to JSON values, once with Content-Length framing and once framed by the JSON.
// Prints messages/s and MB/s (docs/performance.md, "VCI").
#include "VciParser.h"
#include "VciWriter.h"

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace sortie::vci;

namespace {

constexpr size_t kChunk = 64 * 1024;
constexpr size_t kBlockMessages = 10000;

// kBlockMessages distinct messages; the stream is this block repeated.
std::string makeBlock(VciFraming framing, size_t *bodyBytes)
{
    VciWriter writer(framing);
    std::string block;
    *bodyBytes = 0;
    for (size_t i = 0; i < kBlockMessages; ++i) {
        // The shape the simulated vehicles send (docs/vci-profile.md): radians at full precision.
        const double t = double(i) * 0.1, rad = 3.14159265358979323846 / 180;
        const nlohmann::json body = {
            {"latitude", (56.9796 + t * 1e-6) * rad}, {"longitude", (24.0736 - t * 1e-6) * rad},
            {"altitudeAmsl", 512.5 + t * 0.01}, {"altitudeAgl", 100.25 + t * 0.01}, {"time", 1700000000000 + int64_t(i) * 100},
        };
        *bodyBytes += body.dump().size();
        writer.appendRequest(block, VciVerb::Notify, "/telemetry/position", &body);
    }
    *bodyBytes /= kBlockMessages;
    return block;
}

void run(const char *name, VciFraming framing, size_t messages)
{
    size_t bodyBytes = 0;
    const std::string block = makeBlock(framing, &bodyBytes);
    const size_t repeats = messages / kBlockMessages;
    VciParser parser;
    size_t parsed = 0, errors = 0;
    double checksum = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (size_t r = 0; r < repeats; ++r) {
        for (size_t off = 0; off < block.size(); off += kChunk) {
            parser.feed(std::string_view(block).substr(off, kChunk));
            while (auto result = parser.next()) {
                if (auto *m = std::get_if<VciMessage>(&*result)) {
                    ++parsed;
                    checksum += m->body["latitude"].get<double>();
                } else {
                    ++errors;
                }
            }
        }
    }
    // CPU time, not wall time: the figure is for one core, whatever else the machine is doing.
    const double seconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double bytes = double(block.size()) * double(repeats);
    std::printf("%-16s %zu messages (%.0f bytes each, body %zu bytes) in %.3f s CPU (%.3f s wall): %.0f messages/s, %.1f MB/s%s\n", name, parsed,
                bytes / double(parsed ? parsed : 1), bodyBytes, seconds, wall, double(parsed) / seconds, bytes / seconds / 1e6,
                errors || checksum == 0 ? "  ERRORS" : "");
}

} // namespace

int main(int argc, char **argv)
{
    const size_t messages = argc > 1 ? size_t(std::strtoull(argv[1], nullptr, 10)) : 1000000;
    std::printf("VciParser, %zu NOTIFY /telemetry/position messages in %zu-byte chunks, one core\n", messages, kChunk);
    run("Content-Length", VciFraming::ContentLength, messages);
    run("JSON-framed", VciFraming::JsonOnly, messages);
    return 0;
}
