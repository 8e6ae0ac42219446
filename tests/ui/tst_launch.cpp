// The command line of sortie and the settings it keeps.
#include "AppSettings.h"
#include "LaunchOptions.h"

#include <QCoreApplication>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie::app;
using sortie::client::ServerAddress;
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
            {QStringLiteral("udp://host:1"), QStringLiteral("start with tcp:// or serial://")},
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
    }

    void settingsPersist()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        {
            QSettings storage(path, QSettings::IniFormat);
            AppSettings settings(&storage);
            QCOMPARE(settings.lastServer(), QStringLiteral("localhost:3334"));
            QCOMPARE(settings.mapSource(), QStringLiteral("offline"));
            QSignalSpy changed(&settings, &AppSettings::changed);
            settings.setLastServer(QStringLiteral("ucs.local:3334"));
            settings.setLastUser(QStringLiteral("pilot"));
            settings.setMapSource(QStringLiteral("mbtiles"));
            settings.setMbtilesFile(QStringLiteral("/data/area.mbtiles"));
            settings.setUnits(QStringLiteral("imperial"));
            settings.setWindowGeometry(QRect(10, 20, 1000, 700));
            settings.setPassword(QStringLiteral("secret-1"));
            QCOMPARE(changed.count(), 7);
            settings.sync();
        }
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage);
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

    void passwordOnlyWhenRemembered()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sortie.ini"));
        {
            QSettings storage(path, QSettings::IniFormat);
            AppSettings settings(&storage);
            settings.setPassword(QStringLiteral("secret-2"));
            settings.setRememberPassword(true);
            settings.sync();
            QVERIFY(fileContains(path, "secret-2"));
        }
        {
            QSettings storage(path, QSettings::IniFormat);
            AppSettings settings(&storage);
            QVERIFY(settings.rememberPassword());
            QCOMPARE(settings.password(), QStringLiteral("secret-2"));
            settings.setRememberPassword(false); // un-ticking erases the stored copy
            settings.sync();
            QVERIFY(!fileContains(path, "secret-2"));
        }
        // A password left in the file without "remember" (an older version, a hand edit) is dropped.
        {
            QSettings storage(path, QSettings::IniFormat);
            storage.setValue(QStringLiteral("connection/password"), QStringLiteral("secret-3"));
            storage.sync();
        }
        QSettings storage(path, QSettings::IniFormat);
        AppSettings settings(&storage);
        QVERIFY(settings.password().isEmpty());
        settings.sync();
        QVERIFY(!fileContains(path, "secret-3"));
    }

    void unknownMapSourceFallsBackToOffline()
    {
        QTemporaryDir dir;
        QSettings storage(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        storage.setValue(QStringLiteral("map/source"), QStringLiteral("satellite-magic"));
        AppSettings settings(&storage);
        QCOMPARE(settings.mapSource(), QStringLiteral("offline"));
    }

private:
    static bool fileContains(const QString &path, const QByteArray &text)
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) && file.readAll().contains(text);
    }
};

QTEST_GUILESS_MAIN(TestLaunch)
#include "tst_launch.moc"
