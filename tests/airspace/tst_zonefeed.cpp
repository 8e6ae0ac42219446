// Published zone files fetched from a URL (ZoneFeed) against a real HTTP server on 127.0.0.1 (a
// QTcpServer that answers as the test says): the body is kept as a copy and read by the store as
// any zone file, with the time it was fetched; the store says how old its data is and warns after a
// week, across a restart; a failed fetch (HTTP 404, a body over the limit, no web address, a server
// that closes) names why and leaves the last good copy as it was.
#include "Airspace.h"
#include "Geodesy.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"
#include "ZoneFeed.h"

#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::airspace;
using namespace sortie::mission;

namespace {

// One answer for every request: a status line and a body (or a connection closed at once).
class FeedServer : public QObject
{
public:
    FeedServer()
    {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = m_server.nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                    if (!socket->readAll().contains("\r\n\r\n"))
                        return;
                    ++m_requests;
                    if (m_closeAtOnce) {
                        socket->abort();
                        return;
                    }
                    socket->write("HTTP/1.1 " + m_status + "\r\nContent-Type: application/json\r\nContent-Length: "
                                  + QByteArray::number(m_body.size()) + "\r\nConnection: close\r\n\r\n" + m_body);
                    socket->disconnectFromHost();
                });
            }
        });
    }
    bool listen() { return m_server.listen(QHostAddress::LocalHost); }
    QUrl url(const QString &path) const { return QUrl(QStringLiteral("http://127.0.0.1:%1%2").arg(m_server.serverPort()).arg(path)); }
    void answer(QByteArray status, QByteArray body)
    {
        m_status = std::move(status);
        m_body = std::move(body);
        m_closeAtOnce = false;
    }
    void closeAtOnce() { m_closeAtOnce = true; }
    int requests() const { return m_requests; }

private:
    QTcpServer m_server;
    QByteArray m_status = "200 OK", m_body;
    bool m_closeAtOnce = false;
    int m_requests = 0;
};

