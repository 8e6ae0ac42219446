// VciConnection over TCP against a simulated vehicle: requests, notifications, subscriptions,
// one request at a time, timeouts and late answers, reconnects, and the vehicle's own requests.
#include "VciEndpoint.h"
#include "VciProfile.h"
#include "VciTestStreams.h"
#include "VciTestSupport.h"
#include "VciTransport.h"

#include <QBuffer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using nlohmann::json;
using namespace sortie::vci;
using namespace sortie::vci::test;

class TstVciConnection : public QObject
{
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void getIdentity();
    void subscribeAndReceiveNotifications();
    void putArmModeAndRefusals();
    void uploadMissionAndSeeItFlown();
    void unsubscribeAll();
    void statusIsRepeated();
    void requestsGoOneAtATime();
    void notifyWhileGetOutstanding();
    void timeoutAndLateAnswer();
    void reconnectRestoresSubscriptions();
    void malformedOutputIsSurvived();
    void notConnectedAndInvalidRequests();
    void vehicleRequestsAreAnswered();
    void endpoints();
    void aBodyThatIsAllThereIsReadOverManyTurns();

private:
    void connectTo(SimVehicle &sim);
    std::unique_ptr<SimVehicle> m_sim;
    std::unique_ptr<QTcpSocket> m_socket;
    std::unique_ptr<VciConnection> m_conn;
};

void TstVciConnection::init()
{
    sortie::sim::SimVciOptions options;
    options.telemetryRate = 50;
    options.timeScale = 10;
    m_sim = std::make_unique<SimVehicle>(options);
    QVERIFY(m_sim->listener->listen(0));
    m_conn = std::make_unique<VciConnection>();
    connectTo(*m_sim);
}

void TstVciConnection::cleanup()
{
    m_conn.reset();
    m_socket.reset();
    m_sim.reset();
}

void TstVciConnection::connectTo(SimVehicle &sim)
{
    m_socket = std::make_unique<QTcpSocket>();
    QSignalSpy connected(m_socket.get(), &QTcpSocket::connected);
    m_socket->connectToHost(QHostAddress::LocalHost, sim.listener->port());
    QVERIFY(connected.wait(5000));
    m_conn->setDevice(m_socket.get());
    QVERIFY(m_conn->isAttached());
}

void TstVciConnection::getIdentity()
{
    Capture c;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, c.callback());
    QVERIFY(!c.done); // never inside the call
    QTRY_VERIFY(c.done);
    QVERIFY2(c.result.ok(), qPrintable(c.result.message));
    QCOMPARE(c.result.status(), VciStatus::Ok);
    QCOMPARE(c.result.body["id"], json("vci-1"));
    QCOMPARE(c.result.body["profile"], json("sortie-vci/1"));

    Capture missing;
    m_conn->get(QStringLiteral("/no/such/thing"), nullptr, missing.callback());
    QTRY_VERIFY(missing.done);
    QCOMPARE(missing.result.error, VciResult::Error::Status);
    QCOMPARE(missing.result.status(), VciStatus::NotImplemented);
    QVERIFY2(missing.result.message.contains(QLatin1String("no resource /no/such/thing")), qPrintable(missing.result.message));
}

void TstVciConnection::subscribeAndReceiveNotifications()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    Capture c;
    m_conn->subscribe(QStringLiteral("/telemetry/position"), nullptr, c.callback());
    QTRY_VERIFY(c.done);
    QVERIFY2(c.result.ok(), qPrintable(c.result.message));
    QTRY_VERIFY(notified.count() >= 5);
    const json body = notified.last().at(1).value<json>();
    QCOMPARE(notified.last().at(0).toString(), QStringLiteral("/telemetry/position"));
    QVERIFY(std::abs(body["latitude"].get<double>() - rad(56.9496)) < 1e-6);
    QVERIFY(body["time"].get<int64_t>() > 1600000000000);
    QCOMPARE(m_conn->subscriptions(), QStringList{QStringLiteral("/telemetry/position")});

    Capture refused;
    m_conn->subscribe(QStringLiteral("/vehicle"), nullptr, refused.callback());
    QTRY_VERIFY(refused.done);
    QCOMPARE(refused.result.status(), VciStatus::NotImplemented);
    QCOMPARE(m_conn->subscriptions(), QStringList{QStringLiteral("/telemetry/position")}); // not remembered
}

