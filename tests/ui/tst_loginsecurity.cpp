// The login page and how the password travels, in the program's window offscreen against the
// simulator: "Secure" logs in over TLS (the simulator serving a certificate openssl made for the
// test) and shows the certificate's fingerprint; a server that is not this computer, plain, is
// asked about once (no: nothing is sent and the next try asks again; yes: remembered per server).
#include "ClientWindow.h"
#include "TestCertificates.h"
#include "TlsServerIdentity.h"

#include <QQuickItem>
#include <QTcpServer>
#include <QtTest>

using namespace sortie;

class TestLoginSecurity : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    static QQuickItem *findItem(QQuickItem *root, const QString &name)
    {
        for (QQuickItem *child : root->childItems()) {
            if (child->objectName() == name)
                return child;
            if (QQuickItem *found = findItem(child, name))
                return found;
        }
        return nullptr;
    }
    static QQuickItem *find(test::ClientWindow &app, const char *name)
    {
        QQuickItem *item = findItem(app.window()->contentItem(), QString::fromLatin1(name));
        if (!item)
            qWarning("no item named %s", name);
        return item;
    }
    static QPoint centreOf(QQuickItem *item) { return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint(); }
    static bool clickable(QQuickItem *item) { return item && item->isVisible() && item->isEnabled() && item->width() > 0; }
    static void click(test::ClientWindow &app, const char *name)
    {
        QQuickItem *item = find(app, name);
        QVERIFY(item);
        QTRY_VERIFY2(clickable(item), name);
        QTest::mouseClick(app.window(), Qt::LeftButton, {}, centreOf(item));
    }
    static void setText(test::ClientWindow &app, const char *name, const QString &text)
    {
        QQuickItem *item = find(app, name);
        QVERIFY(item);
        item->setProperty("text", text);
    }
    static QString text(test::ClientWindow &app, const char *name)
    {
        QQuickItem *item = find(app, name);
        return item ? item->property("text").toString() : QString();
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void secureLogsInOverTlsAndShowsTheFingerprint()
    {
        test::TestCertificates maker(m_dir.path());
        const auto identity = maker.selfSigned(QStringLiteral("login"));
        QVERIFY2(identity, qPrintable(maker.error()));
        QString error;
        test::ClientWindow::Options options;
        options.vciVehicles = 0;
        options.hciTls = tls::loadServerIdentity(identity->certificate, identity->key, &error);
        QVERIFY2(options.hciTls, qPrintable(error));
        test::ClientWindow app(options);
        QVERIFY2(app.isReady(), qPrintable(app.error()));
        app.showPage(0);

        setText(app, "serverField", QStringLiteral("127.0.0.1:%1").arg(app.server().port()));
        QCOMPARE(find(app, "secureCheck")->property("checked").toBool(), false);
        click(app, "secureCheck");
        QTRY_COMPARE(text(app, "serverField"), QStringLiteral("tls://127.0.0.1:%1").arg(app.server().port()));
        QVERIFY(find(app, "secureCheck")->property("checked").toBool());
        setText(app, "userField", QStringLiteral("admin"));
        setText(app, "passwordField", QStringLiteral("admin"));
        click(app, "connectButton");
        QTRY_VERIFY_WITH_TIMEOUT(app.connection().isReady(), 60000);  // a bound, not a goal: ASan's slow unwinder makes a TLS handshake take seconds
        app.showPage(0); // a login moves on to the mission page: back to see what the login page says
        QTRY_VERIFY(find(app, "certificateNote")->isVisible());
        QVERIFY(!find(app, "cleartextQuestion")->isVisible()); // TLS: nothing to ask
        QVERIFY2(text(app, "certificateNote").contains(identity->fingerprint), qPrintable(text(app, "certificateNote")));
        QVERIFY(text(app, "certificateNote").contains(QLatin1String("remembered")));
        QCOMPARE(app.connection().certificates().remembered(QStringLiteral("127.0.0.1:%1").arg(app.server().port())), identity->fingerprint);

        // Unticking takes the prefix off again.
        app.connection().disconnectFromServer();
        QTRY_VERIFY(clickable(find(app, "secureCheck")));
        click(app, "secureCheck");
        QTRY_COMPARE(text(app, "serverField"), QStringLiteral("127.0.0.1:%1").arg(app.server().port()));
    }

    void aPasswordInClearToAnotherComputerIsAskedAboutOnce()
    {
        test::ClientWindow::Options options;
        options.vciVehicles = 0;
        test::ClientWindow app(options);
        QVERIFY2(app.isReady(), qPrintable(app.error()));
        app.showPage(0);
        // 192.0.2.1 (TEST-NET-1, RFC 5737) is no computer's: a connection to it never completes.
        const QString far = QStringLiteral("192.0.2.1:3334");
        setText(app, "serverField", far);
        setText(app, "userField", QStringLiteral("admin"));
        setText(app, "passwordField", QStringLiteral("admin"));
        click(app, "connectButton");
        QTRY_VERIFY(find(app, "cleartextQuestion")->isVisible());
        QVERIFY2(text(app, "cleartextQuestionText").contains(QLatin1String("192.0.2.1:3334")), qPrintable(text(app, "cleartextQuestionText")));
        QCOMPARE(app.connection().stateName(), QStringLiteral("Disconnected")); // nothing sent while asking

        // No: nothing goes out, the page says so, and nothing is remembered.
        click(app, "refuseCleartextButton");
        QTRY_VERIFY(!find(app, "cleartextQuestion")->isVisible());
        QCOMPARE(app.connection().stateName(), QStringLiteral("Disconnected"));
        QVERIFY2(text(app, "loginMessage").contains(QLatin1String("not sent")), qPrintable(text(app, "loginMessage")));
        click(app, "connectButton");
        QTRY_VERIFY(find(app, "cleartextQuestion")->isVisible()); // asked again

        // Yes: the login starts, and this server is not asked about again.
        click(app, "sendInClearButton");
        QTRY_VERIFY(!find(app, "cleartextQuestion")->isVisible());
        QCOMPARE(app.connection().stateName(), QStringLiteral("Connecting"));
        app.connection().disconnectFromServer();
        QTRY_COMPARE(app.connection().stateName(), QStringLiteral("Disconnected"));
        QTRY_VERIFY(clickable(find(app, "connectButton")));
        click(app, "connectButton");
        QTRY_COMPARE(app.connection().stateName(), QStringLiteral("Connecting"));
        QVERIFY(!find(app, "cleartextQuestion")->isVisible());
        app.connection().disconnectFromServer();

        // This computer is never asked about.
        QTRY_VERIFY(clickable(find(app, "connectButton")));
        setText(app, "serverField", QStringLiteral("127.0.0.1:%1").arg(app.server().port()));
        click(app, "connectButton");
        QTRY_VERIFY_WITH_TIMEOUT(app.connection().isReady(), 60000);  // a bound, not a goal: ASan's slow unwinder makes a TLS handshake take seconds
        QVERIFY(!find(app, "cleartextQuestion")->isVisible());
        QVERIFY(text(app, "certificateNote").isEmpty());
    }
};

QTEST_MAIN(TestLoginSecurity)
#include "tst_loginsecurity.moc"
