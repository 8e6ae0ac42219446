// Resident memory of the whole client, main window offscreen: idle after logging in to a simulator
// with 20 vehicles, then with a 10,000-waypoint route open on the mission page and an hour of 10 Hz
// telemetry for each of the 20 vehicles (every field the client knows, the worst case: the stores
// keep their last 30 minutes), drawn on both pages.
//
// Usage: bench_memory
#include "BenchRoute.h"
#include "ClientUnderTest.h"
#include "FreePort.h"
#include "ProcessStats.h"
#include "QuickScene.h"
#include "SimProcess.h"

#include <QDateTime>
#include <QGuiApplication>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cstdio>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

void report(const char *what)
{
    const auto stats = test::ProcessStats::of();
    std::printf("%-72s RSS %7.1f MiB  (peak %7.1f MiB, %d fds)\n", what, double(stats.residentKiB) / 1024,
                double(stats.peakResidentKiB) / 1024, stats.openFiles);
}

// An hour of telemetry at 10 Hz for every field, as the vehicle's link would deliver it.
void feedAnHour(vehicle::Vehicle &v, qint64 endMs)
{
    constexpr int kTicks = 3600 * 10;
    vehicle::TelemetryBatch batch(vehicle::kTelemetryFieldCount);
    for (int tick = 0; tick < kTicks; ++tick) {
        const qint64 time = endMs - qint64(kTicks - tick) * 100;
        for (size_t f = 0; f < batch.size(); ++f)
            batch[f] = {vehicle::TelemetryField(f), 0.001 * tick + double(f), time};
        v.ingest(batch);
    }
}

} // namespace

int main(int argc, char **argv)
{
    test::useSoftwareRendering();
    QGuiApplication app(argc, argv);
    std::printf("bench_memory: the client's resident memory (VmRSS), main window 1280x800 offscreen, software renderer\n");
    test::SimProcess sim(test::freePort(), {QStringLiteral("--hci-vehicles"), QStringLiteral("20")});
    if (!sim.start()) {
        std::printf("FAILED: sortie-sim did not start\n");
        return 1;
    }
    bench::ClientUnderTest client;
    if (!client.isReady())
        return 1;
    client.renderFrame();
    QTest::qWait(2000);
    report("login view, idle");
    if (!client.logIn(sim.address()) || !QTest::qWaitFor([&] { return client.fleet().count() == 20; }, 30000)) {
        std::printf("FAILED: no login or not 20 vehicles (%s)\n", qPrintable(client.connection().errorString()));
        return 1;
    }
    client.showPage(1);
    QTest::qWait(3000);
    report("logged in, 20 vehicles at 10 Hz, mission page, idle");

    client.missions().document()->load(mission::benchRoute(10000));
    client.showPage(1);
    QTest::qWait(1000);
    client.renderFrame();
    report("+ 10,000-waypoint route on the mission page");

    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    for (int row = 0; row < client.fleet().count(); ++row)
        feedAnHour(*client.fleet().vehicleAt(row), now);
    client.showPage(2);
    QTest::qWait(1000);
    client.renderFrame();
    report("+ an hour of telemetry for 20 vehicles (26 fields, 10 Hz), telemetry page");
    client.showPage(1);
    QTest::qWait(1000);
    client.renderFrame();
    report("  back on the mission page");
    return 0;
}
