#pragma once
// A receiver flooding its client (issue 36): `count` MSG,3 lines, each a distinct ICAO address with
// an airborne position north of a reference point, at a distance that is a permutation of 1..count
// times kStepM (so the nearest are neither the first nor the last sent). Served to the first client
// that connects to 127.0.0.1, from a thread of its own with blocking sockets, as fast as the client
// takes it; the thread ends when all is written or the client goes.
#include <QByteArray>
#include <QTcpServer>
#include <QTcpSocket>

#include <cstdio>
#include <future>
#include <thread>

namespace sortie::test {

struct Flood
{
    static constexpr double kStepM = 5.0;
    static constexpr quint32 kFirstAddress = 0x100000;
    static constexpr double kReferenceLatitude = 56.9;
    static constexpr double kReferenceLongitude = 24.1;

    // The rank of aircraft i by distance (0: the nearest); 7919 is prime, so i -> rank is one to one.
    static qint64 rank(qint64 i, qint64 count) { return (i * 7919) % count; }
    static double distanceM(qint64 i, qint64 count) { return double(rank(i, count) + 1) * kStepM; }

    static QByteArray lines(qint64 count)
    {
        QByteArray out;
        out.reserve(count * 100);
        char line[160];
        for (qint64 i = 0; i < count; ++i) {
            const double latitude = kReferenceLatitude + distanceM(i, count) / 111195.0;
            const int n = std::snprintf(line, sizeof line,
                                        "MSG,3,1,1,%06X,1,2026/12/02,10:00:00.000,2026/12/02,10:00:00.000,,37000,,,%.7f,%.7f,,,0,0,0,0\r\n",
                                        unsigned(kFirstAddress + i), latitude, kReferenceLongitude);
            out.append(line, n);
        }
        return out;
    }
};

class FloodFeeder
{
public:
    explicit FloodFeeder(QByteArray feed)
    {
        std::promise<quint16> port;
        m_port = port.get_future();
        m_thread = std::thread([feed = std::move(feed), port = std::move(port)]() mutable {
            QTcpServer server;
            port.set_value(server.listen(QHostAddress::LocalHost) ? server.serverPort() : 0);
            if (!server.isListening() || !server.waitForNewConnection(60000))
                return;
            QTcpSocket *client = server.nextPendingConnection();
            constexpr qsizetype kChunk = 256 * 1024;
            for (qsizetype at = 0; at < feed.size() && client->state() == QAbstractSocket::ConnectedState; at += kChunk) {
                client->write(feed.constData() + at, std::min(kChunk, feed.size() - at));
                while (client->bytesToWrite() > 0 && client->waitForBytesWritten(60000)) {
                }
            }
            client->waitForDisconnected(60000);  // the client closes; or, if it never does, give up
        });
    }
    ~FloodFeeder() { m_thread.join(); }
    quint16 port() { return m_port.valid() ? (m_cached = m_port.get()) : m_cached; }

private:
    std::future<quint16> m_port;
    quint16 m_cached = 0;
    std::thread m_thread;
};

} // namespace sortie::test
