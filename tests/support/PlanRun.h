#pragma once

// Runs the built sortie-plan (SORTIE_PLAN_BIN, set by the test's CMakeLists) as a process, as a
// script would: its exit code, standard output and standard error. For the command-line tests.
#include <QByteArray>
#include <QProcess>
#include <QStringList>

namespace sortie::test {

struct PlanRun
{
    int code = -1;
    QByteArray out, err;
};

inline PlanRun runPlan(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(SORTIE_PLAN_BIN), args);
    if (!p.waitForFinished(60000))
        qFatal("sortie-plan did not finish");
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

} // namespace sortie::test