void TstVciConnection::putArmModeAndRefusals()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    Capture sub, arm, takeoff, land, badMode, badBody;
    m_conn->subscribe(QStringLiteral("/state/armed"), nullptr, sub.callback());
    m_conn->subscribe(QStringLiteral("/state/mode"));
    m_conn->put(QStringLiteral("/state/armed"), true, nullptr, arm.callback());
    QTRY_VERIFY(arm.done);
    QVERIFY2(arm.result.ok(), qPrintable(arm.result.message));
    QVERIFY(m_sim->vehicle->model().state().armed);
    qsizetype from = 0; // look only at notifications after this one
    auto sawValue = [&](const char *uri, const json &value) {
        for (qsizetype i = from; i < notified.count(); ++i) {
            const auto &args = notified.at(i);
            if (args.at(0).toString() == QLatin1String(uri) && args.at(1).value<json>() == value)
                return true;
        }
        return false;
    };
    QTRY_VERIFY(sawValue("/state/armed", true));

    m_conn->put(QStringLiteral("/command/takeoff"), json{{"altitude", 5.0}}, nullptr, takeoff.callback());
    QTRY_VERIFY(takeoff.done);
    QVERIFY2(takeoff.result.ok(), qPrintable(takeoff.result.message));
    QTRY_VERIFY(sawValue("/state/mode", "takeoff"));
    QTRY_VERIFY_WITH_TIMEOUT(sawValue("/state/mode", "hold"), 10000); // reached 5 m

    from = notified.count();
    m_conn->put(QStringLiteral("/state/mode"), "land", nullptr, land.callback());
    QTRY_VERIFY(land.done);
    QVERIFY(land.result.ok());
    QTRY_VERIFY_WITH_TIMEOUT(sawValue("/state/armed", false), 10000); // touched down and disarmed

    m_conn->put(QStringLiteral("/state/mode"), "warp", nullptr, badMode.callback());
    m_conn->put(QStringLiteral("/command/land"), nullptr, nullptr, badBody.callback());
    QTRY_VERIFY(badMode.done && badBody.done);
    QCOMPARE(badMode.result.status(), VciStatus::BadRequest);
    QVERIFY(badMode.result.message.contains(QLatin1String("return_home")));
    QCOMPARE(badBody.result.status(), VciStatus::BadRequest);
    QVERIFY2(badBody.result.message.contains(QLatin1String("already on the ground")), qPrintable(badBody.result.message));
}

void TstVciConnection::uploadMissionAndSeeItFlown()
{
    namespace profile = sortie::vci::profile;
    const std::vector<profile::Waypoint> plan = {{rad(56.9500), rad(24.1052), 15, 10, 0, {}}, {rad(56.9500), rad(24.1060), 15, 10, 0, {}}};
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    Capture upload, readBack, arm, takeoff, autoMode;
    m_conn->subscribe(QStringLiteral("/mission/progress"));
    m_conn->put(QStringLiteral("/mission"), profile::encodeMission(plan), nullptr, upload.callback());
    m_conn->get(QStringLiteral("/mission"), nullptr, readBack.callback());
    QTRY_VERIFY(readBack.done);
    QVERIFY2(upload.result.ok(), qPrintable(upload.result.message));
    std::string error;
    const auto got = profile::decodeMission(readBack.result.body, &error);
    QVERIFY2(got.has_value(), error.c_str());
    QCOMPARE(got->size(), size_t(2));
    QVERIFY(std::abs((*got)[1].longitude - rad(24.1060)) < 1e-9);

    m_conn->put(QStringLiteral("/state/armed"), true, nullptr, arm.callback());
    m_conn->put(QStringLiteral("/command/takeoff"), 10.0, nullptr, takeoff.callback());
    m_conn->put(QStringLiteral("/state/mode"), "auto", nullptr, autoMode.callback());
    QTRY_VERIFY(autoMode.done);
    QVERIFY2(arm.result.ok() && takeoff.result.ok() && autoMode.result.ok(), qPrintable(autoMode.result.message));
    auto lastProgress = [&] {
        for (qsizetype i = notified.count() - 1; i >= 0; --i) {
            if (notified.at(i).at(0).toString() == QLatin1String("/mission/progress"))
                return notified.at(i).at(1).value<json>();
        }
        return json();
    };
    QTRY_VERIFY_WITH_TIMEOUT(lastProgress().value("state", "") == "complete", 20000);
    QCOMPARE(lastProgress()["reached"], json(2));
    const auto &s = m_sim->vehicle->model().state();
    QVERIFY(std::abs(s.longitude - 24.1060) < 1e-4);

    Capture bad;
    m_conn->put(QStringLiteral("/mission"), json{{"waypoints", {{{"latitude", 9.0}, {"longitude", 0.1}, {"altitude", 5}}}}},
                nullptr, bad.callback());
    QTRY_VERIFY(bad.done);
    QCOMPARE(bad.result.status(), VciStatus::BadRequest);
    QVERIFY2(bad.result.message.contains(QLatin1String("waypoints[0].latitude")), qPrintable(bad.result.message));
}

