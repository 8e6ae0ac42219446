#pragma once

#include "VciEndpoint.h"

#include <QObject>
#include <QTimer>

class QIODevice;

namespace sortie::vci {

// Opens the device for an endpoint (a QTcpSocket or a QSerialPort) and keeps it open: after a loss or
// a failed attempt it tries again, waiting 250 ms at first and twice as long each time up to 5 s
// (setRetryDelays). Owns the devices it makes; a device handed out by opened() lives until lost().
class VciTransport : public QObject
{
    Q_OBJECT
public:
    enum class State { Closed, Opening, Open, Retrying };
    Q_ENUM(State)

    explicit VciTransport(const VciEndpoint &endpoint, QObject *parent = nullptr);
    ~VciTransport() override;

    const VciEndpoint &endpoint() const { return m_endpoint; }
    State state() const { return m_state; }
    QIODevice *device() const { return m_state == State::Open ? m_device : nullptr; }
    QString lastError() const { return m_lastError; }

    void open();   // opens now, and again after every loss until close()
    void close();  // drops the device and stops trying
    void reopen(); // drops the device and opens again at once (the operator's "reconnect")
    void setRetryDelays(int firstMs, int maxMs);

signals:
    void opened(QIODevice *device);
    void lost(const QString &reason);          // an opened device went away; a retry follows unless closed
    void attemptFailed(const QString &reason); // an attempt to open failed; a retry follows
    void stateChanged(sortie::vci::VciTransport::State state);

private:
    void attempt();
    void onOpened();
    void onFailed(QIODevice *device, const QString &reason);
    void drop(const QString &reason);
    void setState(State state);

    VciEndpoint m_endpoint;
    State m_state = State::Closed;
    QIODevice *m_device = nullptr;
    QTimer m_retry;
    int m_firstDelay = 250, m_maxDelay = 5000, m_delay = 250;
    QString m_lastError;
};

} // namespace sortie::vci
