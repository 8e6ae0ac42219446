#pragma once

#include <QProcess>
#include <QStringList>

namespace sortie::test {

// sortie-sim as a separate process on a fixed port: the fault tests kill it (SIGKILL: no goodbye, no
// store flush) and start it again where the client expects it; the benchmarks keep its CPU apart
// from the client's.
class SimProcess
{
public:
    SimProcess(quint16 port, QStringList arguments)
        : m_port(port)
        , m_arguments(QStringList{QStringLiteral("--port"), QString::number(port)} + arguments)
    {
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
    }
    ~SimProcess() { kill(); }

    // Starts it and waits until it listens (it prints "HCI on ..." once it does, then its VCI lines).
    bool start();
    void kill();

    bool isRunning() const { return m_process.state() == QProcess::Running; }
    qint64 pid() const { return m_process.processId(); }
    quint16 port() const { return m_port; }
    QString address() const { return QStringLiteral("127.0.0.1:%1").arg(m_port); }

private:
    quint16 m_port;
    QStringList m_arguments;
    QProcess m_process;
};

} // namespace sortie::test
