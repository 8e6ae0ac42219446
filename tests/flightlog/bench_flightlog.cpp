// Flight-log figures for docs/performance.md:
// 1. recording: 200,000 values/s (770 vehicles x 26 fields x 10 Hz, fed as fast as possible, flushed
//    every half second of data as the live recorder does), CPU per second of data on the gathering
//    thread and on the writer thread, and bytes per value on disk;
// 2. replay: a log of 1 hour of 20 vehicles at 10 Hz (26 fields): FlightLog::open, ReplayController::open
//    (what the operator waits for), the whole-span plot histories decoded on the worker thread after it,
//    scrubbing at random while that worker runs and after, playing at 50x.
#include "FlightLog.h"
#include "FlightLogWriter.h"
#include "FlightRecorder.h"
#include "ReplayController.h"
#include "Vehicle.h"
#include "BenchClock.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <time.h>

using namespace sortie;
using vehicle::TelemetryField;

namespace {

qint64 threadCpuNs()
{
    return qint64(test::threadCpuMs() * 1e6);
}

// Everything an HCI vehicle reports, as it flies a circle: 26 fields (written in radians, as HCI sends
// them; the link gives angles in degrees).
void telemetry(int vehicle, int64_t t, vehicle::TelemetryBatch &out)
{
    out.clear();
    const double s = double(t % 86400000) / 1000.0;
    const double phase = s / 60.0 + vehicle;
    const double lat = (56.95 + 0.002 * std::sin(phase) + vehicle * 1e-3) * M_PI / 180, lon = (24.1 + 0.003 * std::cos(phase)) * M_PI / 180;
    const double v[] = {lat, lon, 60 + 5 * std::sin(s / 30), 50 + 5 * std::sin(s / 30), 0.05 * std::sin(s), 0.03 * std::cos(s / 2),
                        std::fmod(phase + M_PI / 2, 2 * M_PI), std::fmod(phase + M_PI / 2, 2 * M_PI), 8 + 0.2 * std::sin(s), 8.4,
                        0.1 * std::cos(s / 30), 16.4 - s * 1e-4, 12 + std::sin(s / 5), 0.9 - s * 1e-5, 3, 15, 0.7,
                        0.99, 0.42, 10, 1, 4, 1, 2, 1, 5, 0, 0};
    static_assert(sizeof(v) / sizeof(v[0]) == vehicle::kTelemetryFieldCount, "one value per telemetry field");
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f)
        out.push_back({TelemetryField(f), vehicle::isAngle(TelemetryField(f)) ? vehicle::degreesFromRadians(v[f]) : v[f], t}); // as a link delivers it
}

class FeedLink : public vehicle::VehicleLink
{
public:
    FeedLink(int n) { m_identity = {QString::number(n), QStringLiteral("EMU-%1").arg(100 + n), QStringLiteral("multicopter"), {}, QStringLiteral("HCI")}; }
    void send(const vehicle::TelemetryBatch &b) { emit telemetryReceived(b); }
    QString protocol() const override { return QStringLiteral("HCI"); }
    vehicle::VehicleIdentity identity() const override { return m_identity; }
    State state() const override { return State::Connected; }
    Capabilities capabilities() const override { return {}; }
    void start() override {}
    void stop() override {}
    void arm(bool, Done) override {}
    void setMode(vehicle::FlightMode, Done) override {}
    void takeoff(double, Done) override {}
    void land(Done) override {}
    void returnHome(Done) override {}
    void goTo(double, double, double, double, Done) override {}
    void prepareMission(const mission::Route &, PrepareDone) override {}
    void uploadMission(const vehicle::PreparedMission &, UploadObserver, Done) override {}
    void downloadMission(MissionDone) override {}
    void readParameters(ParametersDone) override {}
    void setParameter(const QString &, double, Done) override {}

private:
    vehicle::VehicleIdentity m_identity;
};

