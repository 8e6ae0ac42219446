// VciConnection on a real serial line: a pseudo-terminal with the simulated vehicle on the master side
// and QSerialPort (through VciTransport and a serial: URL) on the slave device.
#include "VciEndpoint.h"
#include "VciProfile.h"
#include "VciTestSupport.h"
#include "VciTransport.h"

#include <QSignalSpy>
#include <QtTest>

using nlohmann::json;
using namespace sortie::vci;
using namespace sortie::vci::test;

class TstVciSerial : public QObject
{
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void endpointFromPty();
    void subscribeAndReceive();
    void putArmAndMode();
    void uploadMissionAndSeeItFlown();
    void unsubscribeAll();
    void timeout();
    void reconnectRestoresSubscriptions();

private:
    std::unique_ptr<SimVehicle> m_sim;
    std::unique_ptr<VciConnection> m_conn;
    std::unique_ptr<VciTransport> m_transport;
};

void TstVciSerial::init()
{
    sortie::sim::SimVciOptions options;
    options.telemetryRate = 20;
    options.timeScale = 10;
    m_sim = std::make_unique<SimVehicle>(options);
    QString error;
    QVERIFY2(m_sim->listener->openPty(&error), qPrintable(error));
    QVERIFY(m_sim->listener->ptyName().startsWith(QLatin1String("/dev/")));
    const auto endpoint = VciEndpoint::parse(QStringLiteral("serial:%1?baud=115200&parity=none").arg(m_sim->listener->ptyName()), &error);
    QVERIFY2(endpoint, qPrintable(error));
    m_conn = std::make_unique<VciConnection>();
    m_transport = std::make_unique<VciTransport>(*endpoint);
    m_transport->setRetryDelays(20, 200);
    connect(m_transport.get(), &VciTransport::opened, m_conn.get(), [this](QIODevice *d) { m_conn->setDevice(d); });
    connect(m_transport.get(), &VciTransport::lost, m_conn.get(), [this](const QString &why) { m_conn->setDevice(nullptr, why); });
    m_transport->open();
    QTRY_VERIFY2(m_conn->isAttached(), qPrintable(m_transport->lastError()));
}

void TstVciSerial::cleanup()
{
    m_conn.reset();
    m_transport.reset();
    m_sim.reset();
}

void TstVciSerial::endpointFromPty()
{
    QCOMPARE(m_transport->state(), VciTransport::State::Open);
    QVERIFY(qobject_cast<QSerialPort *>(m_transport->device()));
    QCOMPARE(qobject_cast<QSerialPort *>(m_transport->device())->baudRate(), 115200);
    Capture c;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, c.callback());
    QTRY_VERIFY(c.done);
    QVERIFY2(c.result.ok(), qPrintable(c.result.message));
    QCOMPARE(c.result.body["type"], json("multicopter"));
}

void TstVciSerial::subscribeAndReceive()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/gps"));
    m_conn->subscribe(QStringLiteral("/telemetry/attitude"));
    QTRY_VERIFY(notified.count() >= 6);
    QSet<QString> uris;
    for (const auto &args : notified)
        uris.insert(args.at(0).toString());
    QCOMPARE(uris, (QSet<QString>{QStringLiteral("/telemetry/gps"), QStringLiteral("/telemetry/attitude")}));
    for (const auto &args : notified) {
        if (args.at(0).toString() == QLatin1String("/telemetry/gps"))
            QCOMPARE(args.at(1).value<json>()["fix"], json(3));
    }
}

void TstVciSerial::putArmAndMode()
{
    Capture arm, guided, disarm;
    m_conn->put(QStringLiteral("/state/armed"), true, nullptr, arm.callback());
    m_conn->put(QStringLiteral("/state/mode"), "guided", nullptr, guided.callback());
    QTRY_VERIFY(guided.done);
    QVERIFY2(arm.result.ok(), qPrintable(arm.result.message));
    QVERIFY2(guided.result.ok(), qPrintable(guided.result.message));
    QTRY_COMPARE(m_sim->vehicle->model().state().mode, sortie::sim::FlightModel::Mode::Hold); // guided to where it is: done
    Capture mode;
    m_conn->get(QStringLiteral("/state/mode"), nullptr, mode.callback());
    QTRY_VERIFY(mode.done);
    QCOMPARE(mode.result.body, json("hold"));
    // Guided to where it stood means 2 m up: it refuses to disarm in the air, and lands when told.
    m_conn->put(QStringLiteral("/state/armed"), false, nullptr, disarm.callback());
    QTRY_VERIFY(disarm.done);
    QCOMPARE(disarm.result.status(), VciStatus::BadRequest);
    QVERIFY2(disarm.result.message.contains(QLatin1String("land first")), qPrintable(disarm.result.message));
    Capture land;
    m_conn->put(QStringLiteral("/command/land"), json::object(), nullptr, land.callback());
    QTRY_VERIFY(land.done);
    QVERIFY(land.result.ok());
    QTRY_VERIFY(!m_sim->vehicle->model().state().armed);
}