void TstVciConnection::unsubscribeAll()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/position"));
    m_conn->subscribe(QStringLiteral("/telemetry/attitude"));
    QTRY_VERIFY(notified.count() >= 10);
    qsizetype atAnswer = -1;
    Capture c;
    m_conn->unsubscribe(QStringLiteral("*"), nullptr, [&](const VciResult &r) {
        atAnswer = notified.count();
        c.callback()(r);
    });
    QVERIFY(m_conn->subscriptions().isEmpty());
    QTRY_VERIFY(c.done);
    QVERIFY(c.result.ok());
    // Nothing may follow the answer: two round trips later the count is the same.
    Capture g1, g2;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, g1.callback());
    QTRY_VERIFY(g1.done);
    m_conn->get(QStringLiteral("/vehicle"), nullptr, g2.callback());
    QTRY_VERIFY(g2.done);
    QCOMPARE(notified.count(), atAnswer);
    QVERIFY(m_sim->session()->subscriptions().isEmpty());
}

void TstVciConnection::statusIsRepeated()
{
    // Unchanged status still arrives now and then, so a silent vehicle can be told from a quiet one.
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/state/armed"));
    m_conn->subscribe(QStringLiteral("/mission"));
    QTRY_VERIFY_WITH_TIMEOUT(notified.count() >= 4, 5000);
    int armed = 0, mission = 0;
    for (const auto &args : notified) {
        armed += args.at(0).toString() == QLatin1String("/state/armed");
        mission += args.at(0).toString() == QLatin1String("/mission");
    }
    QVERIFY(armed >= 3);
    QCOMPARE(mission, 1); // the mission list only once, after SUBSCRIBE: it has not changed
}

void TstVciConnection::requestsGoOneAtATime()
{
    m_sim->vehicle->knobs().answerDelayMs = 20;
    std::vector<int> order;
    for (int i = 0; i < 5; ++i)
        m_conn->get(i % 2 ? QStringLiteral("/state/mode") : QStringLiteral("/state/armed"), nullptr,
                    [&order, i](const VciResult &r) { if (r.ok()) order.push_back(i); });
    QCOMPARE(m_conn->pendingRequests(), 5);
    QCOMPARE(m_conn->stats().requestsSent, quint64(1)); // the rest wait for the answer
    QTRY_COMPARE(order.size(), size_t(5));
    QCOMPARE(order, (std::vector<int>{0, 1, 2, 3, 4}));
    QCOMPARE(m_conn->pendingRequests(), 0);
}

void TstVciConnection::notifyWhileGetOutstanding()
{
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/speed"));
    QTRY_VERIFY(notified.count() >= 1);
    m_sim->vehicle->knobs().answerDelayMs = 300;
    const qsizetype before = notified.count();
    qsizetype duringGet = -1;
    Capture c;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, [&](const VciResult &r) {
        duringGet = notified.count() - before;
        c.callback()(r);
    });
    QTRY_VERIFY(c.done);
    QVERIFY2(c.result.ok(), qPrintable(c.result.message));
    QCOMPARE(c.result.body["id"], json("vci-1"));
    QVERIFY2(duringGet >= 3, qPrintable(QString::number(duringGet))); // 50 Hz for 300 ms
}

void TstVciConnection::timeoutAndLateAnswer()
{
    m_sim->vehicle->knobs().answerDelayMs = 400;
    Capture slow, next;
    m_conn->get(QStringLiteral("/state/armed"), nullptr, slow.callback(), 100);
    m_conn->get(QStringLiteral("/vehicle"), nullptr, next.callback(), 5000);
    QTRY_VERIFY(slow.done);
    QCOMPARE(slow.result.error, VciResult::Error::Timeout);
    QVERIFY(slow.result.message.contains(QLatin1String("GET /state/armed")));
    m_sim->vehicle->knobs().answerDelayMs = 0;
    // The late "false" for /state/armed must not be taken as the answer to GET /vehicle.
    QTRY_VERIFY(next.done);
    QVERIFY2(next.result.ok(), qPrintable(next.result.message));
    QCOMPARE(next.result.body["id"], json("vci-1"));
    QCOMPARE(m_conn->stats().lateReplies, quint64(1));
    QCOMPARE(slow.calls, 1);
}