QByteArray ed269(const QString &name)
{
    return QStringLiteral(R"({"title": "A published feed", "features": [
        {"identifier": "LVP010", "country": "LVA", "name": "%1", "restriction": "PROHIBITED", "applicability": [{"permanent": "YES"}],
         "geometry": [{"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AGL", "upperLimit": 120,
                       "upperVerticalReference": "AGL", "horizontalProjection": {"type": "Circle", "center": [24.12, 56.95], "radius": 200}}]}]})")
        .arg(name)
        .toUtf8();
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestZoneFeed : public QObject
{
    Q_OBJECT

    struct Store
    {
        explicit Store(const QString &dir)
            : settings(dir + QStringLiteral("/settings.ini"), QSettings::IniFormat)
        {
            Route r;
            Waypoint w;
            w.position = {56.95, 24.10};
            r.segments.push_back(w);
            model.resetRoute(r);
            airspace = std::make_unique<Airspace>(&settings, &analyzer, &model, nullptr);
        }
        QSettings settings;
        RouteModel model;
        RouteAnalyzer analyzer{&model};
        std::unique_ptr<Airspace> airspace;
    };

    static bool hasZone(const Airspace &a, const QString &name)
    {
        for (int r = 0; r < a.count(); ++r)
            if (a.zoneAt(r).name == name)
                return true;
        return false;
    }

private slots:
    void aFeedIsKeptReadAndAged()
    {
        FeedServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        const QString folder = dir.filePath(QStringLiteral("zone-feeds"));
        const QUrl url = server.url(QStringLiteral("/uas/zones.json"));
        QString copy;
        {
            Store store(dir.path());
            ZoneFeed feed(folder);
            QObject::connect(&feed, &ZoneFeed::fetched, store.airspace.get(), &Airspace::loadFeedCopy);
            QSignalSpy fetched(&feed, &ZoneFeed::fetched), failed(&feed, &ZoneFeed::failed);
            server.answer("200 OK", ed269(QStringLiteral("Harbour crane")));
            feed.fetch(url);
            QVERIFY(feed.isBusy());
            QVERIFY2(fetched.wait(10000), qPrintable(feed.problem()));
            QCOMPARE(failed.count(), 0);
            copy = fetched.at(0).at(0).toString();
            QCOMPARE(copy, feed.copyPathOf(url));
            QVERIFY(copy.startsWith(folder + QStringLiteral("/127.0.0.1-")) && copy.endsWith(QStringLiteral(".json")));
            QCOMPARE(readAll(copy), ed269(QStringLiteral("Harbour crane")));
            QVERIFY(hasZone(*store.airspace, QStringLiteral("Harbour crane")));
            QCOMPARE(store.airspace->feedUrls(), QList<QUrl>{url});
            QVERIFY2(store.airspace->dataAge().contains(QStringLiteral("fetched from 127.0.0.1 today")), qPrintable(store.airspace->dataAge()));
            QVERIFY(!store.airspace->dataStale());

            // Failures leave the copy as it was, each naming why.
            server.answer("404 Not Found", "no such feed");
            feed.fetch(url);
            QVERIFY(failed.wait(10000));
            QVERIFY2(feed.problem().contains(QStringLiteral("HTTP 404")), qPrintable(feed.problem()));
            server.closeAtOnce();
            feed.fetch(url);
            QVERIFY(failed.wait(10000));
            QVERIFY2(feed.problem().contains(QStringLiteral("cannot be fetched")), qPrintable(feed.problem()));
            feed.fetch(QUrl(QStringLiteral("ftp://127.0.0.1/zones.json")));
            QCOMPARE(failed.count(), 3);
            QVERIFY2(feed.problem().contains(QStringLiteral("no web address")), qPrintable(feed.problem()));
            QCOMPARE(readAll(copy), ed269(QStringLiteral("Harbour crane")));
            QCOMPARE(fetched.count(), 1);

            // Fetched nine days ago (as the record says): older than a week, said so.
            QVERIFY(store.airspace->loadFeedCopy(copy, url, QDateTime::currentDateTimeUtc().addDays(-9)));
            QVERIFY(store.airspace->dataStale());
            QVERIFY2(store.airspace->dataAge().contains(QStringLiteral("9 day"))
                         && store.airspace->dataAge().contains(QStringLiteral("older than a week")),
                     qPrintable(store.airspace->dataAge()));
        }
        // Restarted without a network: the copy is read again, and still nine days old.
        Store again(dir.path());
        QVERIFY(hasZone(*again.airspace, QStringLiteral("Harbour crane")));
        QVERIFY(again.airspace->dataStale());
        QCOMPARE(again.airspace->feedUrls(), QList<QUrl>{url});
        // Removed: its age and URL go with it.
        again.airspace->removeFile(copy);
        QVERIFY(again.airspace->feedUrls().isEmpty());
        QVERIFY(!again.airspace->dataStale());
    }

    void aBodyOverTheLimitIsNotKept()
    {
        FeedServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        ZoneFeed::Limits limits;
        limits.maxBytes = 4096;
        ZoneFeed feed(dir.filePath(QStringLiteral("feeds")), nullptr, limits);
        QSignalSpy failed(&feed, &ZoneFeed::failed), fetched(&feed, &ZoneFeed::fetched);
        server.answer("200 OK", QByteArray(64 * 1024, ' ') + ed269(QStringLiteral("Too big")));
        const QUrl url = server.url(QStringLiteral("/big.json"));
        feed.fetch(url);
        QVERIFY(failed.wait(10000));
        QVERIFY2(feed.problem().contains(QStringLiteral("larger than")), qPrintable(feed.problem()));
        QVERIFY(!feed.isBusy());
        QVERIFY(!QFile::exists(feed.copyPathOf(url)));
        QCOMPARE(fetched.count(), 0);
        // The feed is free again: a small body is kept.
        server.answer("200 OK", ed269(QStringLiteral("Small")));
        feed.fetch(url);
        QVERIFY(fetched.wait(10000));
        QCOMPARE(readAll(feed.copyPathOf(url)), ed269(QStringLiteral("Small")));
    }

    void noFolderNoFetch()
    {
        ZoneFeed feed(QString{});
        QSignalSpy failed(&feed, &ZoneFeed::failed);
        feed.fetch(QUrl(QStringLiteral("https://zones.example/feed.json")));
        QCOMPARE(failed.count(), 1);
        QVERIFY2(feed.problem().contains(QStringLiteral("no folder")), qPrintable(feed.problem()));
    }
};

QTEST_MAIN(TestZoneFeed)
#include "tst_zonefeed.moc"
