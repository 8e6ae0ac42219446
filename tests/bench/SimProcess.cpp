#include "SimProcess.h"

#include <QDeadlineTimer>
#include <QTcpServer>

namespace sortie::bench {

namespace {
quint16 freePort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
}
} // namespace

SimProcess::~SimProcess()
{
    if (m_process.state() != QProcess::NotRunning) {
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            m_process.kill();
        m_process.waitForFinished(5000);
    }
}

bool SimProcess::start(const QStringList &arguments, QString *error)
{
    m_port = freePort();
    m_process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    m_process.start(QStringLiteral(SORTIE_SIM_PATH), QStringList{QStringLiteral("--port"), QString::number(m_port)} + arguments);
    QDeadlineTimer deadline(20000);
    QByteArray output;
    while (!deadline.hasExpired() && m_process.state() != QProcess::NotRunning) {
        m_process.waitForReadyRead(100);
        output += m_process.readAllStandardOutput();
        if (output.contains("HCI on"))
            return true;
    }
    *error = QStringLiteral("sortie-sim did not start: %1").arg(QString::fromLocal8Bit(output + m_process.readAllStandardError()));
    return false;
}

} // namespace sortie::bench