void TstVciConnection::reconnectRestoresSubscriptions()
{
    m_conn->setDevice(nullptr);
    m_socket.reset();
    VciTransport transport(*VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(m_sim->listener->port())));
    transport.setRetryDelays(20, 200);
    connect(&transport, &VciTransport::opened, m_conn.get(), [this](QIODevice *d) { m_conn->setDevice(d); });
    connect(&transport, &VciTransport::lost, m_conn.get(), [this](const QString &why) { m_conn->setDevice(nullptr, why); });
    QSignalSpy restored(m_conn.get(), &VciConnection::subscriptionsRestored);
    QSignalSpy detached(m_conn.get(), &VciConnection::detached);
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    m_conn->subscribe(QStringLiteral("/telemetry/battery")); // not connected yet: remembered
    transport.open();
    QTRY_COMPARE(restored.count(), 1);
    QTRY_VERIFY(notified.count() > 0);

    Capture pending;
    m_sim->vehicle->knobs().answerDelayMs = 500;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, pending.callback());
    QTRY_COMPARE(m_sim->session()->subscriptions().size(), 1);
    m_sim->listener->dropConnections();
    QTRY_VERIFY(pending.done);
    QCOMPARE(pending.result.error, VciResult::Error::ConnectionLost);
    QTRY_COMPARE(detached.count(), 1);
    m_sim->vehicle->knobs().answerDelayMs = 0;
    QTRY_COMPARE(restored.count(), 2);
    notified.clear();
    QTRY_VERIFY(notified.count() > 0);
    QCOMPARE(notified.last().at(0).toString(), QStringLiteral("/telemetry/battery"));
    QTRY_COMPARE(m_sim->session()->subscriptions(), QSet<QString>{QStringLiteral("/telemetry/battery")});
    m_conn->setDevice(nullptr);
}

void TstVciConnection::malformedOutputIsSurvived()
{
    m_sim->vehicle->knobs().malformedEvery = 4;
    QSignalSpy notified(m_conn.get(), &VciConnection::notified);
    QSignalSpy errors(m_conn.get(), &VciConnection::protocolError);
    m_conn->subscribe(QStringLiteral("/telemetry/position"));
    QTRY_VERIFY(errors.count() >= 3);
    QTRY_VERIFY(notified.count() >= 9);
    for (const auto &args : notified)
        QVERIFY(args.at(1).value<json>().contains("latitude"));
    Capture c;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, c.callback());
    QTRY_VERIFY(c.done);
    QVERIFY(c.result.ok());
}

void TstVciConnection::notConnectedAndInvalidRequests()
{
    VciConnection lonely;
    Capture a, b, c;
    lonely.get(QStringLiteral("/vehicle"), nullptr, a.callback());
    lonely.get(QStringLiteral("no-slash"), nullptr, b.callback());
    lonely.request(VciVerb::Get, QStringLiteral("*"), nullptr, nullptr, c.callback());
    QTRY_VERIFY(a.done && b.done && c.done);
    QCOMPARE(a.result.error, VciResult::Error::NotConnected);
    QCOMPARE(b.result.error, VciResult::Error::InvalidRequest);
    QCOMPARE(c.result.error, VciResult::Error::InvalidRequest);

    // A request whose context is gone never calls back.
    Capture d;
    auto *context = new QObject;
    m_conn->get(QStringLiteral("/vehicle"), context, d.callback());
    delete context;
    Capture e;
    m_conn->get(QStringLiteral("/vehicle"), nullptr, e.callback());
    QTRY_VERIFY(e.done);
    QVERIFY(!d.done);
}

