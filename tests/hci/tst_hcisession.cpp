// HciSession against the simulated server over loopback: login good and bad, operator-readable errors,
// re-attach after a drop, a new session when the old one expired, subscriptions that survive both,
// logout with the clientId, and no password in any log line.
#include "HciConnection.h"
#include "HciSubscription.h"
#include "HciTestSupport.h"
#include "Messages.pb.h"

#include <QTcpServer>
#include <QtTest>

using namespace sortie;
using hci::HciError;
using hci::HciSession;
namespace pb = com::ugcs::ucs::proto;

namespace {

QStringList g_log;
QtMessageHandler g_previous = nullptr;

void capture(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    g_log.append(QString::fromLatin1(context.category ? context.category : "") + u' ' + message);
    if (g_previous && type >= QtWarningMsg)
        g_previous(type, context, message);
}

pb::EventSubscriptionWrapper telemetrySubscription()
{
    pb::EventSubscriptionWrapper w;
    w.mutable_telemetrysubscription();
    return w;
}

} // namespace

class TestHciSession : public QObject
{
    Q_OBJECT

private slots:
    void init()
    {
        g_log.clear();
        QLoggingCategory::setFilterRules(QStringLiteral("sortie.*=true"));
        g_previous = qInstallMessageHandler(capture);
    }

    void cleanup()
    {
        qInstallMessageHandler(g_previous);
        QLoggingCategory::setFilterRules(QString());
        // The passwords these tests use appear in no log line, whatever happened.
        for (const QString &line : std::as_const(g_log)) {
            QVERIFY2(!line.contains(QLatin1String("s3cret-bob")), qPrintable(line));
            QVERIFY2(!line.contains(QLatin1String("wrong-pass")), qPrintable(line));
        }
    }

    void logsInThroughEveryState()
    {
        test::SimServer sim;
        HciSession session;
        QList<HciSession::State> states;
        connect(&session, &HciSession::stateChanged, this, [&](HciSession::State s) { states.append(s); });
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        QCOMPARE(states, (QList<HciSession::State>{HciSession::State::Connecting, HciSession::State::Authorizing,
                                                   HciSession::State::LoggingIn, HciSession::State::Ready}));
        QVERIFY(session.clientId() > 0);
        QCOMPARE(session.user().login(), std::string("bob"));
        QVERIFY(!session.user().has_password());
        QVERIFY(sim.server.sessions().find(session.clientId())->user);
        QVERIFY(!g_log.filter(QStringLiteral("logged in as bob")).isEmpty());
    }

