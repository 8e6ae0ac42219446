// sortie: wires the pieces together. Parses the command line, restores the settings, loads the
// Sortie.Ui main window.
#include "AppSettings.h"
#include "AutosaveRecovery.h"
#include "ComparisonController.h"
#include "ConnectionController.h"
#include "DemoServer.h"
#include "ElevationSetup.h"
#include "FleetRecording.h"
#include "FlightRecorder.h"
#include "HciClient.h"
#include "HciSession.h"
#include "MissionController.h"
#include "PasswordVault.h"
#include "RecordingSettings.h"
#include "ReplayController.h"
#include "ServerHistoryRequest.h"
#include "RouteAnalyzer.h"
#include "RouteAutosave.h"
#include "RouteDocument.h"
#include "RouteEditor.h"
#include "VehicleFleet.h"
#include "LaunchOptions.h"
#include "SortieUi.h"
#include "StartupProbe.h"
#include "WindowGeometry.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QIcon>
#include <QQmlApplicationEngine>
#include <QQuickStyle>
#include <QQuickWindow>
#include <QSettings>
#include <QStandardPaths>
#include <QDir>
#include <QtQml/qqmlextensionplugin.h>

#include <cstdio>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

namespace {

void describeApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Sortie"));
    QCoreApplication::setApplicationName(QStringLiteral("sortie"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SORTIE_VERSION));
}

// --autosave-dir, else SORTIE_AUTOSAVE_DIR, else a folder of its own for the demo (its server
// lives only as long as the program), else the application data folder.
QString autosaveDirectory(const sortie::app::LaunchOptions &options)
{
    if (!options.autosaveDir.isEmpty())
        return options.autosaveDir;
    const QString env = qEnvironmentVariable("SORTIE_AUTOSAVE_DIR");
    if (!env.isEmpty())
        return env;
    if (options.demo)
        return QDir::temp().filePath(QStringLiteral("sortie-demo-autosave"));
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("autosave"));
}

// SORTIE_FLIGHTLOG_DIR, else a folder of its own for the demo, else the application data folder.
QString flightLogDirectory(const sortie::app::LaunchOptions &options)
{
    const QString env = qEnvironmentVariable("SORTIE_FLIGHTLOG_DIR");
    if (!env.isEmpty())
        return env;
    if (options.demo)
        return QDir::temp().filePath(QStringLiteral("sortie-demo-flightlogs"));
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("flightlogs"));
}

} // namespace

