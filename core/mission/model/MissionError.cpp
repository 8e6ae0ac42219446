#include "MissionError.h"
#include <QCoreApplication>

namespace sortie::mission {

QString MissionError::toString() const
{
    QString where = file;
    if (line > 0) {
        where += QStringLiteral(":%1").arg(line);
        if (column > 0)
            where += QStringLiteral(":%1").arg(column);
    }
    if (!jsonPath.isEmpty())
        where += (where.isEmpty() ? QString() : QStringLiteral(" ")) + QCoreApplication::translate("MissionError", "(at %1)").arg(jsonPath);
    return where.isEmpty() ? message : where + QStringLiteral(": ") + message;
}

MissionError MissionError::withFile(const QString &name) const
{
    MissionError e = *this;
    e.file = name;
    return e;
}

} // namespace sortie::mission
