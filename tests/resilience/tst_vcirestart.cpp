// A VCI vehicle whose listener dies during telemetry and comes back on the same port: the link says
// so, the vehicle goes stale, a command sent meanwhile fails in words, and once the vehicle listens
// again the connection re-attaches, re-subscribes and the values move again.
#include "ResilienceSupport.h"

#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciEndpoint.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using vehicle::TelemetryField;

namespace {

qint64 lastFix(const vehicle::Vehicle &v)
{
    const auto sample = v.last(TelemetryField::Latitude);
    return sample ? sample->time : 0;
}

} // namespace

class TestVciRestart : public QObject
{
    Q_OBJECT

private slots:
    void listenerKilledDuringTelemetry()
    {
        sim::SimVciOptions options;
        options.telemetryRate = 20;
        sim::SimVciVehicle simVehicle(options);
        auto listener = std::make_unique<sim::SimVciListener>(&simVehicle);
        QVERIFY(listener->listen(0));
        const quint16 port = listener->port();

        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(port), &error);
        QVERIFY2(endpoint, qPrintable(error));
        vehicle::VciVehicleLink link(*endpoint);
        link.transport()->setRetryDelays(50, 400);
        link.setCommandTimeout(2000);
        vehicle::Vehicle v(&link);
        v.setStaleAfter(500);
        link.start();
        QTRY_VERIFY_WITH_TIMEOUT(v.isConnected() && !v.isStale() && lastFix(v) > 0, 10000);
        const QStringList subscribed = link.connection()->subscriptions();
        QVERIFY(!subscribed.isEmpty());

        QSignalSpy restored(link.connection(), &vci::VciConnection::subscriptionsRestored);
        listener.reset(); // the vehicle's side goes away: its sessions close, nothing listens
        QTRY_VERIFY_WITH_TIMEOUT(!v.isConnected(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(v.isStale(), 10000);
        QVERIFY2(!v.lastError().isEmpty(), "the operator is not told why the vehicle went away");
        const qint64 before = lastFix(v);
        const size_t history = v.history().series(TelemetryField::Latitude).size();

        // A command while the vehicle is gone ends, with a reason, instead of hanging.
        bool finished = false;
        QString result;
        connect(&v, &vehicle::Vehicle::commandFinished, this, [&](const QString &, bool ok, const QString &message) {
            finished = true;
            result = ok ? QStringLiteral("ok") : message;
        });
        v.arm();
        QTRY_VERIFY_WITH_TIMEOUT(finished, 10000);
        QVERIFY2(result != QStringLiteral("ok") && !result.isEmpty(), qPrintable(result));

        listener = std::make_unique<sim::SimVciListener>(&simVehicle);
        QVERIFY(listener->listen(port));
        QTRY_VERIFY_WITH_TIMEOUT(v.isConnected(), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(restored.count() > 0, 10000);
        QCOMPARE(link.connection()->subscriptions(), subscribed);
        QTRY_VERIFY_WITH_TIMEOUT(!v.isStale() && lastFix(v) > before, 10000);
        QVERIFY(v.history().series(TelemetryField::Latitude).size() > history); // history kept and extended
        QVERIFY(v.lastError().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestVciRestart)
#include "tst_vcirestart.moc"
