#pragma once

#include "SettingsWiring.h"
#include "Theme.h"
#include "Translations.h"

#include <QStringList>

#include <memory>

class QQmlApplicationEngine;
class QQuickWindow;

namespace sortie::client {
class ClientGraph;
}

namespace sortie::ui {

class AppSettings;

// The client's main window (Main.qml) in an engine of its own: handed the client graph once, with
// the operator's settings, the language it is shown in and the theme it is drawn with, and the
// settings the client follows wired (SettingsWiring). The program and every UI fixture open the window through this class, so
// they load the same window with the same wiring.
class MainWindow
{
public:
    // `graph` and `settings` must outlive this object. `translationsFolder` holds sortie_<code>.qm
    // (tests bring their own). A program that links sortie_uiplugin says
    // Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin) once.
    MainWindow(client::ClientGraph &graph, AppSettings &settings,
               const QString &translationsFolder = QString::fromLatin1(Translations::kBuiltIn));
    ~MainWindow();
    MainWindow(const MainWindow &) = delete;
    MainWindow &operator=(const MainWindow &) = delete;

    // nullptr when Main.qml did not load (loadWarnings() says why).
    QQuickWindow *window() const { return m_window; }
    QQmlApplicationEngine &engine() { return *m_engine; }
    Translations &translations() { return *m_translations; }
    // The colours, spacing and type sizes of every view and painted layer (Main.qml's `theme`).
    Theme &theme() { return m_theme; }
    // What QML warned of while the window loaded (printed as well); empty for a clean start.
    QStringList loadWarnings() const { return m_loadWarnings; }
    // The graph's wiring and the settings', one line each (ClientGraph::wiring()).
    QStringList wiring() const;

private:
    client::ClientGraph &m_graph;
    SettingsWiring m_settingsWiring;
    Theme m_theme; // before the engine: the window's bindings read it to the end
    std::unique_ptr<QQmlApplicationEngine> m_engine;
    std::unique_ptr<Translations> m_translations;
    QQuickWindow *m_window = nullptr;
    QStringList m_loadWarnings;
};

} // namespace sortie::ui
