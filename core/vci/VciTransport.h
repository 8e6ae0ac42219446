#pragma once

#include "TlsOptions.h"
#include "TlsVerdict.h"
#include "VciEndpoint.h"

#include <QObject>
#include <QTimer>

class QIODevice;

namespace sortie::vci {

// Opens the device for an endpoint (a QTcpSocket, a QSslSocket for vci+tls:// or a QSerialPort) and
// keeps it open. Over TLS the device is handed out only after the handshake and the certificate's
// verdict (tls::TlsVerdict: the endpoint's pin, the system's trust, else the store's), so no command
// goes to a vehicle whose certificate is refused: after a loss or
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
    // Where certificates are pinned and remembered for vci+tls:// (not owned; nullptr: only a pinned
    // or system-trusted certificate is accepted).
    void setCertificateStore(tls::CertificateStore *store) { m_store = store; }
    // The verdict on the vehicle's certificate at the last TLS handshake (Refused before one).
    const tls::TlsVerdict &certificate() const { return m_verdict; }

signals:
    void opened(QIODevice *device);
    void lost(const QString &reason);          // an opened device went away; a retry follows unless closed
    void attemptFailed(const QString &reason); // an attempt to open failed; a retry follows
    // Over TLS, just before opened(): the vehicle's certificate was accepted (verdict.firstUse(): it
    // is now remembered, and its fingerprint should be shown).
    void certificateAccepted(const sortie::tls::TlsVerdict &verdict);
    void stateChanged(sortie::vci::VciTransport::State state);

private:
    void attempt();
    void onOpened();
    void onEncrypted();
    void onFailed(QIODevice *device, const QString &reason);
    void drop(const QString &reason);
    void setState(State state);

    VciEndpoint m_endpoint;
    State m_state = State::Closed;
    QIODevice *m_device = nullptr;
    QTimer m_retry;
    int m_firstDelay = 250, m_maxDelay = 5000, m_delay = 250;
    QString m_lastError;
    tls::CertificateStore *m_store = nullptr;
    tls::TlsVerdict m_verdict;
};

} // namespace sortie::vci
