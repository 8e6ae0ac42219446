// 100 connect/disconnect cycles over real sockets, HCI and VCI: after a warm-up of 10, neither this
// process's open file descriptors, its resident memory nor its heap in use may grow (measured from
// /proc/self and the allocator, printed; the heap bound holds under ASan too).
#include "ResilienceSupport.h"

#include "SimFixture.h"
#include "SimVciListener.h"
#include "SimVciSession.h"
#include "SimVciVehicle.h"
#include "VciEndpoint.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QTest>

using namespace sortie;

namespace {

constexpr int kWarmUp = 10;
constexpr int kCycles = 100;
// Allowed RSS growth from cycle 10 to cycle 100. A leak of one socket, reply or session object per
// cycle is a few KiB, so 90 cycles of it would show; 4 MiB leaves room for the allocator's pools
// settling and the sim's telemetry history, which is bounded but fills while the test runs.
constexpr qint64 kRssBoundKiB = 4 * 1024;
// Allowed growth of the heap in use over the same 90 cycles: the same leak of a few KiB a cycle
// shows, and this bound holds under ASan too, where resident memory means nothing.
constexpr qint64 kHeapBoundKiB = 2 * 1024;

struct Figures
{
    int fds = 0;
    qint64 rss = 0;
    qint64 heapKiB = 0;
    static Figures now()
    {
        const auto stats = test::ProcessStats::of();
        return {stats.openFiles, stats.residentKiB, test::heapBytesInUse() / 1024};
    }
};

void report(const char *what, const Figures &warm, const Figures &end)
{
    qInfo("%s: after %d cycles fds %d, VmRSS %lld KiB, heap %lld KiB; after %d cycles fds %d, VmRSS %lld KiB (%+lld KiB), heap %lld KiB (%+lld KiB)",
          what, kWarmUp, warm.fds, qlonglong(warm.rss), qlonglong(warm.heapKiB), kCycles, end.fds, qlonglong(end.rss),
          qlonglong(end.rss - warm.rss), qlonglong(end.heapKiB), qlonglong(end.heapKiB - warm.heapKiB));
}

} // namespace

class TestConnectCycles : public QObject
{
    Q_OBJECT

private slots:
    void hciLoginAndDisconnect()
    {
        test::SimFixture sim;
        const QString address = sim.address();
        // Three ways to end a session, in turn: log out; have the server drop the line, re-attach,
        // then log out; or vanish without a word (the application closed).
        auto cycle = [&](int i) -> bool {
            test::Operator op(false);
            if (!op.logIn(address))
                return false;
            if (!test::waitUntil([&] { return op.missions.routes()->count() > 0 && !op.missions.isBusy(); }))
                return false;
            switch (i % 3) {
            case 0:
                op.connection.disconnectFromServer();
                break;
            case 1:
                sim.server.dropConnections();
                if (!test::waitUntil([&] { return op.states.last() == QStringLiteral("Reconnecting"); })
                    || !test::waitUntil([&] { return op.connection.isReady(); }))
                    return false;
                op.connection.disconnectFromServer();
                break;
            default:
                break;
            }
            if (i % 3 != 2 && !test::waitUntil([&] { return op.connection.stateName() == QStringLiteral("Disconnected"); }))
                return false;
            return true;
        };
        auto settle = [&] {
            // The server forgets the detached sessions of the vanished clients, and all sockets close.
            sim.server.expireSessions();
            return test::waitUntil([&] { return sim.server.connectionCount() == 0; });
        };

        for (int i = 0; i < kWarmUp; ++i)
            QVERIFY2(cycle(i) && settle(), qPrintable(QStringLiteral("warm-up cycle %1").arg(i)));
        QTest::qWait(20);
        const Figures warm = Figures::now();
        for (int i = kWarmUp; i < kCycles; ++i)
            QVERIFY2(cycle(i) && settle(), qPrintable(QStringLiteral("cycle %1").arg(i)));
        QTest::qWait(20);
        const Figures end = Figures::now();
        report("HCI login/disconnect", warm, end);
        QVERIFY2(end.fds <= warm.fds + 2, "file descriptors leak across HCI connections");
        QVERIFY2(!test::kResidentMemoryIsMeaningful || end.rss - warm.rss < kRssBoundKiB, "memory grows with HCI connections");
        QVERIFY2(end.heapKiB - warm.heapKiB < kHeapBoundKiB, "the heap grows with HCI connections");
    }

    void vciConnectAndDisconnect()
    {
        sim::SimVciOptions options;
        options.telemetryRate = 20;
        sim::SimVciVehicle simVehicle(options);
        sim::SimVciListener listener(&simVehicle);
        QVERIFY(listener.listen(0));
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port()), &error);
        QVERIFY2(endpoint, qPrintable(error));

        // Each cycle: a vehicle link connects, subscribes and gets telemetry, then goes away; half of
        // them are dropped by the vehicle first (and reconnect) before the link is stopped.
        auto cycle = [&](int i) -> bool {
            vehicle::VciVehicleLink link(*endpoint);
            link.transport()->setRetryDelays(20, 200);
            vehicle::Vehicle v(&link);
            link.start();
            if (!test::waitUntil([&] { return v.isConnected() && !v.isStale(); }))
                return false;
            if (i % 2) {
                listener.dropConnections();
                if (!test::waitUntil([&] { return !v.isConnected(); }) || !test::waitUntil([&] { return v.isConnected(); }))
                    return false;
            }
            link.stop();
            return true;
        };
        auto settle = [&] { return test::waitUntil([&] { return listener.sessions().isEmpty(); }); };

        for (int i = 0; i < kWarmUp; ++i)
            QVERIFY2(cycle(i) && settle(), qPrintable(QStringLiteral("warm-up cycle %1").arg(i)));
        QTest::qWait(20);
        const Figures warm = Figures::now();
        for (int i = kWarmUp; i < kCycles; ++i)
            QVERIFY2(cycle(i) && settle(), qPrintable(QStringLiteral("cycle %1").arg(i)));
        QTest::qWait(20);
        const Figures end = Figures::now();
        report("VCI connect/disconnect", warm, end);
        QVERIFY2(end.fds <= warm.fds + 2, "file descriptors leak across VCI connections");
        QVERIFY2(!test::kResidentMemoryIsMeaningful || end.rss - warm.rss < kRssBoundKiB, "memory grows with VCI connections");
        QVERIFY2(end.heapKiB - warm.heapKiB < kHeapBoundKiB, "the heap grows with VCI connections");
    }
};

QTEST_GUILESS_MAIN(TestConnectCycles)
#include "tst_connectcycles.moc"
