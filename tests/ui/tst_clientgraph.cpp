// One place builds the client: the graph a UI test fixture gets is the program's graph (the same
// services, wired to each other the same way), and the main window is handed every one of them.
#include "AutosaveRecovery.h"
#include "Airspace.h"
#include "ClientGraph.h"
#include "ServerZones.h"
#include "ServerZoneReply.h"
#include "MissionController.h"
#include "MissionUploader.h"
#include "RoutePreparation.h"
#include "AirspaceCheck.h"
#include "VciFenceBuilder.h"
#include "RouteEndurance.h"
#include "ClientWindow.h"
#include "ProximityMonitor.h"
#include "ZoneAlertMonitor.h"
#include "RouteDeconfliction.h"
#include "ElevationService.h"
#include "FleetRoutes.h"
#include "LaunchOptions.h"
#include "QuickScene.h"
#include "ReplayController.h"
#include "Traffic.h"

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

    void theMainWindowIsHandedEveryService()
    {
        test::ClientWindow fixture;
        QVERIFY2(fixture.isReady(), qPrintable(fixture.error()));
        client::ClientGraph &graph = fixture.graph();
        QQuickWindow *window = fixture.window();
        const std::pair<const char *, QObject *> expected[] = {
            {"connection", &graph.connection()}, {"missions", &graph.missions()}, {"fleet", graph.fleet()},
            {"elevation", graph.elevation()}, {"replay", &graph.replay()},
            {"recovery", graph.recovery()}, {"endurance", &graph.endurance()}, {"traffic", &graph.traffic()},
            {"fleetRoutes", graph.fleetRoutes()}, {"proximity", graph.proximity()},
            {"deconfliction", graph.deconfliction()}, {"zoneAlerts", graph.zoneAlerts()}, {"airspace", &graph.airspace()}};
        for (const auto &[name, object] : expected) {
            QVERIFY2(object, name);
            QCOMPARE(window->property(name).value<QObject *>(), object);
        }
        for (const char *name : {"appSettings", "comparison", "serverHistory", "recordingSettings"})
            QVERIFY2(window->property(name).value<QObject *>(), name);
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