int main(int argc, char *argv[])
{
    QElapsedTimer sinceMain;
    sinceMain.start();
    // The command line is read before any window system is touched, so --help, --version and
    // a mistyped option work without a display.
    std::variant<sortie::app::LaunchOptions, QString> parsed;
    {
        QCoreApplication reader(argc, argv);
        describeApplication();
        parsed = sortie::app::LaunchOptions::parse(QCoreApplication::arguments());
    }
    if (const auto *error = std::get_if<QString>(&parsed)) {
        std::fprintf(stderr, "sortie: %s\n", qPrintable(*error));
        return 2;
    }
    const auto options = std::get<sortie::app::LaunchOptions>(parsed);
    if (options.exitNow) {
        std::fputs(qPrintable(options.output), stdout);
        return 0;
    }

    QGuiApplication app(argc, argv);
    describeApplication();
    QGuiApplication::setApplicationDisplayName(QStringLiteral("Sortie"));
    QGuiApplication::setDesktopFileName(QStringLiteral("sortie"));
    QGuiApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("sortie")));

    // A fixed style makes every machine (and the offscreen tests) draw the same controls;
    // Fusion takes its colours from the system palette, light or dark.
    QQuickStyle::setStyle(QStringLiteral("Fusion"));

    QSettings storage;
    sortie::secrets::PasswordVault vault(QStringLiteral("sortie"));
    sortie::ui::AppSettings settings(&storage, &vault);
    if (options.server)
        settings.setLastServer(options.server->toString());
    if (!options.user.isEmpty())
        settings.setLastUser(options.user);

    sortie::hci::HciSession session;
    sortie::hci::HciClient hciClient(&session);
    sortie::client::ConnectionController connection(&session);
    sortie::client::MissionController missions(&hciClient);
    // Terrain: local tiles (--dem, else the setting) and the server, in the order the settings give.
    sortie::terrain::ElevationSetup elevation(&session);
    elevation.configure(options.demPath.isEmpty() ? storage.value(QStringLiteral("terrain/demFolder")).toString() : options.demPath,
                        storage.value(QStringLiteral("terrain/sourceOrder")).toStringList());
    sortie::client::VehicleFleet fleet(&hciClient, elevation.service());
    missions.document()->analyzer()->addRule(elevation.rule());
    missions.document()->editor()->setGroundLookup([&elevation](const sortie::mission::GeoPoint &p) { return elevation.service()->groundAt(p); });
    missions.setFleet(&fleet);
    // Recovery looks first, so the autosave of this run takes a slot of its own.
    const QString autosaves = autosaveDirectory(options);
    sortie::client::AutosaveRecovery recovery(missions.document(), autosaves);
    sortie::client::RouteAutosave autosave(missions.document(), autosaves);
    QObject::connect(&connection, &sortie::client::ConnectionController::ready, &autosave,
                     [&] { autosave.setServer(connection.server(), connection.user()); });
    // Only a password the server accepted is remembered.
    QObject::connect(&connection, &sortie::client::ConnectionController::ready, &settings, &sortie::ui::AppSettings::loginSucceeded);
    // A server route's autosaved edits are restored only when signed in where they belong.
    QObject::connect(&connection, &sortie::client::ConnectionController::stateChanged, &recovery, [&] {
        const bool ready = connection.isReady();
        recovery.setSession(ready ? connection.server() : QString(), ready ? connection.user() : QString());
    });
    // Every session is recorded without the operator asking: a log per run in the data folder.
    sortie::flightlog::FlightRecorder recorder({sortie::flightlog::FlightRecorder::sessionPath(flightLogDirectory(options)), {}, 500});
    // The operator's size cap and folder limit, from the settings, changed in the Logs… dialog.
    sortie::flightlog::RecordingSettings recordingSettings(&storage, &recorder);
    if (QString error; !recorder.start(&error))
        std::fprintf(stderr, "sortie: %s\n", qPrintable(error)); // flying goes on without a log
    sortie::flightlog::FleetRecording recording(&fleet, &recorder, &session);
    sortie::flightlog::ReplayController replay;
    sortie::flightlog::ComparisonController comparison(&replay);
    sortie::flightlog::ServerHistoryRequest serverHistory(&hciClient, &replay);
    serverHistory.setFleet(&fleet);
    sortie::app::DemoServer demo;
    if (options.demo) {
        QString error;
        if (!demo.start(&error)) {
            std::fprintf(stderr, "sortie: the demo simulator could not start: %s\n", qPrintable(error));
            return 1;
        }
    }

    QQmlApplicationEngine engine;
    sortie::ui::addImportPaths(engine);
    engine.setInitialProperties({{QStringLiteral("appSettings"), QVariant::fromValue(&settings)},
                                 {QStringLiteral("connection"), QVariant::fromValue<QObject *>(&connection)},
                                 {QStringLiteral("missions"), QVariant::fromValue<QObject *>(&missions)},
                                 {QStringLiteral("fleet"), QVariant::fromValue<QObject *>(&fleet)},
                                 {QStringLiteral("replay"), QVariant::fromValue(&replay)},
                                 {QStringLiteral("comparison"), QVariant::fromValue(&comparison)},
                                 {QStringLiteral("serverHistory"), QVariant::fromValue(&serverHistory)},
                                 {QStringLiteral("recordingSettings"), QVariant::fromValue(&recordingSettings)},
                                 {QStringLiteral("recovery"), QVariant::fromValue<QObject *>(&recovery)},
                                 {QStringLiteral("elevation"), QVariant::fromValue<QObject *>(elevation.service())}});
    engine.load(QUrl(QString::fromLatin1(sortie::ui::kMainQml)));
    if (engine.rootObjects().isEmpty())
        return 1;
    auto *window = qobject_cast<QQuickWindow *>(engine.rootObjects().constFirst());
    if (!window)
        return 1;
    sortie::app::restoreWindowGeometry(*window, settings);
    QObject::connect(&app, &QGuiApplication::aboutToQuit, &app, [window, &settings, &session] {
        sortie::app::saveWindowGeometry(*window, settings);
        session.close();
    });
    if (options.reportStartup)
        new sortie::app::StartupProbe(window, sinceMain);
    window->show();
    if (options.demo) {
        connection.connectToServer(demo.address(), sortie::app::DemoServer::user(), sortie::app::DemoServer::password());
        for (const QString &vehicle : demo.vciAddresses())
            fleet.addVciVehicle(vehicle);
    }
    if (options.vci)
        fleet.addVciVehicle(options.vci->toString());
    return QGuiApplication::exec();
}
