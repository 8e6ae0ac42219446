// VciVehicleLink + Vehicle against a simulated VCI vehicle, over TCP and over a pseudo-terminal:
// everything the profile offers, seen through the protocol-independent model.
#include "CommandCatcher.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QSignalSpy>
#include <QtTest>

using namespace sortie;
using namespace sortie::vehicle;

namespace {


using Result = test::CommandCatcher;

} // namespace

class TstVciVehicleLink : public QObject
{
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void telemetryAndIdentity_data();
    void telemetryAndIdentity();
    void commandsThroughTheModel();
    void missionUploadDownloadAndFlight();
    void parametersAndGoTo();
    void lostAndReconnected();
    void unreachableVehicleSaysWhy();

private:
    void startLink(const QString &url);
    std::unique_ptr<sim::SimVciVehicle> m_simVehicle;
    std::unique_ptr<sim::SimVciListener> m_listener;
    std::unique_ptr<VciVehicleLink> m_link;
    std::unique_ptr<Vehicle> m_vehicle;
    // Made before the link starts: a parked vehicle's telemetry may all have arrived, and
    // never change again, by the time startLink() returns.
    std::unique_ptr<QSignalSpy> m_telemetryChanged;
};

void TstVciVehicleLink::init()
{
    sim::SimVciOptions options;
    options.id = QStringLiteral("vci-7");
    options.name = QStringLiteral("Seven");
    options.telemetryRate = 25;
    options.timeScale = 10;
    m_simVehicle = std::make_unique<sim::SimVciVehicle>(options);
    m_listener = std::make_unique<sim::SimVciListener>(m_simVehicle.get());
    QVERIFY(m_listener->listen(0));
}

void TstVciVehicleLink::cleanup()
{
    m_telemetryChanged.reset();
    m_vehicle.reset();
    m_link.reset();
    m_listener.reset();
    m_simVehicle.reset();
}

void TstVciVehicleLink::startLink(const QString &url)
{
    QString error;
    const auto endpoint = vci::VciEndpoint::parse(url, &error);
    QVERIFY2(endpoint, qPrintable(error));
    m_link = std::make_unique<VciVehicleLink>(*endpoint);
    m_link->transport()->setRetryDelays(20, 200);
    m_vehicle = std::make_unique<Vehicle>(m_link.get());
    m_vehicle->setNotifyInterval(20);
    m_telemetryChanged = std::make_unique<QSignalSpy>(m_vehicle.get(), &Vehicle::telemetryChanged);
    QCOMPARE(m_vehicle->protocol(), QStringLiteral("VCI"));
    m_link->start();
    QTRY_VERIFY(m_vehicle->isConnected());
    QTRY_COMPARE(m_vehicle->id(), QStringLiteral("vci-7"));
}

void TstVciVehicleLink::telemetryAndIdentity_data()
{
    QTest::addColumn<bool>("serial");
    QTest::newRow("tcp") << false;
    QTest::newRow("pty") << true;
}

void TstVciVehicleLink::telemetryAndIdentity()
{
    QFETCH(bool, serial);
    if (serial) {
        QString error;
        QVERIFY2(m_listener->openPty(&error), qPrintable(error));
        startLink(QStringLiteral("serial:%1?baud=230400").arg(m_listener->ptyName()));
    } else {
        startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    }
    QCOMPARE(m_vehicle->name(), QStringLiteral("Seven"));
    QCOMPARE(m_link->identity().type, QStringLiteral("multicopter"));
    QTRY_VERIFY(m_vehicle->position().isValid());
    QVERIFY(std::abs(m_vehicle->position().latitude() - 56.9496) < 1e-6);
    QTRY_VERIFY(m_vehicle->home().isValid());
    QVERIFY(std::abs(m_vehicle->home().longitude() - 24.1052) < 1e-6);
    QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("manual"));
    QTRY_COMPARE(m_vehicle->gpsFix(), 3);
    QTRY_VERIFY(m_vehicle->batteryVoltage() > 16);
    QTRY_VERIFY(!std::isnan(m_vehicle->heading()));
    QTRY_VERIFY(!std::isnan(m_vehicle->value(TelemetryField::Course)));
    QTRY_COMPARE(m_vehicle->missionState(), QStringLiteral("idle"));
    QVERIFY(!m_vehicle->armed());
    QVERIFY(!m_vehicle->isStale());
    QTRY_VERIFY(m_vehicle->history().series(TelemetryField::Latitude).size() >= 5);
    QVERIFY(m_telemetryChanged->count() > 0);
}

