#pragma once

#include <QColor>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QTcpServer>

class QTcpSocket;

namespace sortie::test {

// An HTTP/1.1 tile server on 127.0.0.1 for the prefetch tests: GET /{z}/{x}/{y}.png answers a
// generated 256 px PNG whose colour encodes the tile (colourFor). Faults are injected per tile for
// its first `times` requests: 404, 429 with Retry-After, 503, a slow answer, a dropped connection,
// or HTML instead of an image. It counts every request, per tile, with its time, and the most
// requests it ever had in hand at once (received, not yet answered).
class FaultyTileServer : public QObject
{
    Q_OBJECT

public:
    enum class Fault { None, NotFound, TooManyRequests, Unavailable, Slow, Drop, NotImage };
    struct Injection
    {
        Fault fault = Fault::None;
        int times = 1;          // how many requests get it; later ones are answered normally
        int retryAfter = -1;    // seconds, for 429/503 (-1: no header)
        int delayMs = 0;        // for Slow
    };

    explicit FaultyTileServer(QObject *parent = nullptr);

    bool listen();
    quint16 port() const { return m_server.serverPort(); }
    QString urlTemplate() const;
    static QColor colourFor(int z, int x, int y);
    static QByteArray pngFor(int z, int x, int y);

    void inject(const QString &tile, const Injection &injection) { m_injections.insert(tile, injection); }
    // Every answer waits this long (so requests overlap and the concurrency is seen).
    void setResponseDelay(int ms) { m_delayMs = ms; }

    int requests() const { return m_requests; }
    int requestsFor(const QString &tile) const { return int(m_times.value(tile).size()); }
    QList<qint64> requestTimes(const QString &tile) const { return m_times.value(tile); } // ms since listen
    int maximumInFlight() const { return m_maxInFlight; }
    int inFlight() const { return m_inFlight; }
    QStringList userAgents() const { return m_userAgents; }

private:
    void serve(QTcpSocket *socket);
    void answer(QTcpSocket *socket, const QByteArray &response, int delayMs);

    QTcpServer m_server;
    QHash<QString, Injection> m_injections;
    QHash<QString, QList<qint64>> m_times;
    QStringList m_userAgents;
    QElapsedTimer m_clock;
    int m_delayMs = 0;
    int m_requests = 0;
    int m_inFlight = 0;
    int m_maxInFlight = 0;
};

} // namespace sortie::test