    void badPasswordIsAnAuthenticationError()
    {
        test::SimServer sim;
        HciSession session;
        QSignalSpy errors(&session, &HciSession::errorOccurred);
        QSignalSpy reconnects(&session, &HciSession::reconnectScheduled);
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("wrong-pass"));
        QVERIFY(errors.wait());
        QCOMPARE(session.state(), HciSession::State::Disconnected);
        const auto error = errors.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Authentication);
        QVERIFY2(error.message().contains(QLatin1String("'admin'")), qPrintable(error.message()));
        QVERIFY(error.message().contains(QLatin1String("Invalid login or password")));
        QCOMPARE(session.lastError().kind(), HciError::Kind::Authentication);
        // No reconnect follows a refused login. A reconnect is decided when the connection's end
        // is handled; the server seeing it closed proves that moment has passed.
        QTRY_COMPARE(sim.server.connectionCount(), 0);
        QCOMPARE(session.state(), HciSession::State::Disconnected);
        QCOMPARE(reconnects.count(), 0);
    }

    void closedPortIsRefused()
    {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
        const quint16 port = probe.serverPort();
        probe.close();
        HciSession session;
        QSignalSpy errors(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(errors.wait());
        const auto error = errors.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Refused);
        QVERIFY(error.message().contains(QString::number(port)));
        QCOMPARE(session.state(), HciSession::State::Disconnected);
    }

    void unknownHostIsUnreachable()
    {
        HciSession session;
        session.setConnectTimeout(std::chrono::milliseconds(3000));
        QSignalSpy errors(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("no-such-host.invalid"), 3334, QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(errors.wait(15000));
        QCOMPARE(errors.first().first().value<HciError>().kind(), HciError::Kind::Unreachable);
    }

    void licenceLimitIsReportedAsSuch()
    {
        auto config = test::SimServer::fastConfig();
        config.maxSessions = 1;
        test::SimServer sim(config);
        HciSession first, second;
        first.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(first, HciSession::State::Ready));
        QSignalSpy errors(&second, &HciSession::errorOccurred);
        second.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(errors.wait());
        const auto error = errors.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Licence);
        QCOMPARE(error.code(), 1001);
        QVERIFY(error.detail() && error.detail()->has_licenseconstrainterrordetail());
    }

    void sendBeforeReadyFailsAtOnce()
    {
        HciSession session;
        pb::GetObjectListRequest r;
        r.set_clientid(0);
        r.set_objecttype("Vehicle");
        auto reply = test::keep(session.send(r));
        QVERIFY(!reply->isFinished()); // not synchronously: the caller connects first
        QVERIFY(test::finishes(reply.get()));
        QCOMPARE(reply->error().kind(), HciError::Kind::Disconnected);
        QVERIFY(reply->error().message().contains(QLatin1String("GetObjectListRequest")));
    }

    void reattachesAfterADropAndKeepsSubscriptions()
    {
        test::SimServer sim;
        HciSession session;
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(20), std::chrono::milliseconds(200));
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        const int clientId = session.clientId();
        auto *telemetry = session.subscribe(telemetrySubscription());
        int events = 0;
        connect(telemetry, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) { events += e.has_telemetryevent(); });
        QTRY_VERIFY(events > 3);
        const int firstServerId = telemetry->serverId();

        QSignalSpy resumed(&session, &HciSession::resumed);
        QSignalSpy states(&session, &HciSession::stateChanged);
        QSignalSpy activity(telemetry, &hci::HciSubscription::activeChanged);
        sim.server.dropConnections();
        QVERIFY(resumed.wait());
        QCOMPARE(states.first().first().value<HciSession::State>(), HciSession::State::Reconnecting);
        QCOMPARE(activity.first().first().toBool(), false);
        QCOMPARE(resumed.first().first().toBool(), true); // re-attached: same session, locks kept
        QCOMPARE(session.clientId(), clientId);
        QCOMPARE(session.state(), HciSession::State::Ready);
        QTRY_VERIFY(telemetry->isActive());
        QVERIFY(telemetry->serverId() != firstServerId);
        // The server holds exactly the one fresh subscription: the old one was ended, not leaked.
        QTRY_COMPARE(sim.server.sessions().find(clientId)->subscriptions.size(), size_t(1));
        events = 0;
        QTRY_VERIFY(events > 3);
    }

    void startsANewSessionWhenTheOldOneExpired()
    {
        test::SimServer sim;
        HciSession session;
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(50), std::chrono::milliseconds(200));
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        const int oldId = session.clientId();
        auto *telemetry = session.subscribe(telemetrySubscription());
        QTRY_VERIFY(telemetry->isActive());

        QSignalSpy resumed(&session, &HciSession::resumed);
        sim.server.dropConnections();
        QCOMPARE(sim.server.expireSessions(), 1); // gone before the client comes back
        QVERIFY(resumed.wait());
        QCOMPARE(resumed.first().first().toBool(), false);
        QVERIFY(session.clientId() != oldId);
        QCOMPARE(session.user().login(), std::string("bob"));
        QTRY_VERIFY(telemetry->isActive());
        QVERIFY(!g_log.filter(QStringLiteral("would not re-attach")).isEmpty());
    }

    void keepsTryingWhileTheServerIsDown()
    {
        auto sim = std::make_unique<test::SimServer>();
        const quint16 port = sim->port();
        HciSession session;
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(20), std::chrono::milliseconds(100));
        session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        QSignalSpy attempts(&session, &HciSession::reconnectScheduled);
        sim.reset(); // the server goes away entirely
        QTRY_VERIFY(attempts.size() >= 3);
        QCOMPARE(session.state(), HciSession::State::Reconnecting);
        // Backoff: each delay at least the one before.
        for (int i = 1; i < attempts.size(); ++i)
            QVERIFY(attempts.at(i).at(1).toInt() >= attempts.at(i - 1).at(1).toInt());
        session.close();
        QCOMPARE(session.state(), HciSession::State::Disconnected);
    }

    void aSubscriberMayDeleteTheSessionFromAnEvent()
    {
        test::SimServer sim;
        auto *session = new HciSession;
        session->open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(*session, HciSession::State::Ready));
        QPointer<HciSession> watch(session);
        auto *telemetry = session->subscribe(telemetrySubscription());
        connect(telemetry, &hci::HciSubscription::received, this, [session] { delete session; });
        QTRY_VERIFY(!watch); // deleted mid-delivery, and the decoding loop noticed
        QTRY_COMPARE(sim.server.connectionCount(), 0);
    }

    void logoutCarriesTheClientId()
    {
        test::SimServer sim;
        HciSession session;
        QSignalSpy reconnects(&session, &HciSession::reconnectScheduled);
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        const int clientId = session.clientId();
        QVERIFY(sim.server.sessions().find(clientId));
        session.close();
        QVERIFY(test::reaches(session, HciSession::State::Disconnected));
        // The server ended that very session: the LogoutRequest named it.
        QVERIFY(!sim.server.sessions().find(clientId));
        QCOMPARE(session.clientId(), -1);
        // And nothing reconnects: the connection's end, which would decide it, is behind us once
        // the server has seen it.
        QTRY_COMPARE(sim.server.connectionCount(), 0);
        QCOMPARE(session.state(), HciSession::State::Disconnected);
        QCOMPARE(reconnects.count(), 0);
    }
};

QTEST_MAIN(TestHciSession)
#include "tst_hcisession.moc"
