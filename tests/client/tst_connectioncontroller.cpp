// ConnectionController against the simulated server: logging in, the errors an operator sees,
// the licence limit and an automatic reconnect.
#include "ConnectionController.h"
#include "SimFixture.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

using namespace sortie;
using client::ConnectionController;

class TestConnectionController : public QObject
{
    Q_OBJECT

private slots:
    void logsIn()
    {
        test::SimFixture sim;
        hci::HciSession session;
        ConnectionController connection(&session);
        QCOMPARE(connection.stateName(), QStringLiteral("Disconnected"));
        QStringList states;
        connect(&connection, &ConnectionController::stateChanged, this, [&] {
            if (states.isEmpty() || states.last() != connection.stateName())
                states.append(connection.stateName());
        });
        QSignalSpy ready(&connection, &ConnectionController::ready);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QVERIFY(connection.isBusy());
        QVERIFY(ready.wait(10000));
        QVERIFY(connection.isReady());
        QVERIFY(!connection.isBusy());
        QCOMPARE(states, (QStringList{"Connecting", "Authorizing", "LoggingIn", "Ready"}));
        QCOMPARE(connection.user(), QStringLiteral("admin"));
        QCOMPARE(connection.server(), sim.address());
        QVERIFY(connection.errorString().isEmpty());
        QCOMPARE(connection.statusDetail(), QStringLiteral("admin at %1").arg(sim.address()));

        connection.disconnectFromServer();
        QTRY_COMPARE(connection.stateName(), QStringLiteral("Disconnected"));
        QVERIFY(connection.errorString().isEmpty());
    }

    void wrongPassword()
    {
        test::SimFixture sim;
        hci::HciSession session;
        ConnectionController connection(&session);
        QSignalSpy errors(&connection, &ConnectionController::errorChanged);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("nope")));
        QTRY_COMPARE(connection.errorKind(), QStringLiteral("Authentication"));
        QVERIFY2(connection.errorString().startsWith(QStringLiteral("Wrong user name or password")), qPrintable(connection.errorString()));
        QVERIFY(!connection.errorString().contains(QStringLiteral("nope"))); // never the password
        QCOMPARE(connection.stateName(), QStringLiteral("Disconnected"));
        QVERIFY(!connection.isBusy());
    }

    void nothingListening()
    {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
        const quint16 port = probe.serverPort();
        probe.close();
        hci::HciSession session;
        ConnectionController connection(&session);
        QVERIFY(connection.connectToServer(QStringLiteral("127.0.0.1:%1").arg(port), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE(connection.errorKind(), QStringLiteral("Refused"));
        QVERIFY2(connection.errorString().contains(QStringLiteral("Is the UgCS server running")), qPrintable(connection.errorString()));
        // The hint is given once, and no sentence ends in "?.".
        QCOMPARE(connection.errorString().count(QStringLiteral("running"), Qt::CaseInsensitive), 1);
        QVERIFY2(!connection.errorString().contains(QStringLiteral("?.")), qPrintable(connection.errorString()));
        QVERIFY(connection.statusDetail().isEmpty());
    }

    void inputIsCheckedFirst()
    {
        hci::HciSession session;
        ConnectionController connection(&session);
        QVERIFY(!connection.connectToServer(QStringLiteral("my server:3334"), QStringLiteral("admin"), {}));
        QCOMPARE(connection.errorKind(), QStringLiteral("Input"));
        QVERIFY(connection.errorString().contains(QStringLiteral("not usable")));
        QVERIFY(!connection.connectToServer(QStringLiteral("localhost:3334"), QStringLiteral("  "), {}));
        QCOMPARE(connection.errorString(), QStringLiteral("Enter a user name."));
        QCOMPARE(session.state(), hci::HciSession::State::Disconnected);
    }

    void licenceLimit()
    {
        auto config = test::SimFixture::defaults();
        config.maxSessions = 1;
        test::SimFixture sim(config);
        hci::HciSession first, second;
        ConnectionController a(&first), b(&second);
        QSignalSpy ready(&a, &ConnectionController::ready);
        QVERIFY(a.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QVERIFY(ready.wait(10000));
        QVERIFY(b.connectToServer(sim.address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob")));
        QTRY_COMPARE(b.errorKind(), QStringLiteral("Licence"));
        QVERIFY2(b.errorString().contains(QStringLiteral("licence")), qPrintable(b.errorString()));
    }

    void reconnectsByItself()
    {
        test::SimFixture sim;
        hci::HciSession session;
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(50), std::chrono::milliseconds(200));
        ConnectionController connection(&session);
        QSignalSpy ready(&connection, &ConnectionController::ready);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QVERIFY(ready.wait(10000));
        QStringList states;
        connect(&connection, &ConnectionController::stateChanged, this, [&] { states.append(connection.stateName()); });
        sim.server.dropConnections();
        QTRY_VERIFY(states.contains(QStringLiteral("Reconnecting")));
        QTRY_COMPARE(connection.stateName(), QStringLiteral("Ready"));
        QVERIFY(connection.errorString().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestConnectionController)
#include "tst_connectioncontroller.moc"
