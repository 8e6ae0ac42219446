// When the operator is asked before a password goes in clear: the loopback rule (127.0.0.0/8, ::1,
// "localhost"), TLS never asked about, a yes remembered per server (host:port) in the settings and a
// no not remembered; and ConnectionController sending nothing while it asks.
#include "CleartextConsent.h"
#include "ConnectionController.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie;
using client::CleartextConsent;
using client::ConnectionController;
using client::ServerAddress;

namespace {

ServerAddress address(const QString &text)
{
    const auto parsed = ServerAddress::parse(text);
    if (!std::holds_alternative<ServerAddress>(parsed))
        qFatal("not an address: %s", qPrintable(text));
    return std::get<ServerAddress>(parsed);
}

} // namespace

class TestCleartextConsent : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void loopbackIsThisComputerOnly_data()
    {
        QTest::addColumn<QString>("server");
        QTest::addColumn<bool>("loopback");
        QTest::newRow("127.0.0.1") << "127.0.0.1:3334" << true;
        QTest::newRow("127.0.0.2") << "127.0.0.2:3334" << true; // all of 127.0.0.0/8 is loopback
        QTest::newRow("127.255.255.254") << "127.255.255.254" << true;
        QTest::newRow("::1") << "[::1]:3334" << true;
        QTest::newRow("mapped 127") << "[::ffff:127.0.0.1]:3334" << true;
        QTest::newRow("localhost") << "localhost:3334" << true;
        QTest::newRow("LOCALHOST") << "LOCALHOST" << true;
        QTest::newRow("under .localhost") << "ugcs.localhost:3334" << true;
        QTest::newRow("128.0.0.1") << "128.0.0.1:3334" << false;
        QTest::newRow("126.255.255.255") << "126.255.255.255:3334" << false;
        QTest::newRow("private network") << "10.0.0.5:3334" << false;
        QTest::newRow("test-net") << "192.0.2.1:3334" << false;
        QTest::newRow("any address") << "0.0.0.0:3334" << false;
        QTest::newRow("::2") << "[::2]:3334" << false;
        QTest::newRow("link-local v6") << "[fe80::1]:3334" << false;
        QTest::newRow("mapped private") << "[::ffff:10.0.0.1]:3334" << false;
        QTest::newRow("a name") << "ugcs.example:3334" << false;
        QTest::newRow("localhost as a label") << "localhost.example.com:3334" << false;
        QTest::newRow("127 in a name") << "127.0.0.1.example.com:3334" << false;
    }

    void loopbackIsThisComputerOnly()
    {
        QFETCH(QString, server);
        QFETCH(bool, loopback);
        QCOMPARE(address(server).isLoopback(), loopback);
        CleartextConsent consent(nullptr);
        QCOMPARE(consent.mustAsk(address(server)), !loopback);
        QVERIFY(!consent.mustAsk(address(QStringLiteral("tls://") + server))); // over TLS nothing is in clear
    }

    void aYesIsRememberedPerServer()
    {
        const QString file = m_dir.filePath(QStringLiteral("consent.ini"));
        {
            QSettings settings(file, QSettings::IniFormat);
            CleartextConsent consent(&settings);
            QVERIFY(consent.mustAsk(address(QStringLiteral("10.0.0.5:3334"))));
            consent.allow(address(QStringLiteral("10.0.0.5:3334")));
            QVERIFY(!consent.mustAsk(address(QStringLiteral("10.0.0.5:3334"))));
            QVERIFY(consent.mustAsk(address(QStringLiteral("10.0.0.5:3335")))); // another server
            QVERIFY(consent.mustAsk(address(QStringLiteral("10.0.0.6:3334"))));
        }
        QSettings again(file, QSettings::IniFormat); // the next run
        QVERIFY(!CleartextConsent(&again).mustAsk(address(QStringLiteral("10.0.0.5:3334"))));
        QVERIFY(!CleartextConsent(&again).mustAsk(address(QStringLiteral("10.0.0.5")))); // 3334 by default
    }

    void theControllerSendsNothingWhileItAsks()
    {
        QSettings settings(m_dir.filePath(QStringLiteral("controller.ini")), QSettings::IniFormat);
        hci::HciSession session;
        ConnectionController connection(&session, &settings);
        QSignalSpy question(&connection, &ConnectionController::cleartextQuestionChanged);
        QVERIFY(connection.connectToServer(QStringLiteral("192.0.2.1:3334"), QStringLiteral("admin"), QStringLiteral("pw-never-shown")));
        QVERIFY(connection.isAskingCleartext());
        QCOMPARE(question.size(), 1);
        QVERIFY(connection.cleartextQuestion().contains(QLatin1String("192.0.2.1:3334")));
        QVERIFY(!connection.cleartextQuestion().contains(QLatin1String("pw-never-shown")));
        QCOMPARE(session.state(), hci::HciSession::State::Disconnected);

        connection.answerCleartext(false);
        QVERIFY(!connection.isAskingCleartext());
        QCOMPARE(connection.errorKind(), QStringLiteral("Cleartext"));
        QCOMPARE(session.state(), hci::HciSession::State::Disconnected);
        QVERIFY(CleartextConsent(&settings).mustAsk(address(QStringLiteral("192.0.2.1:3334"))));

        QVERIFY(connection.connectToServer(QStringLiteral("192.0.2.1:3334"), QStringLiteral("admin"), QStringLiteral("pw-never-shown")));
        QVERIFY(connection.isAskingCleartext());
        connection.answerCleartext(true);
        QVERIFY(!connection.isAskingCleartext());
        QCOMPARE(session.state(), hci::HciSession::State::Connecting);
        QVERIFY(!CleartextConsent(&settings).mustAsk(address(QStringLiteral("192.0.2.1:3334"))));
        connection.disconnectFromServer();
        QCOMPARE(session.state(), hci::HciSession::State::Disconnected);

        // The address decides the Secure box.
        QVERIFY(connection.isSecureAddress(QStringLiteral(" tls://host:1")));
        QCOMPARE(connection.withSecurity(QStringLiteral("host:1"), true), QStringLiteral("tls://host:1"));
        QCOMPARE(connection.withSecurity(QStringLiteral("tls://host:1"), false), QStringLiteral("host:1"));
        QCOMPARE(connection.withSecurity(QStringLiteral("tls://host:1"), true), QStringLiteral("tls://host:1"));
    }
};

QTEST_GUILESS_MAIN(TestCleartextConsent)
#include "tst_cleartextconsent.moc"
