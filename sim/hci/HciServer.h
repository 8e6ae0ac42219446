#pragma once

#include "HciRequestDispatcher.h"
#include "SimFaults.h"
#include "SimNotifier.h"
#include "SimSessionTable.h"

#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSslConfiguration>
#include <QTcpServer>

#include <memory>
#include <optional>

namespace sortie::sim {

class HciServerConnection;
class SimEventService;
class SimExportService;
class SimLockService;
class SimObjectService;
class SimSessionService;
class SimVehicleService;
class SimWorld;

// The simulated UgCS server: a real HCI server on TCP, built on the same frame codec as the client.
// Embeddable in-process (the desktop app's --demo mode, the tests) as well as run by sortie-sim:
//   sortie::sim::SimWorld world;
//   sortie::sim::HciServer server(world);
//   server.listen(QHostAddress::LocalHost, 0); // then server.port()
class HciServer : public QObject
{
    Q_OBJECT

public:
    static constexpr quint16 kDefaultPort = 3334;

    explicit HciServer(SimWorld &world, QObject *parent = nullptr);
    ~HciServer() override;

    // Serves TLS with this identity (tls::loadServerIdentity) from the next listen(); nullopt: plain.
    void setTls(std::optional<QSslConfiguration> identity) { m_tls = std::move(identity); }
    bool isSecure() const { return m_tls.has_value(); }
    // Starts the world if needed (loading its store) and listens. Port 0 picks a free port.
    bool listen(const QHostAddress &address = QHostAddress::LocalHost, quint16 port = kDefaultPort);
    void close();
    bool isListening() const { return m_server && m_server->isListening(); }
    quint16 port() const { return m_server ? m_server->serverPort() : 0; }
    QString errorString() const { return m_error; }

    SimWorld &world() { return m_world; }
    SimSessionTable &sessions() { return m_sessions; }
    // Test knobs, read live by every connection.
    SimFaults &faults() { return m_faults; }
    // Drops every client connection at once (sessions stay, detached, until they expire).
    void dropConnections();
    // Ends every detached session now, as if its expiry had passed; returns how many.
    int expireSessions() { return m_sessions.expire(true); }
    int connectionCount() const;
    void setUploadStepMs(int ms);

signals:
    void clientConnected();
    void clientDisconnected();

private:
    void onNewConnection();

    SimWorld &m_world;
    std::optional<QSslConfiguration> m_tls;
    std::unique_ptr<QTcpServer> m_server;
    QString m_error;
    SimFaults m_faults;
    SimSessionTable m_sessions;
    SimNotifier m_notifier;
    HciRequestDispatcher m_dispatcher;
    std::unique_ptr<SimSessionService> m_sessionService;
    std::unique_ptr<SimObjectService> m_objectService;
    std::unique_ptr<SimLockService> m_lockService;
    std::unique_ptr<SimEventService> m_eventService;
    std::unique_ptr<SimVehicleService> m_vehicleService;
    std::unique_ptr<SimExportService> m_exportService;
    QList<QPointer<HciServerConnection>> m_connections;
};

} // namespace sortie::sim
