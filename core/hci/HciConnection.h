#pragma once

#include "HciError.h"
#include "HciFrameCodec.h"
#include "TlsOptions.h"
#include "TlsVerdict.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <chrono>

class QSslSocket;

namespace sortie::hci {

class HciReply;
class HciSubscription;

// One TCP connection to an HCI server, plain or TLS (setTls): frames requests, matches answers to them by instance id (in
// any order), reports OperationStatus as progress, turns Error frames into HciError, times requests
// out, and routes notifications (instance id -1) to subscriptions by subscription id. Knows nothing of
// sessions or logins (HciSession does). Never blocks: everything is signals.
class HciConnection : public QObject
{
    Q_OBJECT
    Q_PROPERTY(State state READ state NOTIFY stateChanged)

public:
    enum class State { Unconnected, Connecting, Connected };
    Q_ENUM(State)

    static constexpr std::chrono::milliseconds kDefaultRequestTimeout{30000};
    static constexpr std::chrono::milliseconds kDefaultConnectTimeout{10000};

    explicit HciConnection(QObject *parent = nullptr);
    ~HciConnection() override;

    // How the next connections are secured (plain by default). Over TLS, connected() follows the
    // handshake and the certificate's verdict (TlsVerdict): a refused certificate closes the
    // connection with Kind::Certificate before a byte of HCI is written.
    void setTls(const tls::TlsOptions &options) { m_tls = options; }
    const tls::TlsOptions &tlsOptions() const { return m_tls; }
    bool isSecure() const { return m_tls.enabled; }
    // The verdict on the current (or last) server's certificate; Refused with no reason when plain.
    const tls::TlsVerdict &certificate() const { return m_verdict; }

    void connectToServer(const QString &host, quint16 port);
    // Closes the socket; every pending request fails at once with Disconnected.
    void disconnectFromServer();
    // Gives the connection up as lost (e.g. a link that went silent): like disconnectFromServer(),
    // but disconnected() carries `reason`, so the session reconnects and the log says why.
    void drop(const HciError &reason);
    State state() const { return m_state; }
    QString peerName() const { return m_peer; }

    // Sends a request and returns its reply (owned by this connection; see HciReply for deletion).
    // A request that cannot go out (not connected, not an HCI message, missing required fields) gets
    // a reply that fails on the next event-loop turn. timeout 0 means defaultTimeout().
    HciReply *send(const google::protobuf::Message &request, std::chrono::milliseconds timeout = {});

    void setDefaultTimeout(std::chrono::milliseconds timeout) { m_defaultTimeout = timeout; }
    std::chrono::milliseconds defaultTimeout() const { return m_defaultTimeout; }
    void setConnectTimeout(std::chrono::milliseconds timeout) { m_connectTimeout = timeout; }

    // Notifications carrying subscriptionId go to `subscription` until unrouted or disconnected.
    void route(int32_t subscriptionId, HciSubscription *subscription);
    void unroute(int32_t subscriptionId);

    int pendingCount() const { return int(m_pending.size()); }
    quint64 framesReceived() const { return m_framesReceived; }
    // Every byte read from any server since this object was made: proof of life, whatever it was.
    quint64 bytesReceived() const { return m_bytesReceived; }
    quint64 framesDropped() const { return m_framesDropped; }
    quint64 unroutedNotifications() const { return m_unrouted; }
    // Frames of at least kDecodeAsideFromBytes are decoded on another thread, in stream order.
    static constexpr size_t kDecodeAsideFromBytes = size_t(1) << 20;
    quint64 framesDecodedAside() const { return m_framesDecodedAside; }

signals:
    void stateChanged(sortie::hci::HciConnection::State state);
    void connected();
    // Over TLS, just before connected(): the certificate was accepted (verdict.firstUse(): it was
    // trusted for the first time and is now remembered; its fingerprint should be shown).
    void certificateAccepted(const sortie::tls::TlsVerdict &verdict);
    // The connection closed, or a connection attempt failed (Refused, Unreachable, Disconnected).
    void disconnected(const sortie::hci::HciError &reason);
    // A frame that could not be used: bad header or payload, or an answer no request waits for.
    void frameDropped(const QString &reason);
    // A notification whose subscription id has no route.
    void unroutedNotification(const pb::Notification &notification);

private:
    void onConnected();
    void onEncrypted();
    void onReadyRead();
    void onSocketError();
    bool takeFrames();
    void decodeAside(HciRawFrame frame);
    void forgetDecodingAside();
    void handle(HciFrameDecoder::Result &result);
    void dispatch(HciFrame &frame);
    void dispatchNotification(const HciFrame &frame);
    void dropFrame(const QString &reason);
    void onTimeout(int32_t instanceId);
    void closeWith(const HciError &reason);
    int32_t nextInstanceId();
    void setState(State state);

    QSslSocket *m_socket;
    tls::TlsOptions m_tls;
    tls::TlsVerdict m_verdict;
    QString m_host;
    QTimer m_connectTimer;
    State m_state = State::Unconnected;
    QString m_peer;
    HciFrameDecoder m_decoder;
    std::string m_outBuffer;
    QHash<int32_t, QPointer<HciReply>> m_pending;
    QHash<int32_t, QPointer<HciSubscription>> m_routes;
    int32_t m_nextInstanceId = 0;
    std::chrono::milliseconds m_defaultTimeout = kDefaultRequestTimeout;
    std::chrono::milliseconds m_connectTimeout = kDefaultConnectTimeout;
    quint64 m_framesReceived = 0;
    quint64 m_bytesReceived = 0;
    quint64 m_framesDropped = 0;
    quint64 m_unrouted = 0;
    int m_reading = 0; // > 0 while inside the socket's readyRead
    bool m_decodingAside = false;
    quint64 m_generation = 0; // which connection a frame decoding aside belongs to
    quint64 m_framesDecodedAside = 0;
};

} // namespace sortie::hci
