#include "HciServer.h"

#include "HciServerConnection.h"
#include "SimEventService.h"
#include "SimLockService.h"
#include "SimLog.h"
#include "SimNfzService.h"
#include "SimObjectService.h"
#include "SimSessionService.h"
#include "SimExportService.h"
#include "SimTerrainService.h"
#include "SimTrafficService.h"
#include "SimVehicleService.h"
#include "SimWorld.h"
#include "TlsServerIdentity.h"

#include <QTcpSocket>

namespace sortie::sim {

HciServer::HciServer(SimWorld &world, QObject *parent)
    : QObject(parent)
    , m_world(world)
    , m_notifier(world, m_sessions)
    , m_dispatcher(m_sessions)
{
    const SimServices services{m_world, m_sessions, m_notifier};
    m_sessionService = std::make_unique<SimSessionService>(services);
    m_objectService = std::make_unique<SimObjectService>(services);
    m_lockService = std::make_unique<SimLockService>(services);
    m_eventService = std::make_unique<SimEventService>(services);
    m_vehicleService = std::make_unique<SimVehicleService>(services);
    m_sessionService->install(m_dispatcher);
    m_objectService->install(m_dispatcher);
    m_lockService->install(m_dispatcher);
    m_eventService->install(m_dispatcher);
    m_vehicleService->install(m_dispatcher);
    m_exportService = std::make_unique<SimExportService>(services);
    m_exportService->install(m_dispatcher);
    SimTerrainService::install(m_dispatcher, m_world);
    SimTrafficService::install(m_dispatcher, m_world.traffic());
    SimNfzService::install(m_dispatcher, m_world);

    connect(&m_sessions, &SimSessionTable::sessionEnded, this, [this](int clientId) { m_world.locks().releaseAll(clientId); });
}

HciServer::~HciServer()
{
    for (const auto &c : std::as_const(m_connections))
        if (c)
            c->disconnect(this);
}

bool HciServer::listen(const QHostAddress &address, quint16 port)
{
    QString error;
    if (!m_world.start(&error)) {
        m_error = error;
        return false;
    }
    if (m_server)
        m_server->close();
    m_server = tls::makeListener(m_tls);
    // Not newConnection: a TLS listener hands a connection out only once its handshake is done.
    connect(m_server.get(), &QTcpServer::pendingConnectionAvailable, this, &HciServer::onNewConnection);
    if (!m_server->listen(address, port)) {
        m_error = QStringLiteral("Cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(m_server->errorString());
        return false;
    }
    qCInfo(lcSim).noquote() << "HCI server listening on" << address.toString() + u':' + QString::number(m_server->serverPort()) << (m_tls ? "(TLS)" : "");
    return true;
}

void HciServer::close()
{
    if (m_server)
        m_server->close();
    dropConnections();
}

void HciServer::onNewConnection()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        auto *connection = new HciServerConnection(socket, m_dispatcher, m_faults, this);
        m_connections.append(connection);
        connect(connection, &HciServerConnection::closed, this, [this, connection] {
            m_sessions.detach(connection);
            m_connections.removeAll(connection);
            qCInfo(lcSim).noquote() << "client" << connection->peer() << "disconnected";
            connection->deleteLater();
            emit clientDisconnected();
        });
        emit clientConnected();
    }
}

void HciServer::dropConnections()
{
    const auto connections = m_connections;
    for (const auto &c : connections)
        if (c)
            c->drop();
}

int HciServer::connectionCount() const
{
    return int(m_connections.size());
}

void HciServer::setUploadStepMs(int ms)
{
    m_vehicleService->setUploadStepMs(ms);
}

} // namespace sortie::sim
