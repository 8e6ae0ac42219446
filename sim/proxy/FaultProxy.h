#pragma once

#include <QHostAddress>
#include <QObject>
#include <QPointer>
#include <QTcpServer>

#include <vector>

class QTcpSocket;

namespace sortie::sim {

// A TCP proxy on loopback that misbehaves on request, to prove the client survives bad links:
// it can go silent (keep the connections open but forward nothing), delay every chunk, inject bytes
// into either direction, or cut every connection. Each accepted client gets its own upstream socket.
class FaultProxy : public QObject
{
    Q_OBJECT

public:
    explicit FaultProxy(QHostAddress upstreamHost, quint16 upstreamPort, QObject *parent = nullptr);
    ~FaultProxy() override;

    bool listen(const QHostAddress &address = QHostAddress::LocalHost, quint16 port = 0);
    quint16 port() const { return m_server.serverPort(); }

    // Silent: bytes are read and held back, not forwarded, until forwarding is switched on again.
    void setForwarding(bool on);
    bool isForwarding() const { return m_forwarding; }
    // Every chunk waits this long before it goes on (0 = at once).
    void setDelay(int milliseconds) { m_delayMs = milliseconds; }
    void injectToClients(const QByteArray &bytes);
    void injectToServer(const QByteArray &bytes);
    // Cuts every open connection, both sides; new connections are still accepted.
    void dropConnections();

    int connectionCount() const { return int(m_pairs.size()); }
    qint64 bytesToClients() const { return m_toClients; }
    qint64 bytesToServer() const { return m_toServer; }
    // Bytes read from either side and not yet passed on (held while silent).
    qint64 bytesHeld() const;

signals:
    void connectionCountChanged(int count);

private:
    struct Pair
    {
        QPointer<QTcpSocket> client;
        QPointer<QTcpSocket> upstream;
        QByteArray heldForClient;
        QByteArray heldForServer;
    };

    void accept();
    void pump(Pair *pair);
    void send(QPointer<QTcpSocket> to, QByteArray bytes, qint64 *counter);
    void close(Pair *pair);

    QTcpServer m_server;
    QHostAddress m_upstreamHost;
    quint16 m_upstreamPort;
    std::vector<std::unique_ptr<Pair>> m_pairs;
    bool m_forwarding = true;
    int m_delayMs = 0;
    qint64 m_toClients = 0;
    qint64 m_toServer = 0;
};

} // namespace sortie::sim