void TstVciConnection::vehicleRequestsAreAnswered()
{
    // A hand-driven peer, to send what the simulated vehicle never would.
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, server.serverPort());
    QVERIFY(server.waitForNewConnection(5000));
    QTcpSocket *peer = server.nextPendingConnection();
    QTRY_COMPARE(client.state(), QAbstractSocket::ConnectedState);
    VciConnection conn;
    conn.setDevice(&client);
    conn.setRequestHandler(VciVerb::Get, [](const VciMessage &m) {
        return VciReply{200, json{{"asked", m.uri}}};
    });
    QSignalSpy notified(&conn, &VciConnection::notified);
    peer->write("NOTIFY /n VCI/1.0\r\nContent-Type: application/json\r\n\r\n7 "
                "PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n{}"
                "GET /who VCI/1.0\r\n\r\n"
                "FETCH /x VCI/1.0\r\n\r\n"
                "GET nonsense\r\n\r\n");
    QByteArray answers;
    auto parsed = [&] {
        answers += peer->readAll();
        return parseAll(answers.toStdString());
    };
    QTRY_COMPARE(parsed().size(), size_t(4)); // the NOTIFY is not answered
    const auto r = parsed();
    QCOMPARE(std::get<VciMessage>(r[0]).status, 501); // PUT: no handler
    QCOMPARE(std::get<VciMessage>(r[1]).status, 200);
    QCOMPARE(std::get<VciMessage>(r[1]).body["asked"], json("/who"));
    QCOMPARE(std::get<VciMessage>(r[2]).status, 501); // unknown verb
    QCOMPARE(std::get<VciMessage>(r[3]).status, 400); // malformed
    QVERIFY(std::get<VciMessage>(r[3]).body.contains("error"));
    QCOMPARE(notified.count(), 1);
    QCOMPARE(notified.at(0).at(1).value<json>(), json(7));
}

void TstVciConnection::endpoints()
{
    auto tcp = VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:5760"));
    QVERIFY(tcp);
    QCOMPARE(tcp->kind, VciEndpoint::Kind::Tcp);
    QCOMPARE(tcp->port, quint16(5760));
    auto serial = VciEndpoint::parse(QStringLiteral("serial:/dev/ttyUSB0?baud=57600&parity=even&stopbits=2&databits=7&flow=hardware"));
    QVERIFY(serial);
    QCOMPARE(serial->device, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(serial->baudRate, 57600);
    QCOMPARE(serial->parity, QSerialPort::EvenParity);
    QCOMPARE(serial->stopBits, QSerialPort::TwoStop);
    QCOMPARE(serial->dataBits, QSerialPort::Data7);
    QCOMPARE(serial->flowControl, QSerialPort::HardwareControl);
    QCOMPARE(VciEndpoint::parse(serial->toString())->toString(), serial->toString());
    QCOMPARE(VciEndpoint::parse(QStringLiteral("serial:///dev/ttyS1"))->device, QStringLiteral("/dev/ttyS1"));
    QString error;
    QVERIFY(!VciEndpoint::parse(QStringLiteral("serial:/dev/x?baud=fast"), &error));
    QVERIFY(error.contains(QLatin1String("baud=fast")));
    QVERIFY(!VciEndpoint::parse(QStringLiteral("tcp://host"), &error));
    QVERIFY(!VciEndpoint::parse(QStringLiteral("udp://h:1"), &error));
    QVERIFY(!VciEndpoint::parse(QStringLiteral("serial:/dev/x?speed=1"), &error));
    QVERIFY(error.contains(QLatin1String("speed")));
}

QTEST_GUILESS_MAIN(TstVciConnection)
#include "tst_vciconnection.moc"

// A 12 MiB notification that is all there at once (a socket's buffer after a stall; a QBuffer here,
// so that none of it arrives late): the connection reads it over many turns of the event loop, at
// most kReadTurnBytes each, so a timer (the window's repaint) keeps running meanwhile.
void TstVciConnection::aBodyThatIsAllThereIsReadOverManyTurns()
{
    json big = json::array();
    while (big.dump().size() < size_t(12 << 20))
        for (int i = 0; i < 10000; ++i)
            big.push_back({{"latitude", 56.95 + i * 1e-6}, {"longitude", 24.1}, {"altitude", 40.5}});
    const std::string body = big.dump();
    QByteArray stream = QByteArray::fromStdString("NOTIFY /mission/route VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: "
                                                  + std::to_string(body.size()) + "\r\n\r\n" + body);
    QBuffer device(&stream);
    QVERIFY(device.open(QIODevice::ReadOnly));
    VciConnection connection;
    int turns = 0;
    QTimer repaint;
    repaint.setInterval(0);
    connect(&repaint, &QTimer::timeout, this, [&] { ++turns; });
    QSignalSpy notified(&connection, &VciConnection::notified);
    repaint.start();
    connection.setDevice(&device);
    QVERIFY(notified.wait(30000));
    QCOMPARE(notified.first().at(0).toString(), QStringLiteral("/mission/route"));
    QVERIFY2(turns >= int(stream.size() / VciConnection::kReadTurnBytes) - 1, qPrintable(QString::number(turns)));
}
