#include "FaultyTileServer.h"

#include <QBuffer>
#include <QImage>
#include <QPointer>
#include <QRegularExpression>
#include <QTcpSocket>
#include <QTimer>

namespace sortie::test {

FaultyTileServer::FaultyTileServer(QObject *parent)
    : QObject(parent)
{
    connect(&m_server, &QTcpServer::newConnection, this, [this] {
        while (QTcpSocket *socket = m_server.nextPendingConnection()) {
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] { serve(socket); });
            connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        }
    });
}

bool FaultyTileServer::listen()
{
    m_clock.start();
    return m_server.listen(QHostAddress::LocalHost, 0);
}

QString FaultyTileServer::urlTemplate() const
{
    return QStringLiteral("http://127.0.0.1:%1/{z}/{x}/{y}.png").arg(port());
}

QColor FaultyTileServer::colourFor(int z, int x, int y)
{
    return QColor(40 + z * 10, (x * 37) % 256, (y * 53) % 256);
}

QByteArray FaultyTileServer::pngFor(int z, int x, int y)
{
    QImage image(256, 256, QImage::Format_RGB32);
    image.fill(colourFor(z, x, y));
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return png;
}

void FaultyTileServer::serve(QTcpSocket *socket)
{
    QByteArray request = socket->property("request").toByteArray() + socket->readAll();
    const qsizetype end = request.indexOf("\r\n\r\n");
    if (end < 0) {
        socket->setProperty("request", request);
        return;
    }
    socket->setProperty("request", request.mid(end + 4));
    const QByteArray head = request.left(end);
    ++m_requests;
    m_maxInFlight = std::max(m_maxInFlight, ++m_inFlight);
    static const QRegularExpression agent(QStringLiteral("(?im)^User-Agent:\\s*(.*)$"));
    m_userAgents.append(agent.match(QString::fromLatin1(head)).captured(1).trimmed());
    static const QRegularExpression tilePath(QStringLiteral("^GET /(\\d+)/(\\d+)/(\\d+)\\.png HTTP/1\\.[01]"));
    const QRegularExpressionMatch match = tilePath.match(QString::fromLatin1(head));
    if (!match.hasMatch()) {
        answer(socket, "HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n", m_delayMs);
        return;
    }
    const int z = match.captured(1).toInt(), x = match.captured(2).toInt(), y = match.captured(3).toInt();
    const QString tile = QStringLiteral("%1/%2/%3").arg(z).arg(x).arg(y);
    m_times[tile].append(m_clock.elapsed());
    Injection injection = m_injections.value(tile);
    if (injection.fault != Fault::None && m_times[tile].size() > injection.times)
        injection.fault = Fault::None;
    const QByteArray retryAfter = injection.retryAfter >= 0 ? "Retry-After: " + QByteArray::number(injection.retryAfter) + "\r\n" : QByteArray();
    const auto plain = [](const QByteArray &status, const QByteArray &extra, const QByteArray &type, const QByteArray &body) {
        return "HTTP/1.1 " + status + "\r\n" + extra + "Content-Type: " + type + "\r\nContent-Length: "
            + QByteArray::number(body.size()) + "\r\n\r\n" + body;
    };
    switch (injection.fault) {
    case Fault::NotFound:
        answer(socket, plain("404 Not Found", {}, "text/plain", "no such tile"), m_delayMs);
        return;
    case Fault::TooManyRequests:
        answer(socket, plain("429 Too Many Requests", retryAfter, "text/plain", "slow down"), m_delayMs);
        return;
    case Fault::Unavailable:
        answer(socket, plain("503 Service Unavailable", retryAfter, "text/plain", "busy"), m_delayMs);
        return;
    case Fault::NotImage:
        answer(socket, plain("200 OK", {}, "text/html; charset=utf-8", "<html><body>Please log in</body></html>"), m_delayMs);
        return;
    case Fault::Drop:
        --m_inFlight;
        socket->abort(); // the connection goes away with no answer
        return;
    case Fault::Slow:
        answer(socket, plain("200 OK", {}, "image/png", pngFor(z, x, y)), injection.delayMs);
        return;
    case Fault::None:
        break;
    }
    answer(socket, plain("200 OK", {}, "image/png", pngFor(z, x, y)), m_delayMs);
}

void FaultyTileServer::answer(QTcpSocket *socket, const QByteArray &response, int delayMs)
{
    QPointer<QTcpSocket> guard(socket);
    QTimer::singleShot(delayMs, this, [this, guard, response] {
        --m_inFlight;
        if (guard && guard->state() == QAbstractSocket::ConnectedState)
            guard->write(response);
    });
}

} // namespace sortie::test
