// One place builds the client: the graph a UI test fixture gets is the program's graph (the same
// services, wired to each other the same way), and the main window is handed it once, typed. The
// real program starts without a QML warning, wired as the fixture is.
#include "AutosaveRecovery.h"
#include "Airspace.h"
#include "ClientGraph.h"
#include "PhotoSurvey.h"
#include "MissionResume.h"
#include "ServerZones.h"
#include "ServerZoneReply.h"
#include "MissionController.h"
#include "MissionUploader.h"
#include "RoutePreparation.h"
#include "AirspaceCheck.h"
#include "VciFenceBuilder.h"
#include "RouteEndurance.h"
#include "ClientWindow.h"
#include "ZoneFeed.h"
#include "ProximityMonitor.h"
#include "ZoneAlertMonitor.h"
#include "RouteDeconfliction.h"
#include "ElevationService.h"
#include "FleetRoutes.h"
#include "PreflightChecklists.h"
#include "GamepadCommands.h"
#include "LaunchOptions.h"
#include "QuickScene.h"
#include "ComparisonController.h"
#include "OfflineMaps.h"
#include "RecordingSettings.h"
#include "ReplayController.h"
#include "ServerHistoryRequest.h"
#include "ZoneSharing.h"
#include "FreePort.h"
#include "HgtWriter.h"
#include "SimProcess.h"
#include "Traffic.h"
#include "VehicleVideo.h"

