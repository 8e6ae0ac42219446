// A vehicle over VCI on TLS, end to end: VciVehicleLink and Vehicle against a simulated VCI vehicle
// serving TLS with a certificate openssl made for the test. Trust on first use remembered, a changed
// certificate refused naming both fingerprints, a pin in the address (vci+tls://...?sha256=), the
// addresses themselves, and sortie-sim's fleet saying vci+tls:// when it serves TLS.
#include "CertificateStore.h"
#include "CommandCatcher.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "TestCertificates.h"
#include "TlsServerIdentity.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;
using namespace sortie::vehicle;
using tls::TlsVerdict;

class TestVciTls : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::optional<test::TestIdentity> m_a, m_b;
    std::unique_ptr<QSettings> m_settings;
    std::unique_ptr<tls::CertificateStore> m_store;
    std::unique_ptr<sim::SimVciVehicle> m_simVehicle;
    std::unique_ptr<sim::SimVciListener> m_listener;

    std::optional<QSslConfiguration> identity(const test::TestIdentity &id)
    {
        QString error;
        auto config = tls::loadServerIdentity(id.certificate, id.key, &error);
        if (!config)
            qWarning("%s", qPrintable(error));
        return config;
    }
    void serve(const test::TestIdentity &id, quint16 port = 0)
    {
        m_listener = std::make_unique<sim::SimVciListener>(m_simVehicle.get());
        m_listener->setTls(identity(id));
        QVERIFY(m_listener->isSecure());
        QVERIFY(m_listener->listen(port));
    }
    std::unique_ptr<VciVehicleLink> linkTo(const QString &url, tls::CertificateStore *store)
    {
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(url, &error);
        if (!endpoint)
            qWarning("%s", qPrintable(error));
        auto link = std::make_unique<VciVehicleLink>(*endpoint);
        link->transport()->setRetryDelays(20, 200);
        link->transport()->setCertificateStore(store);
        return link;
    }
    QString url() const { return QStringLiteral("vci+tls://127.0.0.1:%1").arg(m_listener->port()); }
    QString peer() const { return QStringLiteral("127.0.0.1:%1").arg(m_listener->port()); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::TestCertificates maker(m_dir.path());
        m_a = maker.selfSigned(QStringLiteral("vehicle-a"));
        QVERIFY2(m_a, qPrintable(maker.error()));
        m_b = maker.selfSigned(QStringLiteral("vehicle-b"));
        QVERIFY2(m_b, qPrintable(maker.error()));
    }

    void init()
    {
        m_settings = std::make_unique<QSettings>(m_dir.filePath(QStringLiteral("%1.ini").arg(QTest::currentTestFunction())), QSettings::IniFormat);
        m_settings->clear();
        m_store = std::make_unique<tls::CertificateStore>(m_settings.get());
        sim::SimVciOptions options;
        options.id = QStringLiteral("vci-9");
        options.telemetryRate = 25;
        options.timeScale = 10;
        m_simVehicle = std::make_unique<sim::SimVciVehicle>(options);
    }

    void cleanup()
    {
        m_listener.reset();
        m_simVehicle.reset();
    }

    void addresses()
    {
        QString error;
        auto plain = vci::VciEndpoint::parse(QStringLiteral("tcp://10.0.0.7:5760"), &error);
        QVERIFY(plain && !plain->tls);
        auto secure = vci::VciEndpoint::parse(QStringLiteral("vci+tls://vehicle.example:5760"), &error);
        QVERIFY2(secure, qPrintable(error));
        QVERIFY(secure->tls);
        QCOMPARE(secure->host, QStringLiteral("vehicle.example"));
        QCOMPARE(secure->toString(), QStringLiteral("vci+tls://vehicle.example:5760"));
        const QString bare = QString(m_a->fingerprint).remove(u':');
        auto pinned = vci::VciEndpoint::parse(QStringLiteral("vci+tls://vehicle.example:5760?sha256=") + bare.toLower(), &error);
        QVERIFY2(pinned, qPrintable(error));
        QCOMPARE(pinned->pinnedSha256, m_a->fingerprint);
        QCOMPARE(vci::VciEndpoint::parse(pinned->toString())->pinnedSha256, m_a->fingerprint); // round trip
        QVERIFY(!vci::VciEndpoint::parse(QStringLiteral("vci+tls://vehicle.example:5760?sha256=12ab"), &error));
        QVERIFY2(error.contains(QLatin1String("not a SHA-256")), qPrintable(error));
        QVERIFY(!vci::VciEndpoint::parse(QStringLiteral("tcp://vehicle.example:5760?sha256=") + bare, &error));
    }

    void flysOverTlsTrustingOnFirstUse()
    {
        serve(*m_a);
        auto link = linkTo(url(), m_store.get());
        Vehicle vehicle(link.get());
        QSignalSpy notes(link.get(), &VehicleLink::errorOccurred);
        link->start();
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.isConnected(), 10000);
        QTRY_COMPARE(vehicle.id(), QStringLiteral("vci-9"));
        QCOMPARE(link->transport()->certificate().basis, TlsVerdict::Basis::FirstUse);
        QCOMPARE(notes.size(), 1); // the fingerprint trusted on first use is shown
        QVERIFY2(notes.first().first().toString().contains(m_a->fingerprint), qPrintable(notes.first().first().toString()));
        QCOMPARE(m_store->remembered(peer()), m_a->fingerprint);
        QTRY_VERIFY(vehicle.position().isValid()); // telemetry, decrypted
        test::CommandCatcher arm;
        link->arm(true, arm.callback());
        QTRY_VERIFY(arm.done);
        QVERIFY2(arm.result.ok, qPrintable(arm.result.message));
        QTRY_VERIFY(vehicle.armed());
        QCOMPARE(m_listener->sessions().size(), 1);

        // Again later: the remembered certificate.
        link.reset();
        auto again = linkTo(url(), m_store.get());
        Vehicle second(again.get());
        QSignalSpy quiet(again.get(), &VehicleLink::errorOccurred);
        again->start();
        QTRY_VERIFY_WITH_TIMEOUT(second.isConnected(), 10000);
        QCOMPARE(again->transport()->certificate().basis, TlsVerdict::Basis::Remembered);
        QCOMPARE(quiet.size(), 0); // nothing new to show
    }

    void aChangedCertificateIsRefusedNamingBoth()
    {
        serve(*m_a);
        const quint16 port = m_listener->port();
        m_store->remember(peer(), m_a->fingerprint); // trusted on an earlier day
        m_listener.reset();
        serve(*m_b, port); // the same address, another certificate
        auto link = linkTo(url(), m_store.get());
        Vehicle vehicle(link.get());
        QSignalSpy errors(link.get(), &VehicleLink::errorOccurred);
        link->start();
        QVERIFY(errors.wait(10000));
        const QString message = errors.first().first().toString();
        QVERIFY2(message.contains(m_a->fingerprint) && message.contains(m_b->fingerprint), qPrintable(message));
        QVERIFY(!vehicle.isConnected());
        QVERIFY(link->transport()->device() == nullptr); // nothing was handed to the protocol
        QCOMPARE(m_store->remembered(peer()), m_a->fingerprint);
    }

    void aPinInTheAddressIsTheOnlyCertificateAccepted()
    {
        serve(*m_a);
        auto pinned = linkTo(url() + QStringLiteral("?sha256=") + m_a->fingerprint, nullptr);
        Vehicle vehicle(pinned.get());
        pinned->start();
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.isConnected(), 10000);
        QCOMPARE(pinned->transport()->certificate().basis, TlsVerdict::Basis::Pinned);

        auto wrong = linkTo(url() + QStringLiteral("?sha256=") + m_b->fingerprint, nullptr);
        Vehicle other(wrong.get());
        QSignalSpy errors(wrong.get(), &VehicleLink::errorOccurred);
        wrong->start();
        QVERIFY(errors.wait(10000));
        QVERIFY2(errors.first().first().toString().contains(QLatin1String("pinned")), qPrintable(errors.first().first().toString()));
        QVERIFY(!other.isConnected());
    }

    void theSimulatorsFleetServesTls()
    {
        sim::SimVciFleetOptions options;
        options.count = 2;
        options.firstPort = 0;
        options.tls = identity(*m_a);
        sim::SimVciFleet fleet(options);
        QString error;
        QVERIFY2(fleet.start(&error), qPrintable(error));
        const QStringList lines = fleet.describe();
        QCOMPARE(lines.size(), 2);
        QVERIFY2(lines.first().contains(QLatin1String(" vci+tls://127.0.0.1:")), qPrintable(lines.first()));
        auto link = linkTo(lines.first().section(u' ', 1, 1), m_store.get());
        Vehicle vehicle(link.get());
        link->start();
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.isConnected(), 10000);
        QTRY_COMPARE(vehicle.id(), QStringLiteral("vci-1"));
    }
};

QTEST_GUILESS_MAIN(TestVciTls)
#include "tst_vcitls.moc"
