// The command line of sortie and the settings it keeps.
#include "AppSettings.h"
#include "LaunchOptions.h"
#include "PasswordVault.h"
#include "PrivateFiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMetaProperty>
#include <memory>
#include <vector>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace sortie::app;
using sortie::client::ServerAddress;
using sortie::secrets::PasswordVault;
using sortie::ui::AppSettings;

namespace {

LaunchOptions parsed(const QStringList &arguments)
{
    auto result = LaunchOptions::parse(QStringList{QStringLiteral("sortie")} + arguments);
    if (auto *error = std::get_if<QString>(&result))
        qFatal("unexpected error: %s", qPrintable(*error));
    return std::get<LaunchOptions>(result);
}

QString failure(const QStringList &arguments)
{
    auto result = LaunchOptions::parse(QStringList{QStringLiteral("sortie")} + arguments);
    return std::holds_alternative<QString>(result) ? std::get<QString>(result) : QString();
}

} // namespace

class TestLaunch : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QCoreApplication::setApplicationName(QStringLiteral("sortie"));
        QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
        // No keyring here, wherever the test runs (a desktop session included): a session bus
        // address where nothing listens. The keyring itself is tested by tst_keyring.
        qputenv("DBUS_SESSION_BUS_ADDRESS", "unix:path=/nonexistent/sortie-tst-launch");
        m_vault = std::make_unique<PasswordVault>(QStringLiteral("sortie-tests"));
        QTRY_COMPARE(m_vault->state(), PasswordVault::State::Unavailable);
    }

    void serverAddresses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::newRow("host:port") << "ugcs.example:4000" << "ugcs.example" << 4000;
        QTest::newRow("default port") << "localhost" << "localhost" << 3334;
        QTest::newRow("ipv4") << "127.0.0.1:3335" << "127.0.0.1" << 3335;
        QTest::newRow("ipv6") << "[::1]:3336" << "::1" << 3336;
        QTest::newRow("ipv6 no port") << "[fe80::1]" << "fe80::1" << 3334;
        QTest::newRow("tls") << "tls://ugcs.example:4000" << "ugcs.example" << 4000;
        QTest::newRow("tls ipv6") << "TLS://[::1]:3336" << "::1" << 3336;
    }

    void serverAddresses()
    {
        QFETCH(QString, text);
        QFETCH(QString, host);
        QFETCH(int, port);
        const auto result = ServerAddress::parse(text);
        QVERIFY2(std::holds_alternative<ServerAddress>(result),
                 qPrintable(std::holds_alternative<QString>(result) ? std::get<QString>(result) : QString()));
        QCOMPARE(std::get<ServerAddress>(result).host, host);
        QCOMPARE(int(std::get<ServerAddress>(result).port), port);
        QCOMPARE(ServerAddress::parse(std::get<ServerAddress>(result).toString()).index(), size_t(0));
        // tls:// is kept through the round trip; the peer (what is remembered per server) has no scheme.
        QCOMPARE(std::get<ServerAddress>(result).tls, text.startsWith(QLatin1String("tls://"), Qt::CaseInsensitive));
        QCOMPARE(std::get<ServerAddress>(ServerAddress::parse(std::get<ServerAddress>(result).toString())).tls, std::get<ServerAddress>(result).tls);
        QVERIFY(!std::get<ServerAddress>(result).peer().contains(QLatin1String("://")));
    }

    void badServerAddresses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("says");
        QTest::newRow("empty") << "" << "empty";
        QTest::newRow("port 0") << "host:0" << "not a port number";
        QTest::newRow("port too big") << "host:70000" << "not a port number";
        QTest::newRow("port words") << "host:http" << "not a port number";
        QTest::newRow("trailing colon") << "host:" << "not a port number";
        QTest::newRow("bare ipv6") << "::1:3334" << "in brackets";
        QTest::newRow("open bracket") << "[::1:3334" << "never closes";
        QTest::newRow("no host") << ":3334" << "no host";
        QTest::newRow("a url") << "http://host/x" << "give the server as host:port";
        QTest::newRow("spaces") << "my host:1" << "not a host name";
    }

    void badServerAddresses()
    {
        QFETCH(QString, text);
        QFETCH(QString, says);
        const auto result = ServerAddress::parse(text);
        QVERIFY(std::holds_alternative<QString>(result));
        QVERIFY2(std::get<QString>(result).contains(says), qPrintable(std::get<QString>(result)));
    }

    void vciEndpoints()
    {
        auto tcp = std::get<VciEndpoint>(VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:5760")));
        QCOMPARE(tcp.kind, VciEndpoint::Kind::Tcp);
        QCOMPARE(tcp.host, QStringLiteral("127.0.0.1"));
        QCOMPARE(tcp.port, quint16(5760));
        QCOMPARE(tcp.toString(), QStringLiteral("tcp://127.0.0.1:5760"));
        auto serial = std::get<VciEndpoint>(VciEndpoint::parse(QStringLiteral("serial:///dev/ttyUSB0?baud=115200")));
        QCOMPARE(serial.kind, VciEndpoint::Kind::Serial);
        QCOMPARE(serial.device, QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(serial.baud, 115200);
        auto plain = std::get<VciEndpoint>(VciEndpoint::parse(QStringLiteral("serial:///dev/pts/3")));
        QCOMPARE(plain.baud, 57600);
        QCOMPARE(plain.toString(), QStringLiteral("serial:///dev/pts/3?baud=57600"));

        const QList<std::pair<QString, QString>> bad{
            {QStringLiteral("tcp://host"), QStringLiteral("no port")},
            {QStringLiteral("tcp://:5760"), QStringLiteral("no host")},
            {QStringLiteral("udp://host:1"), QStringLiteral("start with tcp://, vci+tls:// or serial://")},
            {QStringLiteral("vci+tls://host"), QStringLiteral("needs a host and a port")},
            {QStringLiteral("vci+tls://host:1?sha256=abc"), QStringLiteral("not a SHA-256 fingerprint")},
            {QStringLiteral("vci+tls://host:1?pin=abc"), QStringLiteral("only sha256 is known")},
            {QStringLiteral("serial://"), QStringLiteral("names no serial device")},
            {QStringLiteral("serial:///dev/ttyS0?baud=-5"), QStringLiteral("positive number")},
            {QStringLiteral("serial:///dev/ttyS0?parity=even"), QStringLiteral("unknown serial option")},
            {QStringLiteral("/dev/ttyS0"), QStringLiteral("not a VCI address")},
        };
        for (const auto &[text, says] : bad) {
            const auto result = VciEndpoint::parse(text);
            QVERIFY2(std::holds_alternative<QString>(result), qPrintable(text));
            QVERIFY2(std::get<QString>(result).contains(says), qPrintable(std::get<QString>(result)));
        }
    }

    void commandLine()
    {
        LaunchOptions options = parsed({QStringLiteral("--demo")});
        QVERIFY(options.demo);
        QVERIFY(!options.server && !options.vci);
        options = parsed({QStringLiteral("--server"), QStringLiteral("ucs.local:3334"), QStringLiteral("--user"),
                          QStringLiteral("pilot"), QStringLiteral("--vci"), QStringLiteral("tcp://10.0.0.5:5760")});
        QVERIFY(!options.demo);
        QCOMPARE(options.server->toString(), QStringLiteral("ucs.local:3334"));
        QCOMPARE(options.user, QStringLiteral("pilot"));
        QCOMPARE(options.vci->toString(), QStringLiteral("tcp://10.0.0.5:5760"));
        // Over TLS: the server's certificate pinned by fingerprint (any spelling) or by its PEM file.
        const QString pin = QStringLiteral("3A:F0:00:11:22:33:44:55:66:77:88:99:AA:BB:CC:DD:EE:FF:00:11:22:33:44:55:66:77:88:99:AA:BB:CC:DD");
        options = parsed({QStringLiteral("--server"), QStringLiteral("tls://ucs.example:4433"), QStringLiteral("--server-pin"),
                          QString(pin).remove(u':').toLower(), QStringLiteral("--vci"), QStringLiteral("vci+tls://10.0.0.5:5761?sha256=") + QString(pin).remove(u':')});
        QVERIFY(options.server->tls);
        QCOMPARE(options.server->toString(), QStringLiteral("tls://ucs.example:4433"));
        QCOMPARE(options.serverPin, pin);
        QVERIFY(options.vci->tls);
        QCOMPARE(options.vci->pin, pin);
        QCOMPARE(options.vci->toString(), QStringLiteral("vci+tls://10.0.0.5:5761?sha256=") + QString(pin).remove(u':'));
        QVERIFY(failure({QStringLiteral("--server"), QStringLiteral("ucs.example:3334"), QStringLiteral("--server-pin"), pin}).contains(QStringLiteral("needs --server tls://")));
        QVERIFY(failure({QStringLiteral("--server"), QStringLiteral("tls://ucs.example"), QStringLiteral("--server-pin"), QStringLiteral("12ab")})
                    .contains(QStringLiteral("neither a SHA-256 fingerprint")));

        options = parsed({QStringLiteral("--version")});
        QVERIFY(options.exitNow);
        QCOMPARE(options.output, QStringLiteral("sortie 9.8.7\n"));
        options = parsed({QStringLiteral("--help")});
        QVERIFY(options.exitNow);
        for (const char *option : {"--demo", "--server", "--user", "--vci", "--help", "--version"})
            QVERIFY2(options.output.contains(QLatin1String(option)), option);

        QVERIFY(failure({QStringLiteral("--bogus")}).contains(QStringLiteral("Unknown option")));
        QVERIFY(failure({QStringLiteral("--server")}).contains(QStringLiteral("Missing value")));
        QVERIFY(failure({QStringLiteral("--server"), QStringLiteral("h:99999")}).startsWith(QStringLiteral("--server:")));
        QVERIFY(failure({QStringLiteral("--vci"), QStringLiteral("ftp://x:1")}).startsWith(QStringLiteral("--vci:")));
        QVERIFY(failure({QStringLiteral("--demo"), QStringLiteral("--server"), QStringLiteral("h:1")}).contains(QStringLiteral("leave out --server")));
        QVERIFY(failure({QStringLiteral("stray")}).contains(QStringLiteral("unexpected argument")));
        // An ADS-B receiver's feed: host:port, handed to the client graph.
        options = parsed({QStringLiteral("--sbs"), QStringLiteral("192.168.1.20:30003")});
        QCOMPARE(options.sbsAddress, QStringLiteral("192.168.1.20:30003"));
        QCOMPARE(options.graphOptions().sbsAddress, QStringLiteral("192.168.1.20:30003"));
        QCOMPARE(failure({QStringLiteral("--sbs"), QStringLiteral("receiver")}), QStringLiteral("--sbs: 'receiver' is not host:port"));
        // The benchmark's demo scenes: --demo with less in it.
        options = parsed({QStringLiteral("--demo-scene"), QStringLiteral("parked")});
        QVERIFY(options.demo);
        QCOMPARE(options.demoScene, QStringLiteral("parked"));
        QCOMPARE(parsed({QStringLiteral("--demo-scene"), QStringLiteral("flying")}).demoScene, QStringLiteral("flying"));
        QVERIFY(parsed({QStringLiteral("--demo")}).demoScene.isEmpty());
        QCOMPARE(failure({QStringLiteral("--demo-scene"), QStringLiteral("busy")}), QStringLiteral("--demo-scene: 'busy' is neither parked nor flying"));
        QVERIFY(failure({QStringLiteral("--demo-scene"), QStringLiteral("parked"), QStringLiteral("--server"), QStringLiteral("h:1")})
                    .contains(QStringLiteral("leave out --server")));
    }

    // Issue 36: the demo wrote to fixed /tmp/sortie-demo-autosave and -flightlogs, which another
    // local user could make first. Now its folders are in a private folder of its own.
    void theDemoWritesToAPrivateFolder()
    {
        qunsetenv("SORTIE_AUTOSAVE_DIR");
        qunsetenv("SORTIE_FLIGHTLOG_DIR");
        const auto graph = parsed({QStringLiteral("--demo")}).graphOptions();
        for (const QString &folder : {graph.autosaveDirectory, graph.flightLogDirectory}) {
            QVERIFY2(!folder.startsWith(QStringLiteral("/tmp/sortie-demo-autosave")) && !folder.startsWith(QStringLiteral("/tmp/sortie-demo-flightlogs")),
                     qPrintable(folder));
            // The folder that holds them: this user's only, made by the demo (0700) or XDG_RUNTIME_DIR's own.
            const QFileInfo parent(QFileInfo(folder).path());
            QVERIFY2(parent.isDir(), qPrintable(parent.filePath()));
            QCOMPARE(parent.ownerId(), uint(::getuid()));
            QCOMPARE(parent.permissions() & (QFileDevice::ReadGroup | QFileDevice::WriteGroup | QFileDevice::ExeGroup | QFileDevice::ReadOther
                                             | QFileDevice::WriteOther | QFileDevice::ExeOther),
                     QFileDevice::Permissions());
        }
        QCOMPARE(QFileInfo(graph.autosaveDirectory).path(), QFileInfo(graph.flightLogDirectory).path());
        // Without XDG_RUNTIME_DIR: a folder of its own made by mkdtemp, never a fixed name.
        const QByteArray runtime = qgetenv("XDG_RUNTIME_DIR");
        qunsetenv("XDG_RUNTIME_DIR");
        QString error;
        const QString made = sortie::files::privateRuntimeFolder(QStringLiteral("sortie-demo-test"), &error);
        qputenv("XDG_RUNTIME_DIR", runtime);
        if (runtime.isEmpty())
            qunsetenv("XDG_RUNTIME_DIR");
        QVERIFY2(!made.isEmpty(), qPrintable(error));
        QVERIFY2(made.startsWith(QDir::temp().filePath(QStringLiteral("sortie-demo-test-"))) && made.size() > QDir::temp().filePath(QStringLiteral("sortie-demo-test-")).size(),
                 qPrintable(made));
        QCOMPARE(QFileInfo(made).permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther | QFileDevice::ExeOther), QFileDevice::Permissions());
        QVERIFY(QDir(made).removeRecursively());
    }

    void settingsPersist()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        {
            QSettings storage(path, QSettings::IniFormat);
            AppSettings settings(&storage, m_vault.get());
            QCOMPARE(settings.lastServer(), QStringLiteral("localhost:3334"));
            QCOMPARE(settings.mapSource(), QStringLiteral("offline"));
            QSignalSpy server(&settings, &AppSettings::lastServerChanged), password(&settings, &AppSettings::passwordChanged);
            settings.setLastServer(QStringLiteral("ucs.local:3334"));
            settings.setLastServer(QStringLiteral("ucs.local:3334")); // the same again: no change
            settings.setLastUser(QStringLiteral("pilot"));
            settings.setMapSource(QStringLiteral("mbtiles"));
            settings.setMbtilesFile(QStringLiteral("/data/area.mbtiles"));
            settings.setUnits(QStringLiteral("imperial"));
            settings.setWindowGeometry(QRect(10, 20, 1000, 700));
            settings.setPassword(QStringLiteral("secret-1"));
            QCOMPARE(server.count(), 1);
            QCOMPARE(password.count(), 1);
            settings.sync();
        }
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage, m_vault.get());
        QCOMPARE(settings.lastServer(), QStringLiteral("ucs.local:3334"));
        QCOMPARE(settings.lastUser(), QStringLiteral("pilot"));
        QCOMPARE(settings.mapSource(), QStringLiteral("mbtiles"));
        QCOMPARE(settings.mbtilesFile(), QStringLiteral("/data/area.mbtiles"));
        QCOMPARE(settings.units(), QStringLiteral("imperial"));
        QCOMPARE(settings.windowGeometry(), QRect(10, 20, 1000, 700));
        // "remember" was never ticked: the password stayed in memory only.
        QVERIFY(settings.password().isEmpty());
        QVERIFY(!fileContains(path, "secret-1"));
    }

    // Each setting has its own NOTIFY signal: writing one notifies that one alone, so a binding on
    // the units is not re-evaluated when the window moves. Every writable property is written once
    // with a new value while every property's signal is watched.
    void oneSettingNotifiesItsOwn()
    {
        QTemporaryDir dir;
        QSettings storage(dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat);
        AppSettings settings(&storage, m_vault.get());
        const QMetaObject &meta = AppSettings::staticMetaObject;
        std::vector<std::unique_ptr<QSignalSpy>> spies;
        QSet<int> signalIndices;
        for (int i = meta.propertyOffset(); i < meta.propertyCount(); ++i) {
            const QMetaProperty property = meta.property(i);
            QVERIFY2(property.hasNotifySignal(), property.name());
            QVERIFY2(!signalIndices.contains(property.notifySignalIndex()),
                     qPrintable(QStringLiteral("%1 shares its NOTIFY signal").arg(QLatin1String(property.name()))));
            signalIndices.insert(property.notifySignalIndex());
            spies.push_back(std::make_unique<QSignalSpy>(&settings, property.notifySignal()));
        }
        int written = 0;
        for (int i = meta.propertyOffset(); i < meta.propertyCount(); ++i) {
            const QMetaProperty property = meta.property(i);
            if (!property.isWritable())
                continue;
            const QVariant before = property.read(&settings);
            QVariant value;
            switch (property.metaType().id()) {
            case QMetaType::QString:
                // A value each getter keeps as written (the map source knows three).
                value = QLatin1String(property.name()) == QLatin1String("mapSource")      ? QStringLiteral("xyz")
                        : QLatin1String(property.name()) == QLatin1String("colourScheme") ? QStringLiteral("sunlight")
                                                                                           : QStringLiteral("new-%1").arg(QLatin1String(property.name()));
                break;
            case QMetaType::Double: value = 0.25; break;
            case QMetaType::Bool: value = !before.toBool(); break;
            case QMetaType::QRect: value = QRect(5, 6, 700, 500); break;
            default: QFAIL(qPrintable(QStringLiteral("no new value for %1").arg(QLatin1String(property.name()))));
            }
            for (auto &spy : spies)
                spy->clear();
            QVERIFY(property.write(&settings, value));
            for (int j = meta.propertyOffset(); j < meta.propertyCount(); ++j) {
                const int expected = j == i ? 1 : 0;
                QVERIFY2(spies[size_t(j - meta.propertyOffset())]->count() == expected,
                         qPrintable(QStringLiteral("writing %1 notified %2 %3 times")
                                        .arg(QLatin1String(property.name()), QLatin1String(meta.property(j).name()))
                                        .arg(spies[size_t(j - meta.propertyOffset())]->count())));
            }
            ++written;
        }
        QCOMPARE(written, 15); // the two read-only ones follow the keyring
    }

    // Without a keyring nothing is remembered, the login view is told why, and the file never
    // holds the password, whatever the operator does.
    void noKeyringNothingRemembered()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        {
            PasswordVault vault(QStringLiteral("sortie-tests"));
            QSettings storage(path, QSettings::IniFormat);
            AppSettings settings(&storage, &vault);
            QVERIFY(!settings.canRememberPassword()); // not before the keyring has answered either
            QTRY_COMPARE(vault.state(), PasswordVault::State::Unavailable);
            QVERIFY(!vault.unavailableReason().isEmpty());
            QVERIFY(!settings.canRememberPassword());
            QVERIFY2(settings.passwordNotice().startsWith(QStringLiteral("No keyring is reachable, so the password cannot be remembered (")), qPrintable(settings.passwordNotice()));
            QVERIFY(settings.passwordNotice().contains(vault.unavailableReason()));

            QSignalSpy remember(&settings, &AppSettings::rememberPasswordChanged);
            settings.setRememberPassword(true);
            QVERIFY(!settings.rememberPassword());
            QCOMPARE(remember.count(), 1); // the ticked box springs back
            settings.rememberLogin(QStringLiteral("ucs.local:3334"), QStringLiteral("pilot"), QStringLiteral("secret-2"));
            QCOMPARE(settings.password(), QStringLiteral("secret-2")); // for this session's re-logins
            QCOMPARE(settings.lastUser(), QStringLiteral("pilot"));
            settings.sync();
            QVERIFY(!fileContains(path, "secret-2"));
        }
        PasswordVault vault(QStringLiteral("sortie-tests"));
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage, &vault);
        QTRY_COMPARE(vault.state(), PasswordVault::State::Unavailable);
        QVERIFY(settings.password().isEmpty());
        QVERIFY(!settings.rememberPassword());
        QVERIFY(!fileContains(path, "secret-2"));
    }

    // A plain-text password an older version wrote leaves the file at once, keyring or not; with no
    // keyring to take it, it is dropped and the notice says so.
    void plainPasswordErasedWithoutKeyring()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        writeOldSettings(path, true, "secret-3");
        QVERIFY(fileContains(path, "secret-3"));
        PasswordVault vault(QStringLiteral("sortie-tests"));
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage, &vault);
        QVERIFY(!fileContains(path, "secret-3")); // erased by the constructor, before any keyring answer
        QTRY_COMPARE(vault.state(), PasswordVault::State::Unavailable);
        QVERIFY2(settings.passwordNotice().contains(QStringLiteral("earlier version kept in the settings file was erased")),
                 qPrintable(settings.passwordNotice()));
        QVERIFY(settings.password().isEmpty());
        QVERIFY(!settings.rememberPassword());
        QCOMPARE(settings.lastUser(), QStringLiteral("pilot"));
        settings.sync();
        QVERIFY(!fileContains(path, "secret-3"));
    }

    // Without "remember" a password left in the file (a hand edit) is simply dropped.
    void strayPasswordDropped()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        writeOldSettings(path, false, "secret-4");
        PasswordVault vault(QStringLiteral("sortie-tests"));
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage, &vault);
        QVERIFY(!fileContains(path, "secret-4"));
        QTRY_COMPARE(vault.state(), PasswordVault::State::Unavailable);
        QVERIFY(!settings.passwordNotice().contains(QStringLiteral("earlier version")));
        QVERIFY(settings.password().isEmpty());
    }

    void entryKeysAreDistinct()
    {
        QCOMPARE(PasswordVault::entryKey(QStringLiteral("ucs.local:3334"), QStringLiteral("pilot")),
                 QStringLiteral("hci://pilot@ucs.local:3334"));
        // A user name with "@" cannot make two server/user pairs share an entry.
        QVERIFY(PasswordVault::entryKey(QStringLiteral("c"), QStringLiteral("a@b"))
                != PasswordVault::entryKey(QStringLiteral("b@c"), QStringLiteral("a")));
    }

    void unknownMapSourceFallsBackToOffline()
    {
        QTemporaryDir dir;
        QSettings storage(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        storage.setValue(QStringLiteral("map/source"), QStringLiteral("satellite-magic"));
        AppSettings settings(&storage, m_vault.get());
        QCOMPARE(settings.mapSource(), QStringLiteral("offline"));
    }

private:
    // Checked once (no keyring); the tests that watch the check itself make vaults of their own.
    std::unique_ptr<PasswordVault> m_vault;

    // The settings file as versions before the keyring wrote it: the password in plain text.
    static void writeOldSettings(const QString &path, bool remember, const char *password)
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray("[connection]\nserver=ucs.local:3334\nuser=pilot\nrememberPassword=")
                   + (remember ? "true" : "false") + "\npassword=" + password + "\n");
    }

    static bool fileContains(const QString &path, const QByteArray &text)
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) && file.readAll().contains(text);
    }
};

QTEST_GUILESS_MAIN(TestLaunch)
#include "tst_launch.moc"