void TstVciVehicleLink::commandsThroughTheModel()
{
    startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    QSignalSpy finished(m_vehicle.get(), &Vehicle::commandFinished);
    m_vehicle->arm();
    QTRY_COMPARE(finished.count(), 1);
    QCOMPARE(finished.at(0).at(0).toString(), QStringLiteral("arm"));
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QTRY_VERIFY(m_vehicle->armed());
    m_vehicle->takeoff(8);
    QTRY_COMPARE(finished.count(), 2);
    QVERIFY(finished.at(1).at(1).toBool());
    QTRY_VERIFY_WITH_TIMEOUT(m_vehicle->altitudeAgl() > 7.5, 10000);
    QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("hold"));
    m_vehicle->setMode(QStringLiteral("teleport"));
    QTRY_COMPARE(finished.count(), 3);
    QVERIFY(!finished.at(2).at(1).toBool());
    m_vehicle->disarm(); // refused in the air: the vehicle's reason reaches the operator
    QTRY_COMPARE(finished.count(), 4);
    QVERIFY(!finished.at(3).at(1).toBool());
    QVERIFY2(finished.at(3).at(2).toString().contains(QLatin1String("land first")), qPrintable(finished.at(3).at(2).toString()));
    m_vehicle->returnHome();
    QTRY_COMPARE(finished.count(), 5);
    QVERIFY(finished.at(4).at(1).toBool());
    QTRY_VERIFY(m_vehicle->mode() == QLatin1String("return_home") || m_vehicle->mode() == QLatin1String("land"));
    m_vehicle->land();
    QTRY_COMPARE(finished.count(), 6);
    QTRY_VERIFY_WITH_TIMEOUT(!m_vehicle->armed(), 20000);
}

void TstVciVehicleLink::missionUploadDownloadAndFlight()
{
    startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    const std::vector<MissionItem> plan = {{56.9499, 24.1052, 10, 12, 0, {}}, {56.9499, 24.1058, 14, 0, 0, {}}};
    QSignalSpy missionChanged(m_link.get(), &VehicleLink::missionChanged);
    Result upload;
    m_link->uploadMission(PreparedMission{plan, {}, {}}, {}, upload.callback());
    QTRY_VERIFY(upload.done);
    QVERIFY2(upload.result.ok, qPrintable(upload.result.message));
    QTRY_VERIFY(missionChanged.count() >= 1);
    bool downloaded = false;
    std::vector<MissionItem> back;
    m_link->downloadMission([&](const CommandResult &r, const std::vector<MissionItem> &items) {
        downloaded = r.ok;
        back = items;
    });
    QTRY_VERIFY(downloaded);
    QCOMPARE(back.size(), size_t(2));
    QCOMPARE(back[0].latitude, plan[0].latitude);
    QCOMPARE(back[1].altitude, 14.0);
    QVERIFY(back[1].speed > 0); // the vehicle filled in its default speed
    QTRY_COMPARE(m_vehicle->missionCount(), 2);

    Result arm, takeoff, go;
    m_link->arm(true, arm.callback());
    m_link->takeoff(10, takeoff.callback());
    m_link->setMode(FlightMode::Auto, go.callback());
    QTRY_VERIFY(go.done);
    QVERIFY2(arm.result.ok && takeoff.result.ok && go.result.ok, qPrintable(go.result.message));
    QTRY_COMPARE(m_vehicle->missionState(), QStringLiteral("active"));
    QTRY_VERIFY_WITH_TIMEOUT(m_vehicle->missionState() == QLatin1String("complete"), 30000);
    QCOMPARE(int(m_vehicle->value(TelemetryField::MissionReached)), 2);
    QVERIFY(std::abs(m_vehicle->position().longitude() - 24.1058) < 1e-4);

    Result bad;
    m_link->uploadMission(PreparedMission{{{120.0, 5.7, 10, 0, 0, {}}}, {}, {}}, {}, bad.callback()); // latitude (degrees) beyond the pole
    QTRY_VERIFY(bad.done);
    QVERIFY(!bad.result.ok);
    QVERIFY2(bad.result.message.contains(QLatin1String("waypoints[0].latitude")), qPrintable(bad.result.message));
}

