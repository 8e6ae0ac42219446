#include "TileHttpServer.h"

#include <QBuffer>
#include <QImage>
#include <QRegularExpression>
#include <QTcpSocket>

namespace sortie::test {

TileHttpServer::TileHttpServer(QObject *parent)
    : QObject(parent)
{
    connect(&m_server, &QTcpServer::newConnection, this, [this] {
        while (QTcpSocket *socket = m_server.nextPendingConnection()) {
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] { serve(socket); });
            connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        }
    });
}

bool TileHttpServer::listen(quint16 port)
{
    if (!m_server.listen(QHostAddress::LocalHost, port))
        return false;
    m_port = m_server.serverPort();
    return true;
}

void TileHttpServer::close()
{
    m_server.close();
    for (QTcpSocket *socket : m_server.findChildren<QTcpSocket *>())
        socket->abort();
}

QString TileHttpServer::urlTemplate() const
{
    return QStringLiteral("http://127.0.0.1:%1/{z}/{x}/{y}.png").arg(m_port);
}

QColor TileHttpServer::colourFor(int z, int x, int y)
{
    return QColor(40 + z * 10, (x * 37) % 256, (y * 53) % 256);
}

void TileHttpServer::serve(QTcpSocket *socket)
{
    QByteArray request = socket->property("request").toByteArray() + socket->readAll();
    socket->setProperty("request", request);
    const qsizetype end = request.indexOf("\r\n\r\n");
    if (end < 0)
        return;
    socket->setProperty("request", request.mid(end + 4));
    ++m_requests;
    const QString line = QString::fromLatin1(request.left(request.indexOf("\r\n")));
    static const QRegularExpression tilePath(QStringLiteral("^GET /(\\d+)/(\\d+)/(\\d+)\\.png HTTP/1\\.[01]$"));
    const QRegularExpressionMatch match = tilePath.match(line);
    QByteArray response;
    if (match.hasMatch()) {
        QImage image(256, 256, QImage::Format_RGB32);
        image.fill(colourFor(match.captured(1).toInt(), match.captured(2).toInt(), match.captured(3).toInt()));
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        image.save(&buffer, "PNG");
        response = "HTTP/1.1 200 OK\r\nContent-Type: image/png\r\nCache-Control: public, max-age=3600\r\n"
                   "Content-Length: " + QByteArray::number(png.size()) + "\r\n\r\n" + png;
    } else {
        const QByteArray body = "no such tile";
        response = "HTTP/1.1 404 Not Found\r\nContent-Type: text/plain\r\nContent-Length: "
                   + QByteArray::number(body.size()) + "\r\n\r\n" + body;
    }
    socket->write(response);
}

} // namespace sortie::test
