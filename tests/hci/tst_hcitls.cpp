// HCI over TLS against the simulated server serving TLS for real (certificates made by openssl at
// test time): a login over TLS, trust on first use remembered per host:port, a changed certificate
// refused naming both fingerprints before anything is sent, a pinned certificate, the system's trust
// store, a reconnect that stays secured, and plain and TLS peers that do not understand each other.
#include "CertificateFingerprint.h"
#include "CertificateStore.h"
#include "HciConnection.h"
#include "HciTestSupport.h"
#include "TestCertificates.h"
#include "TlsServerIdentity.h"

#include <QSettings>
#include <QSslConfiguration>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;
using hci::HciError;
using hci::HciSession;
using tls::TlsVerdict;

namespace {

// A simulated server with one identity, on a port of its own or a given one (a "replaced" server).
struct TlsSim
{
    explicit TlsSim(const std::optional<test::TestIdentity> &identity, quint16 port = 0)
        : world(test::SimServer::fastConfig())
        , server(world)
    {
        if (identity) {
            QString error;
            auto config = tls::loadServerIdentity(identity->certificate, identity->key, &error);
            if (!config)
                qFatal("cannot load the test identity: %s", qPrintable(error));
            server.setTls(config);
        }
        if (!server.listen(QHostAddress::LocalHost, port))
            qFatal("cannot start the simulator: %s", qPrintable(server.errorString()));
    }
    QString peer() const { return QStringLiteral("127.0.0.1:%1").arg(server.port()); }

    sim::SimWorld world;
    sim::HciServer server;
};

bool ends(HciSession &session, int ms = 10000)
{
    return test::reaches(session, HciSession::State::Disconnected, ms);
}

} // namespace

