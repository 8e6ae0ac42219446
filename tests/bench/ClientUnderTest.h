#pragma once

#include "AppSettings.h"
#include "ClientGraph.h"
#include "ConnectionController.h"
#include "MainWindow.h"
#include "MissionController.h"
#include "PasswordVault.h"
#include "VehicleFleet.h"

#include <QSettings>
#include <QTemporaryDir>

#include <memory>

class QQuickWindow;

namespace sortie::bench {

// The desktop client wired as app/sortie wires it (its ClientGraph, the Sortie.Ui main window shown
// offscreen), with settings, autosaves and flight logs in a temporary directory.
class ClientUnderTest
{
public:
    // withWindow false: the client layer alone, no QML engine or window.
    explicit ClientUnderTest(bool withWindow = true);

    bool isReady() const { return m_window != nullptr || !m_withWindow; }
    QQuickWindow *window() const { return m_window; }
    client::ConnectionController &connection() { return m_graph.connection(); }
    client::MissionController &missions() { return m_graph.missions(); }
    client::VehicleFleet &fleet() { return *m_graph.fleet(); }

    // Logs in and waits for the session; false after `timeoutMs`.
    bool logIn(const QString &address, int timeoutMs = 20000);
    // 0 login, 1 mission, 2 live telemetry.
    void showPage(int page);
    // Renders and waits until the frame is out (offscreen: a grab of the window).
    void renderFrame();

private:
    QTemporaryDir m_dir;
    sortie::secrets::PasswordVault m_vault{QStringLiteral("sortie-tests")};
    QSettings m_storage;
    ui::AppSettings m_settings;
    client::ClientGraph m_graph;
    std::unique_ptr<ui::MainWindow> m_mainWindow;
    QQuickWindow *m_window = nullptr;
    bool m_withWindow;
};

} // namespace sortie::bench
