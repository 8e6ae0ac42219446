#pragma once

#include <QVariantMap>

class QQmlEngine;

namespace sortie::client {
class ClientGraph;
}

namespace sortie::ui {

class AppSettings;
class Translations;

// Makes the static Sortie.Ui module importable by an engine. The program (or test) that links
// sortie_uiplugin must also say Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin) once.
void addImportPaths(QQmlEngine &engine);

// The module's main window file, for QQmlApplicationEngine::load().
inline constexpr auto kMainQml = "qrc:/qt/qml/Sortie/Ui/Main.qml";

// Main.qml's initial properties: the settings, the language machinery and every controller of the
// client graph, by the names Main.qml declares. The program and the test fixtures load the window
// with exactly these.
QVariantMap mainWindowProperties(client::ClientGraph &graph, AppSettings &settings, Translations &translations);

} // namespace sortie::ui
