// sortie: wires the pieces together. Parses the command line, restores the settings, loads the
// Sortie.Ui main window.
#include "AppSettings.h"
#include "ClientGraph.h"
#include "ConnectionController.h"
#include "DemoScene.h"
#include "DemoServer.h"
#include "FrameLog.h"
#include "HciSession.h"
#include "LaunchOptions.h"
#include "MainWindow.h"
#include "PasswordVault.h"
#include "SbsFeed.h"
#include "SceneGraphChoice.h"
#include "StartupProbe.h"
#include "Traffic.h"
#include "VehicleFleet.h"
#include "WindowGeometry.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QIcon>
#include <QQuickStyle>
#include <QQuickWindow>
#include <QSettings>
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
    sortie::app::chooseSceneGraph();

    QSettings storage;
    sortie::secrets::PasswordVault vault(QStringLiteral("sortie"));
    sortie::ui::AppSettings settings(&storage, &vault);
    if (options.server)
        settings.setLastServer(options.server->toString());
    if (!options.user.isEmpty())
        settings.setLastUser(options.user);

    // The client: one graph, wired as every test fixture wires it.
    sortie::client::ClientGraph graph(&storage, options.graphOptions());
    if (!options.serverPin.isEmpty())
        graph.connection().certificates().pin(options.server->peer(), options.serverPin);
    if (!graph.recorderError().isEmpty())
        std::fprintf(stderr, "sortie: %s\n", qPrintable(graph.recorderError())); // flying goes on without a log
    sortie::app::DemoServer demo;
    if (options.demo) {
        QString error;
        const auto scene = options.demoScene == QLatin1String("parked")   ? sortie::app::DemoServer::Scene::Parked
                           : options.demoScene == QLatin1String("flying") ? sortie::app::DemoServer::Scene::Flying
                                                                          : sortie::app::DemoServer::Scene::Full;
        if (!demo.start(&error, scene)) {
            std::fprintf(stderr, "sortie: the demo simulator could not start: %s\n", qPrintable(error));
            return 1;
        }
    }

    // The window, handed the graph once, with the settings the client follows wired as every UI
    // fixture wires them; the settings' language before the first word is shown.
    sortie::ui::MainWindow mainWindow(graph, settings);
    QQuickWindow *window = mainWindow.window();
    if (!window)
        return 1;
    sortie::app::restoreWindowGeometry(*window, settings);
    QObject::connect(&app, &QGuiApplication::aboutToQuit, &app, [window, &settings, &graph] {
        sortie::app::saveWindowGeometry(*window, settings);
        graph.session().close();
    });
    if (options.reportStartup)
        new sortie::app::StartupProbe(window, sinceMain);
    new sortie::app::FrameLog(window);
    if (!demo.flyingVehicleName().isEmpty())
        new sortie::app::DemoScene(window, graph.fleet(), demo.flyingVehicleName());
    window->show();
    if (options.demo) {
        graph.connection().connectToServer(demo.address(), sortie::app::DemoServer::user(), sortie::app::DemoServer::password());
        for (const QString &vehicle : demo.vciAddresses())
            graph.fleet()->addVciVehicle(vehicle);
        graph.traffic().receiver()->setAddress(demo.sbsAddress()); // the demo's traffic, not remembered
    }
    if (options.vci)
        graph.fleet()->addVciVehicle(options.vci->toString());
    return QGuiApplication::exec();
}
