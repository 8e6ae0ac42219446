#pragma once

#include <QColor>
#include <QTcpServer>

namespace sortie::test {

// A small HTTP/1.1 tile server on 127.0.0.1 for tests: GET /{z}/{x}/{y}.png answers a 256 px
// PNG whose colour encodes z, x and y (colourFor), cacheable for an hour; any other path is 404.
class TileHttpServer : public QObject
{
    Q_OBJECT

public:
    explicit TileHttpServer(QObject *parent = nullptr);

    bool listen(quint16 port = 0);
    void close();
    quint16 port() const { return m_port; }
    int requests() const { return m_requests; }
    QString urlTemplate() const;
    static QColor colourFor(int z, int x, int y);

private:
    void serve(QTcpSocket *socket);

    QTcpServer m_server;
    quint16 m_port = 0;
    int m_requests = 0;
};

} // namespace sortie::test