class TestHciTls : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::optional<test::TestIdentity> m_a, m_b, m_signed;
    QString m_ca;
    std::unique_ptr<QSettings> m_settings;
    std::unique_ptr<tls::CertificateStore> m_store;

    tls::TlsOptions secured(const QString &pin = {}) const { return {true, pin, m_store.get()}; }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::TestCertificates maker(m_dir.path());
        m_a = maker.selfSigned(QStringLiteral("a"));
        QVERIFY2(m_a, qPrintable(maker.error()));
        m_b = maker.selfSigned(QStringLiteral("b"));
        QVERIFY2(m_b, qPrintable(maker.error()));
        m_signed = maker.signedByCa(QStringLiteral("signed"), &m_ca);
        QVERIFY2(m_signed, qPrintable(maker.error()));
        QVERIFY(m_a->fingerprint != m_b->fingerprint);
    }

    void init()
    {
        m_settings = std::make_unique<QSettings>(m_dir.filePath(QStringLiteral("settings-%1.ini").arg(QTest::currentTestFunction())), QSettings::IniFormat);
        m_settings->clear();
        m_store = std::make_unique<tls::CertificateStore>(m_settings.get());
    }

    void fingerprintsAreWrittenAsOpensslWritesThem()
    {
        QFile file(m_a->certificate);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(tls::sha256Fingerprint(QSslCertificate(file.readAll())), m_a->fingerprint);
        const QString bare = QString(m_a->fingerprint).remove(u':').toLower();
        QCOMPARE(tls::normalizedFingerprint(QStringLiteral("sha256:") + bare), m_a->fingerprint);
        QCOMPARE(tls::normalizedFingerprint(m_a->fingerprint), m_a->fingerprint);
        QVERIFY(!tls::normalizedFingerprint(bare.left(62)));
        QVERIFY(!tls::normalizedFingerprint(bare.left(63) + u'g'));
    }

    void logsInOverTlsTrustingOnFirstUse()
    {
        TlsSim sim(m_a);
        HciSession session;
        QSignalSpy accepted(session.connection(), &hci::HciConnection::certificateAccepted);
        session.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        QVERIFY(session.connection()->isSecure());
        QCOMPARE(accepted.size(), 1);
        QCOMPARE(session.connection()->certificate().basis, TlsVerdict::Basis::FirstUse);
        QCOMPARE(session.connection()->certificate().fingerprint, m_a->fingerprint);
        QCOMPARE(m_store->remembered(sim.peer()), m_a->fingerprint);
        QCOMPARE(sim.server.sessions().loggedInCount(), 1);

        // The next time the same server is known by its certificate: nothing new to remember.
        HciSession again;
        again.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(test::reaches(again, HciSession::State::Ready));
        QCOMPARE(again.connection()->certificate().basis, TlsVerdict::Basis::Remembered);
    }

    void aReconnectStaysSecured()
    {
        TlsSim sim(m_a);
        HciSession session;
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(20), std::chrono::milliseconds(100));
        session.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        QSignalSpy resumed(&session, &HciSession::resumed);
        sim.server.dropConnections();
        QVERIFY(resumed.wait(10000));
        QVERIFY(session.connection()->isSecure());
        QCOMPARE(session.connection()->certificate().basis, TlsVerdict::Basis::Remembered);
    }

    void aChangedCertificateIsRefusedNamingBoth()
    {
        quint16 port = 0;
        {
            TlsSim first(m_a);
            port = first.server.port();
            HciSession session;
            session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
            QVERIFY(test::reaches(session, HciSession::State::Ready));
            session.close();
            QVERIFY(ends(session));
        }
        // Another server with another certificate at the same address (a replaced one, or someone in between).
        TlsSim second(m_b, port);
        HciSession session;
        QSignalSpy failed(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(failed.wait(10000));
        const auto error = failed.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Certificate);
        QVERIFY2(error.message().contains(m_a->fingerprint), qPrintable(error.message()));
        QVERIFY2(error.message().contains(m_b->fingerprint), qPrintable(error.message()));
        QCOMPARE(session.state(), HciSession::State::Disconnected); // not retried
        QCOMPARE(second.server.sessions().size(), 0);               // not even an AuthorizeHci went out
        QCOMPARE(m_store->remembered(QStringLiteral("127.0.0.1:%1").arg(port)), m_a->fingerprint); // still the first
    }

    void aPinnedCertificateIsTheOnlyOneAccepted()
    {
        TlsSim sim(m_a);
        QVERIFY(m_store->pin(sim.peer(), m_a->fingerprint));
        HciSession pinned;
        pinned.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(test::reaches(pinned, HciSession::State::Ready));
        QCOMPARE(pinned.connection()->certificate().basis, TlsVerdict::Basis::Pinned);
        QVERIFY(!m_store->remembered(sim.peer())); // a pin leaves nothing to remember

        // Pinned to another certificate (given with the address, lower case without colons): refused.
        HciSession wrong;
        QSignalSpy failed(&wrong, &HciSession::errorOccurred);
        const QString otherPin = QStringLiteral("sha256:") + QString(m_b->fingerprint).remove(u':').toLower();
        wrong.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured(otherPin));
        QVERIFY(failed.wait(10000));
        const auto error = failed.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Certificate);
        QVERIFY2(error.message().contains(m_a->fingerprint) && error.message().contains(m_b->fingerprint), qPrintable(error.message()));
    }

    void theSystemsTrustStoreIsEnough()
    {
        // The system's CA certificates, as QSslConfiguration's default holds them, plus the test CA.
        const QSslConfiguration saved = QSslConfiguration::defaultConfiguration();
        QSslConfiguration config = saved;
        auto cas = config.caCertificates();
        QFile ca(m_ca);
        QVERIFY(ca.open(QIODevice::ReadOnly));
        cas << QSslCertificate(ca.readAll());
        config.setCaCertificates(cas);
        QSslConfiguration::setDefaultConfiguration(config);
        const auto restore = qScopeGuard([&] { QSslConfiguration::setDefaultConfiguration(saved); });

        TlsSim sim(m_signed);
        HciSession session;
        session.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        QCOMPARE(session.connection()->certificate().basis, TlsVerdict::Basis::System);
        QVERIFY(!m_store->remembered(sim.peer()));
    }

    void withNowhereToRememberOnlyTrustedCertificatesPass()
    {
        TlsSim sim(m_a);
        HciSession session;
        QSignalSpy failed(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("127.0.0.1"), sim.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), tls::TlsOptions{true, {}, nullptr});
        QVERIFY(failed.wait(10000));
        const auto error = failed.first().first().value<HciError>();
        QCOMPARE(error.kind(), HciError::Kind::Certificate);
        QVERIFY2(error.message().contains(m_a->fingerprint), qPrintable(error.message()));
        QCOMPARE(sim.server.sessions().size(), 0);
    }

    void tlsToAPlainServerFailsClearly()
    {
        TlsSim plain(std::nullopt);
        HciSession session;
        session.setConnectTimeout(std::chrono::milliseconds(5000));
        QSignalSpy failed(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("127.0.0.1"), plain.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"), secured());
        QVERIFY(failed.wait(10000));
        const auto error = failed.first().first().value<HciError>();
        QVERIFY2(error.message().contains(QLatin1String("TLS")), qPrintable(error.message()));
        QVERIFY(!m_store->remembered(plain.peer()));
    }

    void plainToATlsServerDoesNotLogIn()
    {
        TlsSim secure(m_a);
        HciSession session;
        session.setConnectTimeout(std::chrono::milliseconds(5000));
        session.setRequestTimeout(std::chrono::milliseconds(3000));
        session.reconnectPolicy().setDelays(std::chrono::milliseconds(20), std::chrono::milliseconds(100));
        QSignalSpy failed(&session, &HciSession::errorOccurred);
        session.open(QStringLiteral("127.0.0.1"), secure.server.port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(failed.wait(20000));
        QCOMPARE(secure.server.sessions().size(), 0);
    }
};

QTEST_GUILESS_MAIN(TestHciTls)
#include "tst_hcitls.moc"
