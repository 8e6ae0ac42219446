// The remembered password against a real Secret Service: run by CTest through run-with-keyring.sh,
// which gives this process a D-Bus session of its own with GNOME Keyring unlocked in a throw-away
// home folder. After every step the settings file's bytes are searched for the password; the last
// test drives the real login view (offscreen).
#include "ClientGraph.h"
#include "ConnectionController.h"
#include "AppSettings.h"
#include "PasswordVault.h"
#include "QuickScene.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QQuickItem>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using sortie::secrets::PasswordVault;
using sortie::ui::AppSettings;

namespace {

const QString kService = QStringLiteral("sortie-tests");
const QString kServer = QStringLiteral("ucs.local:3334");
const QString kUser = QStringLiteral("pilot");

// One start of the program: a settings file and a vault of its own, as main() makes them.
struct Start
{
    explicit Start(const QString &path)
        : storage(path, QSettings::IniFormat)
        , settings(&storage, &vault)
    {
    }
    PasswordVault vault{kService};
    QSettings storage;
    AppSettings settings;
};

} // namespace

class TestKeyring : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        sortie::test::useSoftwareRendering();
        PasswordVault vault(kService);
        QTRY_VERIFY(vault.state() != PasswordVault::State::Checking);
        QVERIFY2(vault.state() == PasswordVault::State::Available,
                 qPrintable(QStringLiteral("no Secret Service (%1): run this test through tests/ui/run-with-keyring.sh")
                                .arg(vault.unavailableReason())));
    }

    void init()
    {
        QVERIFY(m_dir.isValid());
        m_path = m_dir.filePath(QStringLiteral("sortie.ini"));
        QFile::remove(m_path);
    }

    void cleanup()
    {
        // Every test leaves the keyring as it found it.
        PasswordVault vault(kService);
        QTRY_VERIFY(vault.state() == PasswordVault::State::Available);
        for (const auto &[server, user] : {std::pair{kServer, kUser}, std::pair{kServer, QStringLiteral("observer")},
                                           std::pair{QStringLiteral("other.host:3334"), kUser}}) {
            QSignalSpy removed(&vault, &PasswordVault::passwordRemoved);
            vault.remove(server, user);
            QVERIFY(removed.wait(5000));
        }
    }

    // Remember → a restart reads the password back from the keyring; the file never holds it.
    void rememberedAcrossRestart()
    {
        {
            Start first(m_path);
            QTRY_VERIFY(first.settings.canRememberPassword());
            QVERIFY(first.settings.passwordNotice().isEmpty());
            first.settings.setRememberPassword(true);
            QVERIFY(first.settings.rememberPassword());
            QSignalSpy written(&first.vault, &PasswordVault::passwordWritten);
            first.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-secret-1"));
            first.settings.loginSucceeded();
            QVERIFY(written.wait(5000));
            QCOMPARE(written.first().at(0).toString(), kServer);
            QCOMPARE(written.first().at(1).toString(), kUser);
            first.settings.sync();
            QVERIFY(!fileContains("kr-secret-1"));
        }
        // Where it went, seen by another Secret Service client (libsecret's secret-tool).
        QCOMPARE(secretTool(PasswordVault::entryKey(kServer, kUser)), QStringLiteral("kr-secret-1"));

        Start restarted(m_path);
        QSignalSpy recalled(&restarted.settings, &AppSettings::passwordRecalled);
        QVERIFY(recalled.wait(5000));
        QVERIFY(restarted.settings.rememberPassword());
        QCOMPARE(restarted.settings.lastServer(), kServer);
        QCOMPARE(restarted.settings.lastUser(), kUser);
        QCOMPARE(restarted.settings.password(), QStringLiteral("kr-secret-1"));
        restarted.settings.sync();
        QVERIFY(!fileContains("kr-secret-1"));
    }

    // Entries are per server and user: another user, or the same user elsewhere, gets nothing.
    void keyedByServerAndUser()
    {
        {
            Start first(m_path);
            QTRY_VERIFY(first.settings.canRememberPassword());
            first.settings.setRememberPassword(true);
            QSignalSpy written(&first.vault, &PasswordVault::passwordWritten);
            first.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-secret-2"));
            first.settings.loginSucceeded();
            QVERIFY(written.wait(5000));
            // The observer logs in without a password of their own remembered yet.
            first.settings.setLastUser(QStringLiteral("observer"));
            first.settings.sync();
            QVERIFY(!fileContains("kr-secret-2"));
        }
        {
            Start restarted(m_path);
            QSignalSpy read(&restarted.vault, &PasswordVault::passwordRead);
            QVERIFY(read.wait(5000));
            QCOMPARE(read.first().at(1).toString(), QStringLiteral("observer"));
            QVERIFY(read.first().at(2).toString().isEmpty());
            QVERIFY(restarted.settings.password().isEmpty());
            restarted.settings.sync();
            QVERIFY(!fileContains("kr-secret-2"));
        }
        PasswordVault vault(kService);
        QTRY_VERIFY(vault.state() == PasswordVault::State::Available);
        QSignalSpy read(&vault, &PasswordVault::passwordRead);
        vault.read(QStringLiteral("other.host:3334"), kUser);
        vault.read(kServer, kUser);
        QTRY_COMPARE(read.count(), 2);
        QVERIFY(read.at(0).at(2).toString().isEmpty());
        QCOMPARE(read.at(1).at(2).toString(), QStringLiteral("kr-secret-2"));
        QVERIFY(!fileContains("kr-secret-2"));
    }

    // Un-ticking "remember" removes the password from the keyring.
    void untickingRemoves()
    {
        Start start(m_path);
        QTRY_VERIFY(start.settings.canRememberPassword());
        start.settings.setRememberPassword(true);
        QSignalSpy written(&start.vault, &PasswordVault::passwordWritten);
        start.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-secret-3"));
        start.settings.loginSucceeded();
        QVERIFY(written.wait(5000));
        QCOMPARE(secretTool(PasswordVault::entryKey(kServer, kUser)), QStringLiteral("kr-secret-3"));

        QSignalSpy removed(&start.vault, &PasswordVault::passwordRemoved);
        start.settings.setRememberPassword(false);
        QVERIFY(!start.settings.rememberPassword());
        QVERIFY(removed.wait(5000));
        QVERIFY(secretTool(PasswordVault::entryKey(kServer, kUser)).isEmpty());
        start.settings.sync();
        QVERIFY(!fileContains("kr-secret-3"));

        Start restarted(m_path);
        QTRY_VERIFY(restarted.settings.canRememberPassword());
        QVERIFY(!restarted.settings.rememberPassword());
        QVERIFY(restarted.settings.password().isEmpty());
    }

    // A plain-text password from an older version moves to the keyring and leaves the file.
    void plainPasswordMigrates()
    {
        QFile old(m_path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("[connection]\nserver=ucs.local:3334\nuser=pilot\nrememberPassword=true\npassword=kr-secret-4\n");
        old.close();
        QVERIFY(fileContains("kr-secret-4"));
        {
            Start first(m_path);
            QVERIFY(!fileContains("kr-secret-4")); // out of the file before the keyring has answered
            QSignalSpy written(&first.vault, &PasswordVault::passwordWritten);
            QVERIFY(written.wait(5000));
            QVERIFY2(first.settings.passwordNotice().contains(QStringLiteral("is now in the keyring")),
                     qPrintable(first.settings.passwordNotice()));
            QVERIFY(first.settings.rememberPassword());
            QCOMPARE(first.settings.password(), QStringLiteral("kr-secret-4"));
            first.settings.sync();
            QVERIFY(!fileContains("kr-secret-4"));
        }
        QCOMPARE(secretTool(PasswordVault::entryKey(kServer, kUser)), QStringLiteral("kr-secret-4"));
        Start restarted(m_path);
        QSignalSpy recalled(&restarted.settings, &AppSettings::passwordRecalled);
        QVERIFY(recalled.wait(5000));
        QCOMPARE(restarted.settings.password(), QStringLiteral("kr-secret-4"));
        QVERIFY(restarted.settings.passwordNotice().isEmpty()); // said once, on the start that moved it
        restarted.settings.sync();
        QVERIFY(!fileContains("kr-secret-4"));
    }

    // Without "remember" a password found in the file is dropped, not moved.
    void strayPasswordNotMigrated()
    {
        QFile old(m_path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("[connection]\nserver=ucs.local:3334\nuser=pilot\nrememberPassword=false\npassword=kr-secret-5\n");
        old.close();
        Start start(m_path);
        QVERIFY(!fileContains("kr-secret-5"));
        QTRY_VERIFY(start.settings.canRememberPassword());
        PasswordVault vault(kService);
        QSignalSpy read(&vault, &PasswordVault::passwordRead);
        QTRY_VERIFY(vault.state() == PasswordVault::State::Available);
        vault.read(kServer, kUser);
        QVERIFY(read.wait(5000));
        QVERIFY(read.first().at(2).toString().isEmpty());
        QVERIFY(start.settings.password().isEmpty());
    }

    // A password the server refused never replaces the remembered one; the next accepted one does.
    void aRefusedPasswordIsNotRemembered()
    {
        {
            Start first(m_path);
            QTRY_VERIFY(first.settings.canRememberPassword());
            first.settings.setRememberPassword(true);
            QSignalSpy written(&first.vault, &PasswordVault::passwordWritten);
            first.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-secret-7"));
            first.settings.loginSucceeded();
            QVERIFY(written.wait(5000));
            first.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-typo-7"));  // refused: no loginSucceeded
            first.settings.sync();
        }
        QCOMPARE(secretTool(PasswordVault::entryKey(kServer, kUser)), QStringLiteral("kr-secret-7"));
        Start restarted(m_path);
        QSignalSpy recalled(&restarted.settings, &AppSettings::passwordRecalled);
        QVERIFY(recalled.wait(5000));
        QCOMPARE(restarted.settings.password(), QStringLiteral("kr-secret-7"));
    }

    // The real login view: the keyring's answer fills the password field after the page is up, the
    // box is enabled and ticked, nothing to say beside it; un-ticking it by mouse removes the entry.
    void loginViewRecallsThePassword()
    {
        {
            Start first(m_path);
            QTRY_VERIFY(first.settings.canRememberPassword());
            first.settings.setRememberPassword(true);
            QSignalSpy written(&first.vault, &PasswordVault::passwordWritten);
            first.settings.rememberLogin(kServer, kUser, QStringLiteral("kr-secret-6"));
            first.settings.loginSucceeded();
            QVERIFY(written.wait(5000));
            first.settings.sync();
        }
        Start restarted(m_path);
        QTemporaryDir clientDir;
        QSettings clientStorage(QDir(clientDir.path()).filePath(QStringLiteral("client.ini")), QSettings::IniFormat);
        sortie::client::ClientGraph client(&clientStorage, {});
        sortie::test::QuickScene scene("import Sortie.Ui\nLoginPage { theme: Theme {} }", QSize(800, 600),
                                       {{QStringLiteral("appSettings"), QVariant::fromValue(&restarted.settings)},
                                        {QStringLiteral("graph"), QVariant::fromValue(&client)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *password = scene.find<QQuickItem>(QStringLiteral("passwordField"));
        auto *user = scene.find<QQuickItem>(QStringLiteral("userField"));
        auto *remember = scene.find<QQuickItem>(QStringLiteral("rememberCheck"));
        auto *notice = scene.find<QQuickItem>(QStringLiteral("rememberNotice"));
        QVERIFY(password && user && remember && notice);
        QTRY_COMPARE(password->property("text").toString(), QStringLiteral("kr-secret-6"));
        QCOMPARE(user->property("text").toString(), kUser);
        QVERIFY(remember->isEnabled());
        QVERIFY(remember->property("checked").toBool());
        QVERIFY(!notice->isVisible());

        QSignalSpy removed(&restarted.vault, &PasswordVault::passwordRemoved);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, remember->mapToScene(QPointF(10, remember->height() / 2)).toPoint());
        QVERIFY(removed.wait(5000));
        QVERIFY(!remember->property("checked").toBool());
        QVERIFY(!restarted.settings.rememberPassword());
        QVERIFY(secretTool(PasswordVault::entryKey(kServer, kUser)).isEmpty());

        // Ticked again by mouse, then turned off by the settings: the box follows the settings.
        QSignalSpy written(&restarted.vault, &PasswordVault::passwordWritten);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, remember->mapToScene(QPointF(10, remember->height() / 2)).toPoint());
        QVERIFY(written.wait(5000));
        QVERIFY(remember->property("checked").toBool());
        restarted.settings.setRememberPassword(false);
        QVERIFY(!remember->property("checked").toBool());
        QVERIFY(removed.wait(5000));
        restarted.settings.sync();
        QVERIFY(!fileContains("kr-secret-6"));
    }

private:
    bool fileContains(const QByteArray &text) const
    {
        QFile file(m_path);
        return file.open(QIODevice::ReadOnly) && file.readAll().contains(text);
    }

    // The entry as libsecret's command line tool sees it (QtKeychain's attributes: server = the
    // service, user = the entry key); empty when there is none.
    static QString secretTool(const QString &key)
    {
        QProcess tool;
        tool.start(QStringLiteral("secret-tool"), {QStringLiteral("lookup"), QStringLiteral("server"), kService,
                                                   QStringLiteral("user"), key});
        if (!tool.waitForFinished(10000))
            return QStringLiteral("<secret-tool did not finish>");
        return QString::fromUtf8(tool.readAllStandardOutput());
    }

    QTemporaryDir m_dir;
    QString m_path;
};

QTEST_MAIN(TestKeyring)
#include "tst_keyring.moc"
