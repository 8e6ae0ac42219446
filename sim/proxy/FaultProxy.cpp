#include "FaultProxy.h"

#include <QTcpSocket>
#include <QTimer>

#include <algorithm>

namespace sortie::sim {

FaultProxy::FaultProxy(QHostAddress upstreamHost, quint16 upstreamPort, QObject *parent)
    : QObject(parent)
    , m_upstreamHost(std::move(upstreamHost))
    , m_upstreamPort(upstreamPort)
{
    connect(&m_server, &QTcpServer::newConnection, this, &FaultProxy::accept);
}

FaultProxy::~FaultProxy()
{
    // Silence the sockets first: an abort emits disconnected, which would re-enter close().
    for (auto &pair : m_pairs) {
        for (QTcpSocket *s : {pair->client.data(), pair->upstream.data()}) {
            if (s) {
                s->disconnect(this);
                s->abort();
                delete s;
            }
        }
    }
}

bool FaultProxy::listen(const QHostAddress &address, quint16 port)
{
    return m_server.listen(address, port);
}

void FaultProxy::accept()
{
    while (QTcpSocket *client = m_server.nextPendingConnection()) {
        auto pair = std::make_unique<Pair>();
        Pair *p = pair.get();
        p->client = client;
        p->upstream = new QTcpSocket(this);
        client->setParent(this);
        connect(client, &QTcpSocket::readyRead, this, [this, p] { pump(p); });
        connect(p->upstream, &QTcpSocket::readyRead, this, [this, p] { pump(p); });
        connect(p->upstream, &QTcpSocket::connected, this, [this, p] { pump(p); });
        connect(client, &QTcpSocket::disconnected, this, [this, p] { close(p); });
        connect(p->upstream, &QTcpSocket::disconnected, this, [this, p] { close(p); });
        connect(p->upstream, &QTcpSocket::errorOccurred, this, [this, p] { close(p); });
        p->upstream->connectToHost(m_upstreamHost, m_upstreamPort);
        m_pairs.push_back(std::move(pair));
        emit connectionCountChanged(connectionCount());
    }
}

void FaultProxy::send(QPointer<QTcpSocket> to, QByteArray bytes, qint64 *counter)
{
    if (bytes.isEmpty())
        return;
    auto write = [to, bytes, counter] {
        if (to && to->state() == QAbstractSocket::ConnectedState) {
            to->write(bytes);
            *counter += bytes.size();
        }
    };
    if (m_delayMs > 0)
        QTimer::singleShot(m_delayMs, this, write);
    else
        write();
}

void FaultProxy::pump(Pair *p)
{
    if (p->client)
        p->heldForServer += p->client->readAll();
    if (p->upstream)
        p->heldForClient += p->upstream->readAll();
    if (!m_forwarding)
        return;
    if (p->upstream && p->upstream->state() == QAbstractSocket::ConnectedState)
        send(p->upstream, std::exchange(p->heldForServer, {}), &m_toServer);
    send(p->client, std::exchange(p->heldForClient, {}), &m_toClients);
}

qint64 FaultProxy::bytesHeld() const
{
    qint64 held = 0;
    for (const auto &pair : m_pairs)
        held += pair->heldForServer.size() + pair->heldForClient.size();
    return held;
}

void FaultProxy::setForwarding(bool on)
{
    m_forwarding = on;
    if (on) {
        for (auto &pair : m_pairs)
            pump(pair.get());
    }
}

void FaultProxy::injectToClients(const QByteArray &bytes)
{
    for (auto &pair : m_pairs)
        send(pair->client, bytes, &m_toClients);
}

void FaultProxy::injectToServer(const QByteArray &bytes)
{
    for (auto &pair : m_pairs)
        send(pair->upstream, bytes, &m_toServer);
}

void FaultProxy::dropConnections()
{
    // Copy first: aborting emits disconnected, which erases from m_pairs.
    std::vector<Pair *> all;
    for (auto &pair : m_pairs)
        all.push_back(pair.get());
    for (Pair *p : all)
        close(p);
}

void FaultProxy::close(Pair *p)
{
    const auto it = std::find_if(m_pairs.begin(), m_pairs.end(), [p](const auto &x) { return x.get() == p; });
    if (it == m_pairs.end())
        return;
    auto owned = std::move(*it);
    m_pairs.erase(it);
    for (QPointer<QTcpSocket> s : {owned->client, owned->upstream}) {
        if (s) {
            s->disconnect(this);
            s->abort();
            s->deleteLater();
        }
    }
    emit connectionCountChanged(connectionCount());
}

} // namespace sortie::sim