void benchRecording(const QString &folder)
{
    constexpr int kVehicles = 770, kSeconds = 10, kHz = 10;
    const int64_t t0 = 1'780'000'000'000;
    std::vector<std::unique_ptr<FeedLink>> links;
    std::vector<std::unique_ptr<vehicle::Vehicle>> vehicles;
    for (int i = 0; i < kVehicles; ++i) {
        links.push_back(std::make_unique<FeedLink>(i));
        vehicles.push_back(std::make_unique<vehicle::Vehicle>(nullptr));
    }
    vehicle::TelemetryBatch batch;
    // The same loop without a recorder: what generating the telemetry itself costs.
    qint64 baseline = threadCpuNs();
    for (int tick = 0; tick < kSeconds * kHz; ++tick)
        for (int v = 0; v < kVehicles; ++v) {
            telemetry(v, t0 + tick * 100 + v % 7, batch);
            links[size_t(v)]->send(batch);
        }
    baseline = threadCpuNs() - baseline;

    const QString path = QDir(folder).filePath(QStringLiteral("rate.sortielog"));
    flightlog::FlightRecorder recorder({path, {}, 500});
    recorder.start();
    for (int v = 0; v < kVehicles; ++v) {
        // A Vehicle fed by the link, as in the client; the recorder listens to the same link.
        auto *vehicle = new vehicle::Vehicle(links[size_t(v)].get(), links[size_t(v)].get());
        recorder.addVehicle(vehicle);
    }
    QElapsedTimer wall;
    wall.start();
    qint64 gather = threadCpuNs();
    quint64 values = 0;
    for (int tick = 0; tick < kSeconds * kHz; ++tick) {
        for (int v = 0; v < kVehicles; ++v) {
            telemetry(v, t0 + tick * 100 + v % 7, batch);
            links[size_t(v)]->send(batch);
            values += batch.size();
        }
        if (tick % (kHz / 2) == kHz / 2 - 1)
            recorder.flush(); // every half second of data, as the timer does live
    }
    gather = threadCpuNs() - gather;
    recorder.stop(); // waits for the writer
    const double wallS = double(wall.nsecsElapsed()) / 1e9;
    // The Vehicle ingest is the live client's cost either way; measure it apart to leave the recorder's own.
    qint64 ingest = threadCpuNs();
    for (int tick = 0; tick < kSeconds * kHz; ++tick)
        for (int v = 0; v < kVehicles; ++v) {
            telemetry(v, t0 + (kSeconds * kHz + tick) * 100, batch);
            vehicles[size_t(v)]->ingest(batch);
        }
    ingest = threadCpuNs() - ingest;
    std::printf("recording: %llu values (%d vehicles x 26 fields x %d Hz x %d s of data) in %.2f s wall\n",
                (unsigned long long)values, kVehicles, kHz, kSeconds, wallS);
    const QFileInfo file(path);
    std::printf("recording: on disk %.2f bytes per value (%lld bytes)\n", double(file.size()) / double(values), file.size());
    // gather thread: (gather - baseline - vehicle ingest) is the recorder's part
    const double recorderGather = double(gather - baseline - ingest) / 1e9;
    std::printf("recording: gathering thread %.3f s CPU for %d s of data = %.1f %% of one core at %.0f values/s\n", recorderGather, kSeconds,
                100.0 * recorderGather / kSeconds, double(values) / kSeconds);
    const auto stats = recorder.stats();
    std::printf("recording: writer thread %.3f s CPU for %d s of data = %.1f %% of one core (encode + SQLite, %llu blocks)\n",
                double(stats.cpuNs) / 1e9, kSeconds, 100.0 * double(stats.cpuNs) / 1e9 / kSeconds, (unsigned long long)stats.blocks);
    std::fflush(stdout);
}

