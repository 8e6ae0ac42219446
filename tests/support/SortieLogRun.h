#pragma once
// sortie-log run as the operator runs it, a separate process (tst_sortielog, tst_geotagcli,
// tst_coveragecli): its exit status and what it printed. The test target defines SORTIE_LOG_PROGRAM.
#include <QByteArray>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace sortie::test {

struct Run
{
    int exitCode = -1; // -1: it crashed or did not finish within a minute
    QByteArray out, err;
};

// A command that ends by itself. `configHome`: where it keeps its settings (the certificates it
// remembers), a test's own folder rather than the user's.
inline Run sortieLog(const QStringList &arguments, const QString &configHome = {})
{
    QProcess p;
    if (!configHome.isEmpty()) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), configHome);
        p.setProcessEnvironment(env);
    }
    p.start(QStringLiteral(SORTIE_LOG_PROGRAM), arguments);
    Run r;
    if (!p.waitForFinished(60000))
        return r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// For a failed check's message: the status and both outputs.
inline QString describe(const Run &r)
{
    return QStringLiteral("exit %1\nstdout: %2\nstderr: %3").arg(r.exitCode).arg(QString::fromUtf8(r.out), QString::fromUtf8(r.err));
}

} // namespace sortie::test
