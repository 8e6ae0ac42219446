#include "SimProcess.h"

#include <QDeadlineTimer>

namespace sortie::test {

bool SimProcess::start()
{
    m_process.start(QStringLiteral(SORTIE_SIM_PROGRAM), m_arguments);
    if (!m_process.waitForStarted(10000))
        return false;
    QByteArray out;
    QDeadlineTimer deadline(15000);
    while (!out.contains("HCI on") && !deadline.hasExpired() && m_process.state() == QProcess::Running) {
        m_process.waitForReadyRead(50);
        out += m_process.readAllStandardOutput();
    }
    if (!out.contains("HCI on"))
        qWarning("sortie-sim did not start: %s %s", out.constData(), m_process.readAllStandardError().constData());
    // The VCI vehicles are listening too once their lines are out.
    while (!out.contains("VCI") && m_arguments.contains(QStringLiteral("--vci")) && !deadline.hasExpired()) {
        m_process.waitForReadyRead(50);
        out += m_process.readAllStandardOutput();
    }
    return out.contains("HCI on");
}

void SimProcess::kill()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.kill();
    m_process.waitForFinished(10000);
}

} // namespace sortie::test