// 1 h of 20 vehicles at 10 Hz, written straight through the writer (as the recorder would have).
QString makeHourLog(const QString &folder)
{
    constexpr int kVehicles = 20, kSeconds = 3600, kHz = 10;
    const int64_t t0 = 1'780'000'000'000;
    const QString path = QDir(folder).filePath(QStringLiteral("hour.sortielog"));
    flightlog::FlightLogWriter writer(path, {0, 0});
    QString error;
    if (!writer.open(&error))
        qFatal("%s", qPrintable(error));
    vehicle::TelemetryBatch batch;
    QElapsedTimer wall;
    wall.start();
    for (int second = 0; second < kSeconds; ++second) {
        flightlog::RecordingChunk chunk;
        if (second == 0)
            for (int v = 0; v < kVehicles; ++v)
                chunk.vehicles.push_back({QStringLiteral("HCI:%1").arg(v), {QString::number(v), QStringLiteral("EMU-%1").arg(101 + v), QStringLiteral("multicopter"), {}, QStringLiteral("HCI")}});
        for (int v = 0; v < kVehicles; ++v) {
            flightlog::RecordedSamples s{QStringLiteral("HCI:%1").arg(v), {}};
            for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f)
                s.fields.push_back({TelemetryField(f), {}});
            for (int k = 0; k < kHz; ++k) {
                telemetry(v, t0 + second * 1000 + k * 100, batch);
                for (size_t f = 0; f < batch.size(); ++f)
                    s.fields[f].samples.push_back({batch[f].time, batch[f].value});
            }
            chunk.samples.push_back(std::move(s));
        }
        if (second % 60 == 0)
            chunk.events.push_back({QStringLiteral("HCI:%1").arg(second / 60 % kVehicles), t0 + second * 1000, QStringLiteral("mode"), QStringLiteral("auto"), -1});
        writer.write(chunk);
    }
    const auto s = writer.stats();
    writer.close();
    std::printf("hour log: %llu values written in %.1f s (writer thread %.1f s CPU: %.2f us per value), %.2f bytes per value on disk\n",
                (unsigned long long)s.values, double(wall.elapsed()) / 1000, double(s.cpuNs) / 1e9, double(s.cpuNs) / 1e3 / double(s.values),
                double(QFileInfo(path).size()) / double(s.values));
    std::printf("recording: writer thread at 200000 values/s: %.1f %% of one core\n", double(s.cpuNs) / double(s.values) * 200000 / 1e9 * 100);
    return path;
}

void benchReplay(const QString &path)
{
    QElapsedTimer t;
    t.start();
    QString error;
    const auto log = flightlog::FlightLog::open(path, &error);
    const double openMs = double(t.nsecsElapsed()) / 1e6;
    if (!log)
        qFatal("%s", qPrintable(error));
    t.restart();
    flightlog::ReplayController replay;
    replay.open(path);
    const double replayMs = double(t.nsecsElapsed()) / 1e6;
    QElapsedTimer sinceOpen;
    sinceOpen.start();
    std::printf("replay: 1 h x 20 vehicles x 10 Hz (%.1f M values): FlightLog::open %.0f ms, ReplayController::open %.0f ms (load average %.1f)\n",
                double(log->vehicles()[0].sampleCount() * log->vehicles().size()) / 1e6, openMs, replayMs, test::loadAverage());
    QRandomGenerator rng(11);
    auto scrub = [&](int seeks, const char *when) {
        double worst = 0, total = 0;
        for (int i = 0; i < seeks; ++i) {
            t.restart();
            replay.setProgress(rng.generateDouble());
            const double ms = double(t.nsecsElapsed()) / 1e6;
            worst = std::max(worst, ms);
            total += ms;
        }
        std::printf("replay: scrub %s (seek 20 vehicles to a random time): mean %.2f ms, worst %.2f ms over %d seeks\n", when, total / seeks, worst, seeks);
    };
    // While the worker decodes the histories (the GUI thread shares the 2 cores with it).
    scrub(100, "while the histories load");
    const double guiCpu = test::threadCpuMs();
    if (!replay.isHistoryLoaded()) {
        QEventLoop loop;
        QObject::connect(&replay, &flightlog::ReplayController::historyLoadedChanged, &loop, &QEventLoop::quit);
        loop.exec();
    }
    std::printf("replay: whole-span plot histories in the vehicles %.0f ms after open returned (worker thread, load average %.1f); "
                "handing them to the vehicles took %.0f ms CPU on the GUI thread\n",
                double(sinceOpen.nsecsElapsed()) / 1e6, test::loadAverage(), test::threadCpuMs() - guiCpu);
    scrub(500, "after");
    replay.seek(replay.start());
    replay.setSpeed(50);
    double worst = 0, total = 0;
    int frames = 0;
    while (replay.position() < replay.start() + 600000) {
        t.restart();
        replay.advance(16);
        const double ms = double(t.nsecsElapsed()) / 1e6;
        worst = std::max(worst, ms);
        total += ms;
        ++frames;
    }
    std::printf("replay: playing at 50x, one 16 ms frame: mean %.2f ms, worst %.2f ms over %d frames\n", total / frames, worst, frames);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    benchRecording(dir.path());
    benchReplay(makeHourLog(dir.path()));
    return 0;
}
