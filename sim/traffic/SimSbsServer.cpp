#include "SimSbsServer.h"

#include "SbsWriter.h"
#include "SimTraffic.h"

#include <QDateTime>
#include <QTcpSocket>

namespace sortie::sim {
namespace {
constexpr double kFeetPerMetre = 1.0 / 0.3048;
constexpr double kKnotsPerMps = 3600.0 / 1852.0;
} // namespace

SimSbsServer::SimSbsServer(const SimTraffic &traffic, QObject *parent)
    : QObject(parent)
    , m_traffic(traffic)
{
    connect(&m_server, &QTcpServer::newConnection, this, &SimSbsServer::onNewConnection);
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &SimSbsServer::tick);
}

bool SimSbsServer::listen(const QHostAddress &address, quint16 port)
{
    if (!m_server.listen(address, port))
        return false;
    m_timer.start();
    return true;
}

int SimSbsServer::clientCount() const
{
    int n = 0;
    for (const auto &c : m_clients)
        n += c ? 1 : 0;
    return n;
}

QByteArray SimSbsServer::round(bool withIdentification) const
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    std::string out;
    for (const SimAircraft &a : m_traffic.aircraftNow()) {
        traffic::sbs::SbsMessage m;
        m.address = a.address;
        if (withIdentification) {
            m.transmission = 1;
            m.callsign = a.callsign.toStdString();
            out += traffic::sbs::writeSbsLine(m, now);
            m.callsign.reset();
        }
        m.transmission = 3;
        m.altitudeFt = a.altitudeM * kFeetPerMetre;
        m.latitude = a.latitude;
        m.longitude = a.longitude;
        m.alert = m.emergency = m.ident = m.onGround = false;
        out += traffic::sbs::writeSbsLine(m, now);
        traffic::sbs::SbsMessage v;
        v.address = a.address;
        v.transmission = 4;
        v.groundSpeedKt = a.groundSpeedMps * kKnotsPerMps;
        v.trackDeg = a.trackDeg;
        v.verticalRateFpm = a.verticalRateMps * kFeetPerMetre * 60.0;
        out += traffic::sbs::writeSbsLine(v, now);
    }
    return QByteArray::fromStdString(out);
}

void SimSbsServer::onNewConnection()
{
    while (QTcpSocket *socket = m_server.nextPendingConnection()) {
        connect(socket, &QTcpSocket::readyRead, socket, [socket] { socket->readAll(); });
        connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        m_clients.append(socket);
        socket->write(round(true));
    }
}

void SimSbsServer::tick()
{
    m_clients.removeIf([](const QPointer<QTcpSocket> &c) { return c.isNull(); });
    if (m_clients.isEmpty())
        return;
    const QByteArray lines = round(++m_ticks % 5 == 0);
    for (const auto &client : m_clients) {
        if (client && client->state() == QAbstractSocket::ConnectedState)
            client->write(lines);
    }
}

} // namespace sortie::sim
