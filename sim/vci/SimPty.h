#pragma once

#include <QByteArray>
#include <QIODevice>
#include <QTimer>

class QSocketNotifier;

namespace sortie::sim {

// The master side of a pseudo-terminal as a QIODevice, so a simulated vehicle can sit at the far end
// of a real serial line: the client opens slaveName() with QSerialPort. The line is put in raw mode
// (no echo, no line editing). The master cannot tell when a client opens the slave, only when the
// last one closes it (reads fail with EIO): then peerClosed() is emitted, output is dropped instead of
// queued for the next client, and the slave is polled until someone opens it again (peerReturned()).
class SimPty : public QIODevice
{
    Q_OBJECT
public:
    explicit SimPty(QObject *parent = nullptr);
    ~SimPty() override;

    // Creates the pair and opens this device. False (and an error) when the system refuses.
    bool create(QString *error = nullptr);
    QString slaveName() const { return m_slaveName; }
    bool peerClosed() const { return m_peerClosed; }

    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_in.size() + QIODevice::bytesAvailable(); }
    void close() override;

signals:
    void peerGone();
    void peerReturned();

protected:
    qint64 readData(char *data, qint64 maxSize) override;
    qint64 writeData(const char *data, qint64 size) override;

private:
    void onReadable();
    void flush();
    void pollPeer();
    void markPeerClosed();

    int m_fd = -1;
    QString m_slaveName;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    QTimer m_peerPoll;
    QByteArray m_in, m_out;
    bool m_peerClosed = false;
};

} // namespace sortie::sim
