#pragma once

// sortie-sim as a child process (the test's SORTIE_SIM_PROGRAM), for the tests that kill it.
#include <QDeadlineTimer>
#include <QProcess>
#include <QStringList>

namespace sortie::test {

// sortie-sim as a separate process on a fixed port, so it can be killed (SIGKILL: no goodbye, no
// store flush) and started again where the client expects it.
class SimProcess
{
public:
    SimProcess(quint16 port, QStringList arguments)
        : m_arguments(QStringList{QStringLiteral("--port"), QString::number(port)} + arguments)
    {
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
    }
    ~SimProcess() { kill(); }

    // Starts it and waits until it listens (it prints "HCI on ..." once it does).
    bool start()
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

    void kill()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.kill();
        m_process.waitForFinished(10000);
    }

    bool isRunning() const { return m_process.state() == QProcess::Running; }

private:
    QStringList m_arguments;
    QProcess m_process;
};

} // namespace sortie::test
