#include "SortieUi.h"

#include <QQmlEngine>

namespace sortie::ui {

void addImportPaths(QQmlEngine &engine)
{
    engine.addImportPath(QStringLiteral("qrc:/qt/qml"));
}

} // namespace sortie::ui
