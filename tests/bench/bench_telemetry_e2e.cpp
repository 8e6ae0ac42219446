// Telemetry ingest end to end: sortie-sim (its own process) streams telemetry over loopback HCI to
// the whole client (session, fleet, vehicles, stores) with the main window on the live telemetry
// page, offscreen. Prints the values per second the client took in, its CPU, the frames it drew,
// and the latency from the server's timestamp to the model update (the Vehicle and its history
// hold the value), per second and overall, so falling behind shows as latency that grows.
//
// Usage: bench_telemetry_e2e [--seconds S] [--headless] [vehicles@Hz ...]   (default: 224@100 22@100)
#include "ClientUnderTest.h"
#include "FreePort.h"
#include "ProcessStats.h"
#include "QuickScene.h"
#include "SimProcess.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QGuiApplication>
#include <QQuickWindow>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

double nowMs()
{
    using namespace std::chrono;
    return duration<double, std::milli>(system_clock::now().time_since_epoch()).count();
}

// Runs the event loop for `ms` without pausing it (QTest::qWait sleeps 10 ms between passes, which
// would show up as latency).
void runEventLoop(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

double percentile(std::vector<float> values, double p)
{
    if (values.empty())
        return 0;
    const size_t at = std::min(values.size() - 1, size_t(p * double(values.size())));
    std::nth_element(values.begin(), values.begin() + long(at), values.end());
    return values[at];
}

// Latency of every batch (one vehicle's tick) and the values it carried, from the moment the
// vehicle's own ingest has run: the recorder is connected after it, so Qt calls it later.
struct Recorder
{
    std::vector<float> latencies;
    quint64 values = 0;

    void record(const vehicle::TelemetryBatch &batch)
    {
        if (batch.empty())
            return;
        values += batch.size();
        latencies.push_back(float(nowMs() - double(batch.front().time)));
    }
};

struct Scenario
{
    int vehicles = 0;
    int rateHz = 0;
};

bool run(const Scenario &scenario, int seconds, bool withWindow)
{
    std::printf("\n== %d vehicles x %d Hz, %s, %d s measured after 3 s of warm-up\n", scenario.vehicles, scenario.rateHz,
                withWindow ? "main window on the telemetry page" : "client layer only (--headless)", seconds);
    test::SimProcess sim(test::freePort(), {QStringLiteral("--hci-vehicles"), QString::number(scenario.vehicles),
                                            QStringLiteral("--telemetry-rate"), QString::number(scenario.rateHz),
                                            QStringLiteral("--no-demo-mission")});
    if (!sim.start()) {
        std::printf("FAILED: sortie-sim did not start\n");
        return false;
    }
    bench::ClientUnderTest client(withWindow);
    if (!client.isReady() || !client.logIn(sim.address())) {
        std::printf("FAILED: the client did not log in (%s)\n", qPrintable(client.connection().errorString()));
        return false;
    }
    if (!QTest::qWaitFor([&] { return client.fleet().count() == scenario.vehicles; }, 30000)) {
        std::printf("FAILED: %d of %d vehicles appeared\n", client.fleet().count(), scenario.vehicles);
        return false;
    }
    client.showPage(2);

    Recorder recorder;
    for (int row = 0; row < client.fleet().count(); ++row) {
        QObject::connect(client.fleet().vehicleAt(row)->link(), &vehicle::VehicleLink::telemetryReceived, &client.fleet(),
                         [&recorder](const vehicle::TelemetryBatch &batch) { recorder.record(batch); });
    }
    int frames = 0;
    if (client.window())
        QObject::connect(client.window(), &QQuickWindow::frameSwapped, client.window(), [&frames] { ++frames; });

    runEventLoop(3000);
    std::printf("second   values/s   client CPU   sim CPU   frames   latency p50   p99    max (ms)\n");
    quint64 totalValues = 0;
    std::vector<float> all;
    const auto start = test::ProcessStats::of();
    const auto simStart = test::ProcessStats::of(sim.pid());
    QElapsedTimer wall;
    wall.start();
    for (int second = 1; second <= seconds; ++second) {
        recorder = {};
        frames = 0;
        const auto before = test::ProcessStats::of();
        const auto simBefore = test::ProcessStats::of(sim.pid());
        const qint64 from = wall.nsecsElapsed();
        runEventLoop(1000);
        const double elapsed = double(wall.nsecsElapsed() - from) / 1e9;
        const auto after = test::ProcessStats::of();
        const auto simAfter = test::ProcessStats::of(sim.pid());
        std::printf("%6d %10.0f %11.0f%% %8.0f%% %8d %13.2f %6.2f %6.2f\n", second, double(recorder.values) / elapsed,
                    100 * (after.cpuSeconds - before.cpuSeconds) / elapsed,
                    100 * (simAfter.cpuSeconds - simBefore.cpuSeconds) / elapsed, frames,
                    percentile(recorder.latencies, 0.5), percentile(recorder.latencies, 0.99),
                    percentile(recorder.latencies, 1.0));
        totalValues += recorder.values;
        all.insert(all.end(), recorder.latencies.begin(), recorder.latencies.end());
    }
    const double elapsed = double(wall.nsecsElapsed()) / 1e9;
    const auto end = test::ProcessStats::of();
    const auto simEnd = test::ProcessStats::of(sim.pid());
    std::printf("total: %.0f values/s (%zu batches), client CPU %.0f%% of one core, sim CPU %.0f%%, latency p50 %.2f ms,"
                " p99 %.2f ms, max %.2f ms, client RSS %.0f MiB\n",
                double(totalValues) / elapsed, all.size(), 100 * (end.cpuSeconds - start.cpuSeconds) / elapsed,
                100 * (simEnd.cpuSeconds - simStart.cpuSeconds) / elapsed, percentile(all, 0.5), percentile(all, 0.99),
                percentile(all, 1.0), double(end.residentKiB) / 1024);
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    test::useSoftwareRendering();
    QGuiApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    int seconds = 10;
    if (const int at = int(args.indexOf(QStringLiteral("--seconds"))); at >= 0 && at + 1 < args.size()) {
        seconds = std::max(1, args[at + 1].toInt());
        args.remove(at, 2);
    }
    const bool withWindow = !args.removeAll(QStringLiteral("--headless"));
    std::vector<Scenario> scenarios;
    for (const QString &arg : args) {
        const QStringList parts = arg.split(QLatin1Char('@'));
        if (parts.size() == 2)
            scenarios.push_back({parts[0].toInt(), parts[1].toInt()});
    }
    if (scenarios.empty())
        scenarios = {{224, 100}, {22, 100}};
    std::printf("bench_telemetry_e2e: latency = client clock at model update - server timestamp (ms, same machine);"
                " CPU = user + system time / wall time\n");
    bool ok = true;
    for (const Scenario &s : scenarios)
        ok = run(s, seconds, withWindow) && ok;
    return ok ? 0 : 1;
}