void TstVciVehicleLink::parametersAndGoTo()
{
    startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    QVariantMap params;
    bool read = false;
    m_link->readParameters([&](const CommandResult &r, const QVariantMap &p) {
        read = r.ok;
        params = p;
    });
    QTRY_VERIFY(read);
    QCOMPARE(params.value(QStringLiteral("telemetry_rate")).toDouble(), 25.0);
    QVERIFY(params.contains(QStringLiteral("cruise_speed")));
    Result set, readOnly, badName;
    m_link->setParameter(QStringLiteral("takeoff_altitude"), 6, set.callback());
    m_link->setParameter(QStringLiteral("cruise_speed"), 3, readOnly.callback());
    m_link->setParameter(QStringLiteral("bad name"), 3, badName.callback());
    QTRY_VERIFY(set.done && readOnly.done && badName.done);
    QVERIFY2(set.result.ok, qPrintable(set.result.message));
    QVERIFY(!readOnly.result.ok);
    QVERIFY(readOnly.result.message.contains(QLatin1String("read-only")));
    QVERIFY(!badName.result.ok);

    Result arm, go;
    m_link->arm(true, arm.callback());
    m_link->goTo(56.9500, 24.1054, 12, 10, go.callback());
    QTRY_VERIFY(go.done);
    QVERIFY2(go.result.ok, qPrintable(go.result.message));
    QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("guided"));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_vehicle->position().latitude() - 56.9500) < 2e-5, 20000);
}

void TstVciVehicleLink::lostAndReconnected()
{
    startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    QSignalSpy linkState(m_vehicle.get(), &Vehicle::linkStateChanged);
    QTRY_VERIFY(m_vehicle->position().isValid());
    m_listener->dropConnections();
    QTRY_COMPARE(m_vehicle->linkState(), VehicleLink::State::Lost);
    QTRY_COMPARE(m_vehicle->linkState(), VehicleLink::State::Connected);
    QVERIFY(linkState.count() >= 2);
    // Telemetry flows again on the new connection (the sim's new session has every subscription).
    const qsizetype before = qsizetype(m_vehicle->history().series(TelemetryField::Latitude).size());
    QTRY_VERIFY(qsizetype(m_vehicle->history().series(TelemetryField::Latitude).size()) > before + 3);
    QTRY_COMPARE(m_listener->sessions().size(), 1);
    m_link->stop();
    QCOMPARE(m_vehicle->linkState(), VehicleLink::State::Disconnected);
}

void TstVciVehicleLink::unreachableVehicleSaysWhy()
{
    const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("serial:/dev/sortie-no-such-port?baud=57600"));
    QVERIFY(endpoint);
    VciVehicleLink link(*endpoint);
    link.transport()->setRetryDelays(20, 100);
    Vehicle v(&link);
    link.start();
    QTRY_VERIFY(!v.lastError().isEmpty());
    QVERIFY2(v.lastError().contains(QLatin1String("/dev/sortie-no-such-port")), qPrintable(v.lastError()));
    QCOMPARE(v.linkState(), VehicleLink::State::Connecting); // and it keeps trying

    // Once it connects, the error is cleared.
    startLink(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()));
    QSignalSpy errors(m_vehicle.get(), &Vehicle::lastErrorChanged);
    m_listener->dropConnections();
    QTRY_VERIFY(m_vehicle->lastError().contains(QLatin1String("lost")));
    QTRY_VERIFY(m_vehicle->isConnected());
    QVERIFY(m_vehicle->lastError().isEmpty());
    QCOMPARE(errors.count(), 2);
}

QTEST_GUILESS_MAIN(TstVciVehicleLink)
#include "tst_vcivehiclelink.moc"