#include <QMetaProperty>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestClientGraph : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    // The graph app/sortie builds when started with `arguments`, its folders in this test's own.
    QStringList programWiring(const QStringList &arguments)
    {
        qputenv("SORTIE_AUTOSAVE_DIR", m_dir.filePath(QStringLiteral("autosave")).toUtf8());
        qputenv("SORTIE_FLIGHTLOG_DIR", m_dir.filePath(QStringLiteral("flightlogs")).toUtf8());
        const auto parsed = app::LaunchOptions::parse(QStringList{QStringLiteral("sortie")} + arguments);
        if (!std::holds_alternative<app::LaunchOptions>(parsed))
            return {std::get<QString>(parsed)};
        QSettings storage(m_dir.filePath(QStringLiteral("program.ini")), QSettings::IniFormat);
        client::ClientGraph program(&storage, std::get<app::LaunchOptions>(parsed).graphOptions());
        return program.wiring();
    }

    // The real program, offscreen with fresh settings and this test's folders, until it quits by
    // itself (--report-startup); what it printed on stdout and on stderr.
    std::pair<QString, QString> runProgram(const QStringList &arguments)
    {
        QTemporaryDir home;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("QT_QUICK_BACKEND"), QStringLiteral("software"));
        env.insert(QStringLiteral("QT_LOGGING_RULES"), QStringLiteral("sortie.client.graph.info=true\nsortie.ui.mainwindow.info=true"));
        env.insert(QStringLiteral("QT_MESSAGE_PATTERN"), QStringLiteral("%{if-category}%{category}: %{endif}%{message}"));
        env.insert(QStringLiteral("HOME"), home.path());
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
        env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
        env.insert(QStringLiteral("XDG_CACHE_HOME"), home.filePath(QStringLiteral("cache")));
        env.insert(QStringLiteral("SORTIE_AUTOSAVE_DIR"), m_dir.filePath(QStringLiteral("program-autosave")));
        env.insert(QStringLiteral("SORTIE_FLIGHTLOG_DIR"), m_dir.filePath(QStringLiteral("program-flightlogs")));
        env.insert(QStringLiteral("DBUS_SESSION_BUS_ADDRESS"), QStringLiteral("unix:path=/nonexistent/sortie-tst-clientgraph")); // no keyring
        QProcess program;
        program.setProcessEnvironment(env);
        program.start(QStringLiteral(SORTIE_APP_PATH), arguments);
        if (!program.waitForFinished(60000))
            program.kill();
        return {QString::fromUtf8(program.readAllStandardOutput()), QString::fromUtf8(program.readAllStandardError())};
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void theFixtureRunsTheProgramsWiring()
    {
        const QStringList program = programWiring({});
        // What the program wires, so that a fixture and a program that both lost a service do not agree.
        for (const char *line : {"route validation: with the terrain rule", "height conversions: through the ground",
                                 "vehicles: fleet planning over the ground", "upload chooser: the fleet", "autosave: on",
                                 "fleet routes: the open route's vehicle and every upload",
                                 "recovery: on", "flight recorder: recording", "fleet recording: on",
                                 "server history: from the fleet", "traffic: the server's ADS-B list; receiver off"})
            QVERIFY2(program.contains(QString::fromLatin1(line)), qPrintable(program.join(QLatin1Char('\n'))));

        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        QCOMPARE(fixture.graph().wiring(), program);
    }

    // The main window is handed the graph once; every service the views use is one of its typed,
    // constant properties, and each page holds the graph's own object.
    void theMainWindowIsHandedTheGraph()
    {
        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        client::ClientGraph &graph = fixture.graph();
        QQuickWindow *window = fixture.window();
        QCOMPARE(window->property("graph").value<QObject *>(), &graph);
        // The properties are the services the C++ accessors give.
        const std::pair<const char *, QObject *> services[] = {
            {"connection", &graph.connection()}, {"missions", &graph.missions()}, {"elevation", graph.elevation()},
            {"fleet", graph.fleet()}, {"fleetRoutes", graph.fleetRoutes()}, {"recovery", graph.recovery()},
            {"endurance", &graph.endurance()}, {"airspace", &graph.airspace()}, {"zoneSharing", &graph.zoneSharing()}, {"zoneFeed", &graph.zoneFeed()},
            {"traffic", &graph.traffic()}, {"video", graph.video()}, {"preflight", graph.preflight()}, {"gamepads", graph.gamepads()}, {"offlineMaps", &graph.offlineMaps()}, {"proximity", graph.proximity()},
            {"zoneAlerts", graph.zoneAlerts()}, {"deconfliction", graph.deconfliction()},
            {"recordingSettings", &graph.recordingSettings()}, {"replay", &graph.replay()},
            {"comparison", &graph.comparison()}, {"serverHistory", &graph.serverHistory()}, {"photos", &graph.photos()},
            {"resume", graph.resume()}};
        const QMetaObject *meta = graph.metaObject();
        QCOMPARE(meta->propertyCount() - meta->propertyOffset(), int(std::size(services)));
        for (const auto &[name, object] : services) {
            const QMetaProperty property = meta->property(meta->indexOfProperty(name));
            QVERIFY2(property.isValid() && property.isConstant(), name);
            QVERIFY2(object, name); // the program's graph has every one
            QCOMPARE(property.read(&graph).value<QObject *>(), object);
        }
        // The pages take theirs from it.
        const std::pair<const char *, QStringList> pages[] = {
            {"loginPage", {"connection"}},
            {"missionPage", {"missions", "elevation", "endurance", "traffic", "fleetRoutes", "deconfliction", "airspace", "zoneSharing"}},
            {"telemetryPage", {"fleet", "replay", "serverHistory", "comparison", "endurance", "traffic", "fleetRoutes",
                               "proximity", "zoneAlerts", "airspace", "preflight", "gamepads", "photos", "resume"}}};
        for (const auto &[pageName, names] : pages) {
            QObject *page = fixture.page(pageName);
            QVERIFY2(page, pageName);
            QCOMPARE(page->property("graph").value<QObject *>(), &graph);
            for (const QString &name : names)
                QVERIFY2(page->property(qPrintable(name)).value<QObject *>() == graph.property(qPrintable(name)).value<QObject *>(),
                         qPrintable(QStringLiteral("%1.%2").arg(QLatin1String(pageName), name)));
        }
        QCOMPARE(fixture.page("missionPage")->property("vehicleModel").value<QObject *>(), graph.fleet());
    }

    // The terrain follows the DEM the operator chooses in the map source dialog (the setting): in a
    // fixture as in the program, both wired by ui::MainWindow (SettingsWiring).
    void theTerrainFollowsTheDemSetting()
    {
        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        terrain::ElevationService *ground = fixture.graph().elevation();
        const mission::GeoPoint riga{56.5, 24.5};
        QVERIFY(!ground->groundAt(riga)); // no DEM, not logged in: no ground to read
        QTemporaryDir dems;
        QVERIFY(terrain::test::writeHgt(dems.filePath(QStringLiteral("N56E024.hgt")), 1201, [](int, int) { return 123; }));
        fixture.settings().setDemPath(dems.path());
        const std::optional<double> height = ground->groundAt(riga);
        QVERIFY2(height, qPrintable(ground->sourceNames().join(QStringLiteral(", "))));
        QCOMPARE(*height, 123.0);
        // The password wiring beside it is the program's too (theProgramStartsCleanlyWiredAsTheFixture).
        QVERIFY(fixture.mainWindow().wiring().contains(QStringLiteral("terrain setting: the DEM chosen in the map source dialog")));
    }

    // The real program, started against sortie-sim (a VCI vehicle of its own), and again as the demo
    // (logged in to its embedded simulator): not one QML warning from start to quit, and the wiring it
    // logs (the graph's and the settings') is the fixture's.
    void theProgramStartsCleanlyWiredAsTheFixture_data()
    {
        QTest::addColumn<bool>("demo");
        QTest::newRow("sortie-sim") << false;
        QTest::newRow("demo") << true;
    }
    void theProgramStartsCleanlyWiredAsTheFixture()
    {
        QFETCH(bool, demo);
        const quint16 vciPort = test::freePort();
        test::SimProcess sim(test::freePort(), {QStringLiteral("--vci"), QStringLiteral("1"), QStringLiteral("--vci-port"),
                                                QString::number(vciPort)});
        QStringList arguments{QStringLiteral("--report-startup")};
        if (demo) {
            arguments << QStringLiteral("--demo");
        } else {
            QVERIFY(sim.start());
            arguments << QStringLiteral("--server") << sim.address() << QStringLiteral("--user") << QStringLiteral("admin")
                      << QStringLiteral("--vci") << QStringLiteral("tcp://127.0.0.1:%1").arg(vciPort);
        }
        const auto [output, errors] = runProgram(arguments);
        QVERIFY2(output.contains(QLatin1String("first-frame")), qPrintable(output + errors));
        QVERIFY2(output.contains(QLatin1String("idle rss")), qPrintable(output + errors)); // it ran to the end and quit

        // QML names the file and line of what it warns about: none may appear.
        static const QRegularExpression qmlWarning(QStringLiteral("\\.qml:\\d+|QQmlApplicationEngine|TypeError|ReferenceError"));
        QStringList warnings;
        for (const QString &line : errors.split(QLatin1Char('\n')))
            if (qmlWarning.match(line).hasMatch())
                warnings << line;
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join(QLatin1Char('\n'))));

        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        QVERIFY2(fixture.mainWindow().loadWarnings().isEmpty(), qPrintable(fixture.mainWindow().loadWarnings().join(QLatin1Char('\n'))));
        const QString graphLine = QStringLiteral("sortie.client.graph: wired: ") + fixture.graph().wiring().join(QStringLiteral("; "));
        const QString settingsLine = QStringLiteral("sortie.ui.mainwindow: settings wired: ")
                                     + fixture.mainWindow().wiring().mid(fixture.graph().wiring().size()).join(QStringLiteral("; "));
        QVERIFY2(errors.contains(graphLine), qPrintable(graphLine + QStringLiteral("\n---\n") + errors));
        QVERIFY2(errors.contains(settingsLine), qPrintable(settingsLine + QStringLiteral("\n---\n") + errors));
    }

    // The server's zones reach the one store where a map looks, and from it the alerts and the
    // fence a VCI vehicle is sent: sortie-sim's aerodromes near Riga and its custom "Crane works".
    void theServersZonesReachTheAirspace()
    {
        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        QVERIFY(fixture.logIn());
        client::ClientGraph &graph = fixture.graph();
        airspace::Airspace &store = graph.airspace();
        auto serverZones = [&store] {
            QStringList names;
            for (int row = 0; row < store.count(); ++row)
                if (store.groupOf(row) == airspace::Airspace::Group::Server)
                    names << store.zoneAt(row).name;
            names.sort();
            return names;
        };
        store.lookAt(56.90, 23.90, 57.02, 24.20);
        QTRY_COMPARE_WITH_TIMEOUT(serverZones(), (QStringList{"Crane works", "RIX CTR", "Spilve airfield"}), 10000);
        // The same set is what the fence is built from and what the alerts watch.
        const vehicle::FenceSettings &fence = graph.missions().preparation()->uploader()->fenceSettings();
        QVERIFY(fence.zones);
        QCOMPARE(int(airspace::fenceZonesOf(fence)->zones().size()), store.count());
        // A custom zone saved to the server (under its lock) comes back into the store.
        airspace::Zone pier;
        pier.name = QStringLiteral("Test pier");
        pier.shape = airspace::ZonePolygons{{airspace::ZonePolygon{{{{56.9700, 24.1000}, {56.9700, 24.1030}, {56.9720, 24.1030}, {56.9720, 24.1000}}}}}};
        pier.ceiling = airspace::HeightLimit{80, terrain::HeightReference::AboveTerrain};
        airspace::ServerZoneReply *reply = graph.serverZones().save(pier);
        std::optional<QString> error; // the reply deletes itself once finished
        connect(reply, &airspace::ServerZoneReply::finished, this, [&] { error = reply->error(); });
        QTRY_VERIFY_WITH_TIMEOUT(error.has_value(), 10000);
        QVERIFY2(error->isEmpty(), qPrintable(*error));
        QTRY_COMPARE_WITH_TIMEOUT(serverZones(), (QStringList{"Crane works", "RIX CTR", "Spilve airfield", "Test pier"}), 10000);
        QCOMPARE(int(airspace::fenceZonesOf(graph.missions().preparation()->uploader()->fenceSettings())->zones().size()), store.count());
    }

    // A fixture changes what it needs through the options, and the wiring says so.
    void optionsChangeTheGraph()
    {
        QSettings storage(m_dir.filePath(QStringLiteral("bare.ini")), QSettings::IniFormat);
        client::ClientGraph bare(&storage, {{}, {}, {}, false});
        const QStringList wiring = bare.wiring();
        QVERIFY2(wiring.contains(QStringLiteral("vehicles: none")), qPrintable(wiring.join(QLatin1Char('\n'))));
        QVERIFY(wiring.contains(QStringLiteral("autosave: off")));
        QVERIFY(wiring.contains(QStringLiteral("proximity alerts: none"))); // no fleet, nothing to watch
        QVERIFY(!bare.proximity());
        QVERIFY(wiring.contains(QStringLiteral("flight recorder: off")));
        QVERIFY(wiring.contains(QStringLiteral("route validation: with the terrain rule"))); // terrain is always wired
        QVERIFY(!bare.fleet());
        QVERIFY(!bare.recovery());
        QVERIFY(bare.recorderError().isEmpty());
    }
};

QTEST_MAIN(TestClientGraph)
#include "tst_clientgraph.moc"
