#include "SimVciListener.h"

#include "SimPty.h"
#include "SimVciSession.h"
#include "SimVciVehicle.h"
#include "TlsServerIdentity.h"

#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>

namespace sortie::sim {

SimVciListener::SimVciListener(SimVciVehicle *vehicle, QObject *parent)
    : QObject(parent)
    , m_vehicle(vehicle)
{
}

SimVciListener::~SimVciListener()
{
    for (const auto &s : std::as_const(m_tcpSessions)) {
        if (s)
            s->device()->disconnect(this);
    }
}

bool SimVciListener::listen(quint16 port, QString *error)
{
    if (!m_server) {
        m_server = tls::makeListener(m_tls).release();
        m_server->setParent(this);
        // Not newConnection: a TLS listener hands a connection out only once its handshake is done.
        connect(m_server, &QTcpServer::pendingConnectionAvailable, this, &SimVciListener::onNewConnection);
    }
    if (m_server->listen(QHostAddress::LocalHost, port))
        return true;
    if (error)
        *error = m_server->errorString();
    return false;
}

quint16 SimVciListener::port() const
{
    return m_server ? m_server->serverPort() : 0;
}

bool SimVciListener::openPty(QString *error)
{
    if (m_pty)
        return true;
    auto *pty = new SimPty(this);
    if (!pty->create(error)) {
        delete pty;
        return false;
    }
    m_pty = pty;
    m_ptySession = new SimVciSession(pty, m_vehicle, this);
    connect(pty, &SimPty::peerGone, m_ptySession, &SimVciSession::reset);
    connect(pty, &SimPty::peerGone, this, &SimVciListener::clientDisconnected);
    connect(pty, &SimPty::peerReturned, this, &SimVciListener::clientConnected);
    return true;
}

QString SimVciListener::ptyName() const
{
    return m_pty ? m_pty->slaveName() : QString();
}

QList<SimVciSession *> SimVciListener::sessions() const
{
    QList<SimVciSession *> out;
    for (const auto &s : m_tcpSessions) {
        if (s)
            out << s;
    }
    if (m_ptySession)
        out << m_ptySession;
    return out;
}

void SimVciListener::dropConnections()
{
    const auto sessions = m_tcpSessions;
    for (const auto &s : sessions) {
        if (s)
            s->drop();
    }
    if (m_ptySession)
        m_ptySession->reset();
}

void SimVciListener::onNewConnection()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        auto *session = new SimVciSession(socket, m_vehicle, this);
        socket->setParent(session);
        m_tcpSessions << session;
        auto gone = [this, session] {
            if (!m_tcpSessions.removeAll(session))
                return; // dropped already
            session->deleteLater();
            emit clientDisconnected();
        };
        connect(socket, &QTcpSocket::disconnected, session, gone);
        connect(session, &SimVciSession::dropped, session, gone);
        emit clientConnected();
    }
}

} // namespace sortie::sim
