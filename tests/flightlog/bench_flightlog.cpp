// Flight-log figures for docs/performance.md:
// 1. recording: 200,000 values/s (770 vehicles x 26 fields x 10 Hz, fed as fast as possible, flushed
//    every half second of data as the live recorder does), CPU per second of data on the gathering
//    thread and on the writer thread, and bytes per value on disk;
// 2. replay: a log of 1 hour of 20 vehicles at 10 Hz (26 fields): FlightLog::open, ReplayController::open
//    (what the operator waits for), the whole-span plot histories decoded on the worker thread after it,
//    scrubbing at random while that worker runs and after, playing at 50x;
// 3. telemetry as a sensor reports it: the simulator's flight model flying a survey, with GPS jitter
//    and drift, attitude and speed noise added as a receiver and an IMU give them, written as a log:
//    bytes per value on disk, per field in the block codec, and what zstd makes of the blocks.
#include "FlightLog.h"
#include "FlightLogWriter.h"
#include "FlightRecorder.h"
#include "ReplayController.h"
#include "Vehicle.h"
#include "BenchClock.h"
#include "FlightModel.h"
#include "TelemetryBlockCodec.h"

#include <zstd.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
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

// A sensor's error: white noise around a first-order Gauss-Markov drift (what a GNSS receiver's
// multipath and atmosphere look like at 10 Hz: metres that wander over a minute, centimetres that
// jump each fix).
class SensorError
{
public:
    SensorError(double whiteSigma, double driftSigma, double driftSeconds, std::mt19937_64 &rng)
        : m_white(0, whiteSigma), m_driftSigma(driftSigma), m_tau(driftSeconds), m_rng(rng) {}
    double next(double dt)
    {
        if (m_tau > 0) {
            const double a = std::exp(-dt / m_tau);
            m_drift = a * m_drift + std::sqrt(1 - a * a) * m_driftSigma * m_unit(m_rng);
        }
        return m_drift + m_white(m_rng);
    }

private:
    std::normal_distribution<double> m_white, m_unit{0, 1};
    double m_driftSigma, m_tau, m_drift = 0;
    std::mt19937_64 &m_rng;
};

