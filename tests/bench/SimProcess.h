#pragma once

#include <QProcess>
#include <QStringList>

namespace sortie::bench {

// The simulator (sortie-sim) as a separate process on a free loopback port, so that its CPU is not
// the client's: the benchmarks measure the client alone.
class SimProcess
{
public:
    ~SimProcess();

    // Starts it with these extra arguments and waits until it listens; false with `error` set.
    bool start(const QStringList &arguments, QString *error);
    QString address() const { return QStringLiteral("127.0.0.1:%1").arg(m_port); }
    qint64 pid() const { return m_process.processId(); }

private:
    QProcess m_process;
    quint16 m_port = 0;
};

} // namespace sortie::bench
