#pragma once

// The whole client in one offscreen window, wired by the program's own ClientGraph, against the
// embedded simulator: an HCI server with the demo content (three vehicles, a demo route) and VCI
// vehicles on loopback ports. For UI tests that fly, render or inspect the real views.
#include "AppSettings.h"
#include "ClientGraph.h"
#include "ConnectionController.h"
#include "HciServer.h"
#include "MainWindow.h"
#include "MissionController.h"
#include "PasswordVault.h"
#include "SimVciFleet.h"
#include "SimWorld.h"
#include "Translations.h"
#include "VehicleFleet.h"

#include <QGeoCoordinate>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSettings>
#include <QSslConfiguration>
#include <QTemporaryDir>

#include <functional>
#include <optional>
#include <memory>

namespace sortie::test {

class ClientWindow
{
public:
    struct Options
    {
        int vciVehicles = 1;
        bool mannedTraffic = true;  // the simulator's three aircraft; false: an empty sky
        QGeoCoordinate vciHome;     // invalid: the simulator's default, south-east of the demo route
        double vciTimeScale = 1;    // simulated seconds per real second for the VCI vehicles
        // The VCI vehicles' battery and powers (a small battery drains fast); empty: the sim's default.
        std::optional<endurance::EnergyProfile> vciEnergy;
        int uploadStepMs = 20;
        QSize size{1280, 800};
        bool activate = false;      // also wait until the window is active (keyboard tests)
        // Where the client autosaves and recovers from: empty, a folder of the fixture's own (as the
        // program has one); a test that prepares a previous run's autosaves names their folder.
        QString autosaveDirectory;
        // Runs once the simulator listens, before the client is built: what a previous run left
        // behind that names this server (its autosaves).
        std::function<void(ClientWindow &)> beforeClient;
        // Where the translations (sortie_<code>.qm) are: empty, the program's own resources.
        QString translationsFolder;
        QString checklistDirectory; // empty: a folder of the fixture's own, empty (Sortie's default checklist)
        // The simulated server's TLS identity (tls::loadServerIdentity); nullopt: plain HCI.
        std::optional<QSslConfiguration> hciTls;
    };
    explicit ClientWindow(Options options);
    ClientWindow() : ClientWindow(Options{}) {}
    ~ClientWindow();

    bool isReady() const { return m_window != nullptr; }
    QString error() const { return m_error; }
    QQuickWindow *window() const { return m_window; }

    // Logs in to the simulated server straight through the controller (the login page's own
    // test types it); true once ready.
    bool logIn();
    // Opens the simulator's demo route; true once its waypoints are in the document.
    bool openDemoRoute();
    // Adds every simulated VCI vehicle to the fleet; true once each has a position.
    bool addVciVehicles();
    void showPage(int page);
    // The waypoint table's cell for `role` ("altitude", "speed", ...) in a row, as laid out now.
    QQuickItem *waypointCell(int row, const QString &role) const;

    template<typename T = QQuickItem>
    T *find(const QString &name) const
    {
        return m_window ? m_window->findChild<T *>(name) : nullptr;
    }
    QObject *page(const char *name) const { return m_window->property(name).value<QObject *>(); }

    QSettings &storage() { return *m_storage; }
    sim::SimWorld &world() { return *m_world; }
    sim::HciServer &server() { return *m_server; }
    sim::SimVciFleet &vci() { return *m_vci; }
    ui::AppSettings &settings() { return *m_settings; }
    ui::Translations &translations() { return m_mainWindow->translations(); }
    ui::MainWindow &mainWindow() { return *m_mainWindow; }
    client::ClientGraph &graph() { return *m_graph; }
    client::ConnectionController &connection() { return m_graph->connection(); }
    client::MissionController &missions() { return m_graph->missions(); }
    client::VehicleFleet &fleet() { return *m_graph->fleet(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<sim::SimWorld> m_world;
    std::unique_ptr<sim::HciServer> m_server;
    std::unique_ptr<sim::SimVciFleet> m_vci;
    sortie::secrets::PasswordVault m_vault{QStringLiteral("sortie-tests")}; // no keyring under ctest: nothing remembered
    std::unique_ptr<QSettings> m_storage;
    std::unique_ptr<ui::AppSettings> m_settings;
    std::unique_ptr<client::ClientGraph> m_graph;
    std::unique_ptr<ui::MainWindow> m_mainWindow;
    QQuickWindow *m_window = nullptr;
    QString m_error;
};

// Waits until the window has drawn a frame after now (layouts and polish done).
bool waitForFrame(QQuickWindow *window);

} // namespace sortie::test
