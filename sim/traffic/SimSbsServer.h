#pragma once

#include <QHostAddress>
#include <QList>
#include <QPointer>
#include <QTcpServer>
#include <QTimer>

class QTcpSocket;

namespace sortie::sim {

class SimTraffic;

// The simulated traffic as an ADS-B receiver serves it: SBS-1 lines on TCP (sortie-sim --sbs-port),
// as dump1090 does on port 30003. Every second each aircraft's airborne position (MSG,3) and
// velocity (MSG,4), every fifth second its identification (MSG,1); a new client gets all three at
// once. It only writes: what a client sends is read and thrown away.
class SimSbsServer : public QObject
{
    Q_OBJECT

public:
    static constexpr int kIntervalMs = 1000;

    explicit SimSbsServer(const SimTraffic &traffic, QObject *parent = nullptr);

    // Port 0 picks a free port.
    bool listen(const QHostAddress &address, quint16 port);
    quint16 port() const { return m_server.serverPort(); }
    QString errorString() const { return m_server.errorString(); }
    int clientCount() const;

    // The lines of one round (tests read them to know what a client gets).
    QByteArray round(bool withIdentification) const;

private:
    void onNewConnection();
    void tick();

    const SimTraffic &m_traffic;
    QTcpServer m_server;
    QTimer m_timer;
    QList<QPointer<QTcpSocket>> m_clients;
    int m_ticks = 0;
};

} // namespace sortie::sim
