// The fault proxy between a real client socket and a real echo server on 127.0.0.1.
#include "FaultProxy.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using sortie::sim::FaultProxy;

namespace {
// Echoes every byte back: the upstream peer.
class EchoServer : public QTcpServer
{
public:
    EchoServer()
    {
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = nextPendingConnection())
                connect(s, &QTcpSocket::readyRead, s, [s] { s->write(s->readAll()); });
        });
        listen(QHostAddress::LocalHost, 0);
    }
};

QByteArray readAtLeast(QTcpSocket &s, int n)
{
    QByteArray got;
    QElapsedTimer t;
    t.start();
    // The proxy and the echo server share this thread: wait by spinning the event loop, not by blocking.
    while (got.size() < n && t.elapsed() < 5000) {
        QTest::qWait(5);
        got += s.readAll();
    }
    return got;
}
} // namespace

class TestFaultProxy : public QObject
{
    Q_OBJECT

private slots:
    void forwardsBothWays()
    {
        EchoServer echo;
        FaultProxy proxy(QHostAddress::LocalHost, echo.serverPort());
        QVERIFY(proxy.listen());
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(client.waitForConnected(3000));
        client.write("hello");
        QCOMPARE(readAtLeast(client, 5), QByteArray("hello"));
        QCOMPARE(proxy.bytesToServer(), 5);
        QCOMPARE(proxy.bytesToClients(), 5);
    }

    void silentHoldsBytesUntilResumed()
    {
        EchoServer echo;
        FaultProxy proxy(QHostAddress::LocalHost, echo.serverPort());
        QVERIFY(proxy.listen());
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(client.waitForConnected(3000));
        QTRY_COMPARE(proxy.connectionCount(), 1);
        proxy.setForwarding(false);
        client.write("ping");
        // The proxy has the bytes and holds them: none went on, so none can come back.
        QTRY_COMPARE(proxy.bytesHeld(), qint64(4));
        QCOMPARE(proxy.bytesToServer(), qint64(0));
        QCOMPARE(client.bytesAvailable(), 0);
        QCOMPARE(client.state(), QAbstractSocket::ConnectedState);
        proxy.setForwarding(true);
        QCOMPARE(readAtLeast(client, 4), QByteArray("ping"));
    }

    void injectsGarbageAndDelays()
    {
        EchoServer echo;
        FaultProxy proxy(QHostAddress::LocalHost, echo.serverPort());
        QVERIFY(proxy.listen());
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(client.waitForConnected(3000));
        QTRY_COMPARE(proxy.connectionCount(), 1);
        proxy.injectToClients("junk");
        QCOMPARE(readAtLeast(client, 4), QByteArray("junk"));
        proxy.setDelay(50);
        client.write("later");
        QCOMPARE(readAtLeast(client, 5), QByteArray("later"));
    }

    void dropCutsTheClientAndAcceptsAgain()
    {
        EchoServer echo;
        FaultProxy proxy(QHostAddress::LocalHost, echo.serverPort());
        QVERIFY(proxy.listen());
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(client.waitForConnected(3000));
        QTRY_COMPARE(proxy.connectionCount(), 1);
        QSignalSpy gone(&client, &QTcpSocket::disconnected);
        proxy.dropConnections();
        QVERIFY(gone.wait(3000));
        QCOMPARE(proxy.connectionCount(), 0);
        QTcpSocket again;
        again.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(again.waitForConnected(3000));
        again.write("back");
        QCOMPARE(readAtLeast(again, 4), QByteArray("back"));
    }

    void upstreamDownClosesTheClient()
    {
        quint16 deadPort;
        {
            QTcpServer probe;
            probe.listen(QHostAddress::LocalHost, 0);
            deadPort = probe.serverPort();
        }
        FaultProxy proxy(QHostAddress::LocalHost, deadPort);
        QVERIFY(proxy.listen());
        QTcpSocket client;
        QSignalSpy gone(&client, &QTcpSocket::disconnected);
        client.connectToHost(QHostAddress::LocalHost, proxy.port());
        QVERIFY(client.waitForConnected(3000));
        QVERIFY(gone.wait(3000));
    }
};

QTEST_MAIN(TestFaultProxy)
#include "tst_faultproxy.moc"