void TstVciSerial::uploadMissionAndSeeItFlown()
{
    namespace profile = sortie::vci::profile;
    const std::vector<profile::Waypoint> plan = {{rad(56.9499), rad(24.1052), 12, 12, 0, {}}, {rad(56.9499), rad(24.1057), 12, 12, 0, {}},
                                                 {rad(56.9497), rad(24.1057), 12, 12, 0, {}}};
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/mission/progress"));
    Capture upload, arm, takeoff, go;
    m_conn->put(QStringLiteral("/mission"), profile::encodeMission(plan), nullptr, upload.callback());
    m_conn->put(QStringLiteral("/state/armed"), true, nullptr, arm.callback());
    m_conn->put(QStringLiteral("/command/takeoff"), json{{"altitude", 12}}, nullptr, takeoff.callback());
    m_conn->put(QStringLiteral("/state/mode"), "auto", nullptr, go.callback());
    QTRY_VERIFY(go.done);
    QVERIFY2(upload.result.ok() && arm.result.ok() && takeoff.result.ok() && go.result.ok(), qPrintable(go.result.message));
    QStringList states;
    auto progressStates = [&] {
        states.clear();
        for (const auto &args : notified) {
            if (args.at(0).toString() == QLatin1String("/mission/progress"))
                states << QString::fromStdString(args.at(1).value<json>()["state"].get<std::string>());
        }
        return states;
    };
    QTRY_VERIFY_WITH_TIMEOUT(progressStates().contains(QLatin1String("complete")), 30000);
    QVERIFY(states.contains(QLatin1String("active")));
    QCOMPARE(states.first(), QStringLiteral("idle"));
}

void TstVciSerial::unsubscribeAll()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/position"));
    m_conn->subscribe(QStringLiteral("/telemetry/speed"));
    QTRY_VERIFY(notified.count() >= 4);
    qsizetype atAnswer = -1;
    Capture c;
    m_conn->unsubscribe(QStringLiteral("*"), nullptr, [&](const VciResult &r) {
        atAnswer = notified.count();
        c.callback()(r);
    });
    QTRY_VERIFY(c.done);
    Capture g;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, g.callback());
    QTRY_VERIFY(g.done);
    QCOMPARE(notified.count(), atAnswer);
}

void TstVciSerial::timeout()
{
    m_sim->vehicle->knobs().answerDelayMs = 300;
    Capture slow, next;
    m_conn->get(QStringLiteral("/telemetry/home"), nullptr, slow.callback(), 50);
    m_conn->get(QStringLiteral("/state/armed"), nullptr, next.callback(), 5000);
    QTRY_VERIFY(slow.done);
    QCOMPARE(slow.result.error, VciResult::Error::Timeout);
    QTRY_VERIFY(next.done);
    QVERIFY2(next.result.ok(), qPrintable(next.result.message));
    QCOMPARE(next.result.body, json(false)); // its own answer, not the late /telemetry/home
}

void TstVciSerial::reconnectRestoresSubscriptions()
{
    QSignalSpy restored(m_conn.get(), &VciConnection::subscriptionsRestored);
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/battery"));
    QTRY_VERIFY(notified.count() > 0);
    QSignalSpy gone(m_sim->listener.get(), &sortie::sim::SimVciListener::clientDisconnected);
    m_transport->close(); // the operator unplugs: the vehicle sees its line hang up and forgets us
    QTRY_COMPARE(gone.count(), 1);
    QVERIFY(m_sim->session()->subscriptions().isEmpty());
    notified.clear();
    m_transport->open();
    QTRY_COMPARE(restored.count(), 1);
    QTRY_VERIFY(notified.count() > 0);
    QCOMPARE(notified.last().at(0).toString(), QStringLiteral("/telemetry/battery"));
    QCOMPARE(m_sim->session()->subscriptions(), QSet<QString>{QStringLiteral("/telemetry/battery")});
    m_transport->reopen(); // and once more without waiting for the vehicle to notice
    QTRY_COMPARE(restored.count(), 2);
}

QTEST_GUILESS_MAIN(TstVciSerial)
#include "tst_vciserial.moc"