// The simulator's multicopter flies a survey (ten 400 m lines 40 m apart at 8 m/s, 50 m above home)
// and reports at 10 Hz what sortie-sim's HCI vehicles report (16 fields), with the errors of a
// typical GNSS receiver (0.3 m white, 0.8 m drift over 60 s horizontally; 0.6 m and 1.5 m vertically)
// and MEMS attitude (roll and pitch 0.3 deg, heading 0.5 deg), speeds (0.08 and 0.1 m/s), battery
// voltage (0.02 V) and current (0.3 A), times jittered by 0-3 ms.
void benchNoisyFlight(const QString &folder)
{
    constexpr double kHz = 10, dt = 1 / kHz;
    const int64_t t0 = 1'780'000'000'000;
    sim::FlightModel model(56.95, 24.10, 12.0);
    std::vector<sim::FlightModel::Waypoint> survey;
    for (int line = 0; line < 10; ++line)
        for (int end = 0; end < 2; ++end) {
            double lat = 0, lon = 0;
            sim::sphericalDestination(56.95, 24.10, 90, 40.0 * line, &lat, &lon);
            sim::sphericalDestination(lat, lon, 0, (line % 2 == end) ? 0 : 400, &lat, &lon);
            survey.push_back({lat, lon, 50, 8});
        }
    survey.back().landHere = true;
    model.arm();
    model.setMission(survey);
    model.takeoff(50);
    std::mt19937_64 rng(7);
    SensorError north(0.3, 0.8, 60, rng), east(0.3, 0.8, 60, rng), up(0.6, 1.5, 60, rng);
    SensorError roll(0.3, 0, 0, rng), pitch(0.3, 0, 0, rng), heading(0.5, 0, 0, rng);
    SensorError speed(0.08, 0, 0, rng), climb(0.1, 0, 0, rng), volts(0.02, 0, 0, rng), amps(0.3, 0, 0, rng);
    std::uniform_int_distribution<int> jitter(0, 3);
    const double metresPerDegree = 111'320.0, lonScale = std::cos(56.95 * M_PI / 180);

    // Per second of flight, one block of fields, as the writer makes them.
    std::vector<flightlog::BlockFields> seconds;
    const std::vector<TelemetryField> reported = {TelemetryField::Latitude, TelemetryField::Longitude, TelemetryField::AltitudeAmsl,
        TelemetryField::AltitudeAgl, TelemetryField::GroundSpeed, TelemetryField::VerticalSpeed, TelemetryField::Heading, TelemetryField::Roll,
        TelemetryField::Pitch, TelemetryField::BatteryVoltage, TelemetryField::BatteryCurrent, TelemetryField::BatteryRemaining,
        TelemetryField::GpsFix, TelemetryField::Satellites, TelemetryField::Mode, TelemetryField::Armed};
    bool started = false;
    int tick = 0;
    for (; tick < 3600 * int(kHz); ++tick) {
        model.tick(dt);
        const auto &st = model.state();
        if (!started && st.altitudeAgl > 49) {
            model.startMission();
            started = true;
        }
        if (started && !st.armed)
            break;
        const int64_t t = t0 + tick * 100 + jitter(rng);
        const double dUp = up.next(dt);
        const double values[] = {st.latitude + north.next(dt) / metresPerDegree, st.longitude + east.next(dt) / (metresPerDegree * lonScale),
            st.altitudeAmsl() + dUp, st.altitudeAgl + dUp, std::max(0.0, st.groundSpeed + speed.next(dt)), st.verticalSpeed + climb.next(dt),
            std::fmod(st.heading + heading.next(dt) + 360, 360), st.roll + roll.next(dt), st.pitch + pitch.next(dt),
            std::round((st.batteryVoltage + volts.next(dt)) * 100) / 100, std::round((st.batteryCurrent + amps.next(dt)) * 100) / 100,
            std::round(st.batteryRemaining * 10000) / 10000, double(st.gpsFix), double(st.satellites), double(int(st.mode)), st.armed ? 1.0 : 0.0};
        if (tick % int(kHz) == 0) {
            seconds.emplace_back();
            for (TelemetryField f : reported)
                seconds.back().push_back({f, {}});
        }
        for (size_t i = 0; i < reported.size(); ++i)
            seconds.back()[i].samples.push_back({t, values[i]});
    }

    // On disk, through the writer, as sortie-log record writes it.
    const QString path = QDir(folder).filePath(QStringLiteral("noisy.sortielog"));
    flightlog::FlightLogWriter writer(path, {0, 0});
    QString error;
    if (!writer.open(&error))
        qFatal("%s", qPrintable(error));
    for (size_t second = 0; second < seconds.size(); ++second) {
        flightlog::RecordingChunk chunk;
        if (second == 0)
            chunk.vehicles.push_back({QStringLiteral("HCI:1"), {QStringLiteral("1"), QStringLiteral("EMU-101"), QStringLiteral("multicopter"), {}, QStringLiteral("HCI")}});
        chunk.samples.push_back({QStringLiteral("HCI:1"), seconds[second]});
        writer.write(chunk);
    }
    const auto stats = writer.stats();
    writer.close();
    std::printf("noisy flight: %zu s of a survey at 10 Hz, %llu values; on disk %.2f bytes per value (SQLite included)\n", seconds.size(),
                (unsigned long long)stats.values, double(QFileInfo(path).size()) / double(stats.values));

    // The blocks alone, and each field alone, and zstd over each block (what compressing the
    // block body would give), at two levels.
    size_t raw = 0, zstd3 = 0, zstd19 = 0, values = 0;
    std::map<TelemetryField, std::pair<size_t, size_t>> perField; // bytes, values
    std::string out;
    for (const auto &block : seconds) {
        const std::string encoded = flightlog::TelemetryBlockCodec::encode(block);
        raw += encoded.size();
        out.resize(ZSTD_compressBound(encoded.size()));
        zstd3 += ZSTD_compress(out.data(), out.size(), encoded.data(), encoded.size(), 3);
        zstd19 += ZSTD_compress(out.data(), out.size(), encoded.data(), encoded.size(), 19);
        for (size_t i = 0; i < block.size(); ++i) {
            values += block[i].samples.size();
            flightlog::BlockFields without = block;
            without.erase(without.begin() + std::ptrdiff_t(i));
            perField[block[i].field].first += encoded.size() - flightlog::TelemetryBlockCodec::encode(without).size();
            perField[block[i].field].second += block[i].samples.size();
        }
    }
    std::printf("noisy flight: blocks %.2f bytes per value; zstd level 3 over each block %.2f, level 19 %.2f\n", double(raw) / double(values),
                double(zstd3) / double(values), double(zstd19) / double(values));
    std::printf("noisy flight: bytes per value of each field (what leaving it out of the blocks saves):");
    for (const auto &[field, bv] : perField)
        std::printf(" %s %.2f", std::string(vehicle::fieldName(field)).c_str(), double(bv.first) / double(bv.second));
    std::printf("\n");
    std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    benchNoisyFlight(dir.path());
    if (app.arguments().contains(QStringLiteral("--noisy-only")))
        return 0;
    benchRecording(dir.path());
    benchReplay(makeHourLog(dir.path()));
    return 0;
}
