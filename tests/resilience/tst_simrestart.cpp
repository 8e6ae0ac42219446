// The simulator as a real process, killed with SIGKILL and started again on the same port: during the
// login, during an upload, during telemetry. The operator's view (connection state and errors, the
// mission's message and progress, the vehicles' staleness and values) is what is asserted, and
// nothing the operator typed may be lost.
#include "ResilienceSupport.h"
#include "SimProcess.h"

#include "Messages.pb.h"
#include "Vehicle.h"

#include <QGeoCoordinate>
#include <QPointer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie;
using namespace std::chrono_literals;
using client::MissionController;
using vehicle::TelemetryField;
using test::kDemoRoute;
using test::rowOf;

namespace {

// The time of a vehicle's last latitude sample, or 0.
qint64 lastFix(const vehicle::Vehicle *v)
{
    const auto sample = v ? v->last(TelemetryField::Latitude) : std::nullopt;
    return sample ? sample->time : 0;
}

} // namespace

class TestSimRestart : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString store() const { return m_dir.filePath(QString::fromLatin1(QTest::currentTestFunction()) + QStringLiteral(".json")); }

private slots:
    void killedDuringLogin()
    {
        const quint16 port = test::freePort();
        // Every answer comes 300 ms late, so the login is surely under way when the process dies.
        test::SimProcess sim(port, {QStringLiteral("--store"), store(), QStringLiteral("--fault-delay"), QStringLiteral("300")});
        QVERIFY(sim.start());
        test::Operator op;
        QVERIFY(op.connection.connectToServer(QStringLiteral("127.0.0.1:%1").arg(port), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_VERIFY_WITH_TIMEOUT(op.connection.stateName() == QStringLiteral("Authorizing")
                                     || op.connection.stateName() == QStringLiteral("LoggingIn"), 10000);
        sim.kill();
        // The operator sees a retry, not a dead end...
        QTRY_COMPARE_WITH_TIMEOUT(op.connection.stateName(), QStringLiteral("Reconnecting"), 10000);
        QTRY_VERIFY(op.connection.detail().startsWith(QStringLiteral("connection lost; attempt")));
        QVERIFY(sim.start());
        // ...and then a logged-in session, with no error left on screen.
        QTRY_COMPARE_WITH_TIMEOUT(op.connection.stateName(), QStringLiteral("Ready"), 15000);
        QVERIFY2(op.connection.errorString().isEmpty(), qPrintable(op.connection.errorString()));
        QCOMPARE(op.connection.user(), QStringLiteral("admin"));
        QVERIFY(op.session.clientId() >= 0);
        QCOMPARE(op.session.user().login(), std::string("admin"));
        QCOMPARE(op.states.first(), QStringLiteral("Connecting"));
        QVERIFY2(op.states.contains(QStringLiteral("Reconnecting")), qPrintable(op.states.join(',')));
        // The session works: the server's routes arrive.
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(*op.missions.routes(), kDemoRoute) >= 0, 10000);
    }

    void killedDuringUpload()
    {
        const quint16 port = test::freePort();
        test::SimProcess sim(port, {QStringLiteral("--store"), store()});
        QVERIFY(sim.start());
        test::Operator op;
        QVERIFY(op.logIn(QStringLiteral("127.0.0.1:%1").arg(port)));
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(*op.missions.routes(), kDemoRoute) >= 0, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(op.missions.vehicles()->count(), 3, 10000);
        op.missions.openRoute(op.missions.routes()->objectIdAt(rowOf(*op.missions.routes(), kDemoRoute)));
        QTRY_COMPARE_WITH_TIMEOUT(op.missions.document()->model()->count(), 4, 10000);
        client::RouteDocument *doc = op.missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820)); // the operator's edit, never saved
        QCOMPARE(doc->model()->count(), 5);

        client::RoutePreparation &preparation = *op.missions.preparation();
        client::MissionUploader &uploader = *preparation.uploader();
        QSignalSpy uploaded(&preparation, &client::RoutePreparation::uploaded);
        QTRY_COMPARE_WITH_TIMEOUT(op.fleet->count(), 3, 10000);
        const QString emu = op.fleet->index(0).data(client::VehicleFleet::VehicleIdRole).toString();
        preparation.setVehicleId(emu);
        preparation.upload();
        // The edit is not saved: the uploader asks, and the operator uploads what is on screen.
        QTRY_COMPARE(uploader.state(), client::MissionUploader::State::AwaitingConfirmation);
        QVERIFY(uploader.question().contains(QLatin1String("not saved")));
        uploader.confirm();
        // The transfer has begun: the server reported progress.
        QTRY_VERIFY_WITH_TIMEOUT(uploader.progressMaximum() > 0 && uploader.activity().startsWith(QStringLiteral("Uploading to")), 10000);
        sim.kill();

        // Reported failed, the progress is over, and the edit is still on screen.
        QTRY_VERIFY_WITH_TIMEOUT(!uploader.isBusy(), 10000);
        QVERIFY2(preparation.message().startsWith(QStringLiteral("Upload to EMU-101 failed")), qPrintable(preparation.message()));
        QCOMPARE(uploaded.count(), 0);
        QCOMPARE(doc->model()->count(), 5);
        QVERIFY(doc->isModified());

        QVERIFY(sim.start());
        QTRY_COMPARE_WITH_TIMEOUT(op.connection.stateName(), QStringLiteral("Ready"), 15000);
        QTRY_COMPARE_WITH_TIMEOUT(op.missions.vehicles()->count(), 3, 10000);
        QCOMPARE(uploaded.count(), 0); // a reconnect does not make the lost upload look done
        // Uploading again works, and what goes up is the edited route.
        QTRY_COMPARE_WITH_TIMEOUT(op.fleet->count(), 3, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(op.fleet->vehicle(emu) && op.fleet->vehicle(emu)->isConnected(), 10000);
        preparation.upload();
        QTRY_COMPARE(uploader.state(), client::MissionUploader::State::AwaitingConfirmation);
        uploader.confirm();
        QVERIFY(uploaded.wait(15000));
        QCOMPARE(uploaded.count(), 1);
        QVERIFY2(preparation.message().startsWith(QStringLiteral("Uploaded to EMU-101: ")), qPrintable(preparation.message()));
        QVERIFY(!uploader.isBusy());
        QVERIFY(op.fleet->vehicle(emu)->mission().size() >= 5);
        QCOMPARE(doc->model()->count(), 5);
    }

    void killedDuringTelemetry()
    {
        const quint16 port = test::freePort();
        const quint16 vciPort = test::freePort();
        test::SimProcess sim(port, {QStringLiteral("--store"), store(), QStringLiteral("--telemetry-rate"), QStringLiteral("10"),
                                    QStringLiteral("--vci"), QStringLiteral("1"), QStringLiteral("--vci-port"),
                                    QString::number(vciPort), QStringLiteral("--vci-rate"), QStringLiteral("10")});
        QVERIFY(sim.start());
        test::Operator op;
        QVERIFY(op.logIn(QStringLiteral("127.0.0.1:%1").arg(port)));
        QVERIFY(op.fleet->addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(vciPort)));
        QTRY_COMPARE_WITH_TIMEOUT(op.fleet->count(), 4, 10000);

        // Every vehicle, HCI and VCI, is live; it is marked stale after 600 ms of silence.
        QList<QPointer<vehicle::Vehicle>> vehicles;
        for (int row = 0; row < op.fleet->count(); ++row) {
            vehicles.append(op.fleet->vehicleAt(row));
            vehicles.last()->setStaleAfter(600);
        }
        for (const auto &v : vehicles)
            QTRY_VERIFY_WITH_TIMEOUT(!v->isStale() && lastFix(v) > 0, 10000);

        sim.kill();
        for (int row = 0; row < op.fleet->count(); ++row)
            QTRY_VERIFY_WITH_TIMEOUT(op.fleet->index(row).data(client::VehicleFleet::StaleRole).toBool(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(op.connection.stateName(), QStringLiteral("Reconnecting"), 10000);
        QList<qint64> before;
        QList<size_t> history;
        for (const auto &v : vehicles) {
            QVERIFY(v);
            QTRY_VERIFY_WITH_TIMEOUT(v->isStale(), 10000); // nothing heard for 600 ms
            before.append(lastFix(v));
            history.append(v->history().series(TelemetryField::Latitude).size());
        }

        QVERIFY(sim.start());
        QTRY_COMPARE_WITH_TIMEOUT(op.connection.stateName(), QStringLiteral("Ready"), 15000);
        // The same vehicles (the views keep their pointers and plots) come back to life: re-subscribed,
        // fresh samples after the ones from before the restart, and the history kept.
        QCOMPARE(op.fleet->count(), 4);
        for (int i = 0; i < vehicles.size(); ++i) {
            QVERIFY2(vehicles[i], "a vehicle object was replaced by the reconnect");
            QTRY_VERIFY_WITH_TIMEOUT(!vehicles[i]->isStale() && lastFix(vehicles[i]) > before[i], 15000);
            QVERIFY(vehicles[i]->history().series(TelemetryField::Latitude).size() > history[i]);
            QCOMPARE(op.fleet->vehicleAt(i), vehicles[i].data());
        }
        QVERIFY(op.connection.errorString().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestSimRestart)
#include "tst_simrestart.moc"
