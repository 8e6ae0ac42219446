#pragma once

#include <QList>
#include <QObject>
#include <QPointer>
#include <QSslConfiguration>

#include <optional>

class QTcpServer;

namespace sortie::sim {

class SimPty;
class SimVciSession;
class SimVciVehicle;

// Where clients reach one simulated vehicle: a TCP port on 127.0.0.1 (each connection its own
// session; TLS with setTls) and, on request, a pseudo-terminal whose slave device a client opens as a serial line.
class SimVciListener : public QObject
{
    Q_OBJECT
public:
    explicit SimVciListener(SimVciVehicle *vehicle, QObject *parent = nullptr);
    ~SimVciListener() override;

    // Serves TLS with this identity (tls::loadServerIdentity) from the next listen(); nullopt: plain.
    void setTls(std::optional<QSslConfiguration> identity) { m_tls = std::move(identity); }
    bool isSecure() const { return m_tls.has_value(); }
    bool listen(quint16 port = 0, QString *error = nullptr); // 0: any free port
    quint16 port() const;
    bool openPty(QString *error = nullptr);
    QString ptyName() const; // e.g. "/dev/pts/3"; empty without a pty

    SimVciVehicle *vehicle() const { return m_vehicle; }
    QList<SimVciSession *> sessions() const;
    // Test knob: closes every TCP connection now; the pty's session forgets its client.
    void dropConnections();

signals:
    void clientConnected();
    void clientDisconnected();

private:
    void onNewConnection();

    SimVciVehicle *m_vehicle;
    std::optional<QSslConfiguration> m_tls;
    QTcpServer *m_server = nullptr;
    SimPty *m_pty = nullptr;
    QPointer<SimVciSession> m_ptySession;
    QList<QPointer<SimVciSession>> m_tcpSessions;
};

} // namespace sortie::sim
