// Decodes 1,000,000 TelemetryEvent notifications (~250 bytes each: a vehicle and six telemetry values)
// fed to HciFrameDecoder in 64 KiB chunks, and parses the same payloads with bare ParseFromArray.
// Prints frames/s and MB/s for each; the best of several runs is reported.
//   bench_hcidecode [frames] [runs] [decoder|generic|reused|fresh|corpus]   (one mode only: for callgrind)
#include "HciFrameCodec.h"
#include "Messages.pb.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace pb = com::ugcs::ucs::proto;
using namespace sortie::hci;
using Clock = std::chrono::steady_clock;

// CPU time of this thread: on a shared machine it leaves out the time other processes ran.
double cpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) / 1e9;
}

namespace {

constexpr size_t kChunk = 64 * 1024;
constexpr double kSdkFramesPerSecond = 850000; // the official Java SDK's decoder on this machine class

void addTelemetry(pb::TelemetryEvent *event, const char *code, pb::Semantic semantic, int64_t time)
{
    auto *t = event->add_telemetry();
    t->set_time(time);
    auto *field = t->mutable_telemetryfield();
    field->set_code(code);
    field->set_semantic(semantic);
    field->set_subsystem(pb::S_FLIGHT_CONTROLLER);
    field->set_subsystemid(0);
    (void)t->mutable_value();
}

// One notification as UgCS sends it: vehicle reference, then six values with their field codes.
pb::Notification makeNotification(int i)
{
    pb::Notification n;
    n.set_subscriptionid(100);
    auto *event = n.mutable_event()->mutable_telemetryevent();
    auto *vehicle = event->mutable_vehicle();
    vehicle->set_id(1 + i % 3);
    vehicle->set_name("EMU-10" + std::to_string(1 + i % 3));
    vehicle->set_tailnumber(vehicle->name());
    const int64_t time = 1750147560000 + int64_t(i) * 100;
    addTelemetry(event, "latitude", pb::S_LATITUDE, time);
    event->mutable_telemetry(0)->mutable_value()->set_doublevalue(0.99443 + i * 1e-9);
    addTelemetry(event, "longitude", pb::S_LONGITUDE, time);
    event->mutable_telemetry(1)->mutable_value()->set_doublevalue(0.42024 + i * 1e-9);
    addTelemetry(event, "altitude_amsl", pb::S_ALTITUDE_AMSL, time);
    event->mutable_telemetry(2)->mutable_value()->set_floatvalue(112.4f + float(i % 100) * 0.1f);
    addTelemetry(event, "ground_speed", pb::S_GROUND_SPEED, time);
    event->mutable_telemetry(3)->mutable_value()->set_floatvalue(5.12f);
    addTelemetry(event, "heading", pb::S_HEADING, time);
    event->mutable_telemetry(4)->mutable_value()->set_floatvalue(1.57f);
    addTelemetry(event, "battery_voltage", pb::S_VOLTAGE, time);
    event->mutable_telemetry(5)->mutable_value()->set_floatvalue(15.86f);
    return n;
}

struct Corpus
{
    std::string stream;                           // every frame back to back
    std::vector<std::pair<size_t, size_t>> payloads; // offset and length of each payload in `stream`
};

Corpus makeCorpus(size_t frames)
{
    Corpus c;
    c.stream.reserve(frames * 280);
    c.payloads.reserve(frames);
    for (size_t i = 0; i < frames; ++i) {
        const size_t start = c.stream.size();
        appendHciFrame(c.stream, -1, makeNotification(int(i)));
        c.payloads.emplace_back(start + kHciHeaderSize, c.stream.size() - start - kHciHeaderSize);
    }
    return c;
}

struct Result
{
    double seconds = 1e9; // wall
    double cpu = 1e9;
    size_t frames = 0;
    uint64_t check = 0; // keeps the compiler from discarding the work
};

uint64_t touch(const pb::Notification &n)
{
    const auto &e = n.event().telemetryevent();
    return uint64_t(e.vehicle().id()) + uint64_t(e.telemetry_size());
}

Result runDecoder(const Corpus &c, bool fastPath)
{
    Result r;
    HciFrameDecoder decoder;
    decoder.setFastPath(fastPath);
    const auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    for (size_t at = 0; at < c.stream.size(); at += kChunk) {
        decoder.feed(std::string_view(c.stream).substr(at, kChunk));
        while (auto result = decoder.next()) {
            auto *frame = std::get_if<HciFrame>(&*result);
            if (!frame)
                std::abort();
            r.check += touch(static_cast<const pb::Notification &>(*frame->message));
            ++r.frames;
            decoder.recycle(std::move(frame->message));
        }
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.cpu = cpuSeconds() - cpuStart;
    return r;
}

Result runDecoderFast(const Corpus &c)
{
    return runDecoder(c, true);
}

Result runDecoderGeneric(const Corpus &c)
{
    return runDecoder(c, false);
}

Result runBareReused(const Corpus &c)
{
    Result r;
    pb::Notification n;
    const auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    for (const auto &[offset, length] : c.payloads) {
        if (!n.ParseFromArray(c.stream.data() + offset, int(length)))
            std::abort();
        r.check += touch(n);
        ++r.frames;
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.cpu = cpuSeconds() - cpuStart;
    return r;
}

Result runBareFresh(const Corpus &c)
{
    Result r;
    const auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    for (const auto &[offset, length] : c.payloads) {
        pb::Notification n;
        if (!n.ParseFromArray(c.stream.data() + offset, int(length)))
            std::abort();
        r.check += touch(n);
        ++r.frames;
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.cpu = cpuSeconds() - cpuStart;
    return r;
}

template<class F>
Result best(F run, const Corpus &c, int runs)
{
    Result b;
    for (int i = 0; i < runs; ++i) {
        const Result r = run(c);
        if (r.cpu < b.cpu)
            b = r;
    }
    return b;
}

void print(const char *name, const Result &r, size_t bytes)
{
    std::printf("%-36s %10.0f frames/s %8.1f MB/s   (%zu frames: %.3f s CPU, %.3f s wall)\n", name, r.frames / r.cpu,
                bytes / r.cpu / 1e6, r.frames, r.cpu, r.seconds);
}

} // namespace

int main(int argc, char **argv)
{
    const size_t frames = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
    const Corpus corpus = makeCorpus(frames);
    std::printf("%zu TelemetryEvent notifications, %.1f bytes per frame on average (16-byte header included), "
                "fed in %zu-byte chunks; best of %d runs by CPU time\n",
                frames, double(corpus.stream.size()) / frames, kChunk, runs);

    if (argc > 3) {
        const std::string mode = argv[3];
        if (mode == "corpus")
            return 0;
        const Result r = mode == "decoder" ? runDecoderFast(corpus)
            : mode == "generic"            ? runDecoderGeneric(corpus)
            : mode == "reused"             ? runBareReused(corpus)
                                           : runBareFresh(corpus);
        print(mode.c_str(), r, corpus.stream.size());
        return 0;
    }
    const Result decoder = best(runDecoderFast, corpus, runs);
    const Result generic = best(runDecoderGeneric, corpus, runs);
    const Result reused = best(runBareReused, corpus, runs);
    const Result fresh = best(runBareFresh, corpus, runs);
    if (decoder.check != reused.check || reused.check != fresh.check || generic.check != reused.check)
        return 2;
    print("HciFrameDecoder (64 KiB chunks)", decoder, corpus.stream.size());
    print("HciFrameDecoder, general parser only", generic, corpus.stream.size());
    print("bare ParseFromArray, reused message", reused, corpus.stream.size());
    print("bare ParseFromArray, new message", fresh, corpus.stream.size());

    const double fps = decoder.frames / decoder.cpu;
    const double bare = reused.frames / reused.cpu;
    std::printf("decoder / SDK (%.0f frames/s): %.2fx (target >= 3x)\n", kSdkFramesPerSecond, fps / kSdkFramesPerSecond);
    std::printf("decoder / bare ParseFromArray (reused): %.1f%% (target >= 85%%)\n", 100.0 * fps / bare);
    const bool ok = fps >= 3 * kSdkFramesPerSecond && fps >= 0.85 * bare;
    std::printf("%s\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
