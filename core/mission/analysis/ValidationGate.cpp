#include "ValidationGate.h"

#include <QStringList>
#include <QCoreApplication>

namespace sortie::mission {

Result<void> permitRelease(const ValidationReport &report, ValidationOverride override, const QString &what)
{
    if (!report.hasErrors() || override == ValidationOverride::AcceptErrors)
        return {};
    QStringList first;
    for (const ValidationIssue &i : report.issues) {
        if (i.severity != Severity::Error)
            continue;
        if (first.size() == 3) {
            first << QStringLiteral("...");
            break;
        }
        first << i.message;
    }
    return MissionError{QCoreApplication::translate("ValidationGate", "%1 refused: the route has %n validation error(s). %2 Fix them, or override explicitly.",
                                                    nullptr, int(report.errorCount()))
                            .arg(what, first.join(QLatin1Char(' '))), {}, 0, 0, {}};
}

} // namespace sortie::mission
