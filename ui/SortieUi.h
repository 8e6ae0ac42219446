#pragma once

class QQmlEngine;

namespace sortie::ui {

// Makes the static Sortie.Ui module importable by an engine. The program (or test) that links
// sortie_uiplugin must also say Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin) once.
void addImportPaths(QQmlEngine &engine);

// The module's main window file; ui::MainWindow loads it with the client graph, the settings and
// the language.
inline constexpr auto kMainQml = "qrc:/qt/qml/Sortie/Ui/Main.qml";

} // namespace sortie::ui
