// The prefetch job against a tile server on 127.0.0.1 (FaultyTileServer): the area's tiles end up in
// the MBTiles file with the provider's attribution; 429 (Retry-After), 503, timeouts and dropped
// connections are retried with back-off; 404 and non-images are named and not stored; the
// concurrency limit is never exceeded (the server counts); the total limit refuses before any
// request; pause, resume, and a new job after a restart skip what is there; a job stopped or a
// process killed mid-way leaves a pack that opens and reads.
#include "FaultyTileServer.h"
#include "MbTilesFile.h"
#include "TilePrefetch.h"

#include <QImage>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie::maptiles;
using sortie::test::FaultyTileServer;
using Fault = FaultyTileServer::Fault;

namespace {
// Around Riga: 1 tile at zoom 8 up to a few dozen at zoom 13.
const GeoBounds kRiga{56.90, 23.95, 57.00, 24.20};

QList<TileId> tilesOf(const TileArea &area, int minZoom, int maxZoom)
{
    QList<TileId> tiles;
    for (int z = minZoom; z <= maxZoom; ++z)
        for (const TileSpan &span : area.spans(z))
            for (int x = span.firstColumn; x <= span.lastColumn; ++x)
                tiles.append({z, x, span.row});
    return tiles;
}

bool waitForEnd(TilePrefetch &job, int timeoutMs = 60000)
{
    QElapsedTimer clock;
    clock.start();
    while (job.state() == TilePrefetch::State::Running && clock.elapsed() < timeoutMs)
        QTest::qWait(10);
    return job.state() == TilePrefetch::State::Finished;
}

// A request of our own to the server, answered: every request the job had sent before it has
// reached the server too (same loopback, same thread), so what the server counted is all there is.
void roundTrip(QNetworkAccessManager &network, const FaultyTileServer &server)
{
    const QString fence = server.urlTemplate().replace(QStringLiteral("{z}/{x}/{y}"), QStringLiteral("0/0/0"));
    QNetworkReply *reply = network.get(QNetworkRequest(QUrl(fence)));
    QSignalSpy finished(reply, &QNetworkReply::finished);
    QVERIFY(reply->isFinished() || finished.wait(10000));
    QCOMPARE(server.requestsFor(QStringLiteral("0/0/0")) > 0, true);
    reply->deleteLater();
}

// What the job asked of the server: every request but the round trips' own.
int jobRequests(const FaultyTileServer &server)
{
    return server.requests() - server.requestsFor(QStringLiteral("0/0/0"));
}

// Every tile in the file is the server's picture of that tile.
void verifyPack(const QString &path, const QList<TileId> &expected, qint64 *count = nullptr)
{
    MbTilesFile file;
    QString error;
    QVERIFY2(file.open(path, MbTilesFile::Mode::ReadOnly, &error), qPrintable(error));
    QCOMPARE(file.integrityCheck(), QStringLiteral("ok"));
    for (const TileId &tile : expected) {
        const auto bytes = file.tile(tile);
        QVERIFY2(bytes, qPrintable(tile.toString() + QStringLiteral(" missing")));
        const QImage image = QImage::fromData(*bytes);
        QCOMPARE(image.pixelColor(7, 7), FaultyTileServer::colourFor(tile.z, tile.x, tile.y));
    }
    if (count)
        *count = file.tileCount();
}
} // namespace

class TestTilePrefetch : public QObject
{
    Q_OBJECT

    QNetworkAccessManager m_network;

private slots:
    void downloadsTheAreaIntoAValidPack()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        server.setResponseDelay(5);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("riga.mbtiles"));
        const TileArea area = TileArea::rectangle(kRiga);
        PrefetchLimits limits;
        limits.maximumConcurrent = 3;
        TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 13, path, {}, QStringLiteral("© Test contributors")}, limits);
        QVERIFY2(job.start(), qPrintable(job.problem()));
        QVERIFY(waitForEnd(job));
        const QList<TileId> tiles = tilesOf(area, 8, 13);
        QCOMPARE(job.total(), tiles.size());
        QCOMPARE(job.downloaded(), tiles.size());
        QCOMPARE(job.failed(), 0);
        QCOMPARE(server.requests(), tiles.size());
        qint64 stored = 0;
        verifyPack(path, tiles, &stored);
        QCOMPARE(stored, tiles.size());
        QVERIFY2(server.maximumInFlight() <= 3, qPrintable(QString::number(server.maximumInFlight())));
        qInfo("%lld tiles, at most %d requests in flight (limit 3)", qint64(tiles.size()), server.maximumInFlight());
        // The provider's policy: who is asking, and the attribution kept with the tiles.
        for (const QString &agent : server.userAgents())
            QCOMPARE(agent, sortieUserAgent());
        QVERIFY(sortieUserAgent().startsWith(QStringLiteral("Sortie/0.")));
        MbTilesFile file;
        QVERIFY(file.open(path, MbTilesFile::Mode::ReadOnly, nullptr));
        const MbTilesMetadata meta = file.metadata();
        QCOMPARE(meta.attribution, QStringLiteral("© Test contributors"));
        QCOMPARE(meta.format, QStringLiteral("png"));
        QCOMPARE(meta.name, QStringLiteral("127.0.0.1"));
        QCOMPARE(meta.minZoom.value(), 8);
        QCOMPARE(meta.maxZoom.value(), 13);
        QCOMPARE(meta.bounds->south, kRiga.south);
        QVERIFY(meta.problems.isEmpty());
    }

    void oneConnectionAtATime()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        server.setResponseDelay(2);
        QTemporaryDir dir;
        PrefetchLimits limits;
        limits.maximumConcurrent = 1;
        TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), TileArea::rectangle(kRiga), 8, 12, dir.filePath(QStringLiteral("a.mbtiles")), {}, {}}, limits);
        QVERIFY(job.start());
        QVERIFY(waitForEnd(job));
        QCOMPARE(server.maximumInFlight(), 1);
    }

    void faultsAreRetriedOrNamed()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        const TileArea area = TileArea::rectangle(kRiga);
        const QList<TileId> tiles = tilesOf(area, 8, 12);
        QVERIFY(tiles.size() >= 8);
        const QString busy = tiles[1].toString(), throttled = tiles[2].toString(), dropped = tiles[3].toString(),
                      slow = tiles[4].toString(), missing = tiles[5].toString(), portal = tiles[6].toString(), down = tiles[7].toString();
        server.inject(busy, {Fault::Unavailable, 2});
        server.inject(throttled, {Fault::TooManyRequests, 1, 1});
        server.inject(dropped, {Fault::Drop, 2});
        server.inject(slow, {Fault::Slow, 1, -1, 3000});
        server.inject(missing, {Fault::NotFound, 99});
        server.inject(portal, {Fault::NotImage, 99});
        server.inject(down, {Fault::Unavailable, 99});
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("faults.mbtiles"));
        PrefetchLimits limits;
        limits.maximumConcurrent = 2;
        limits.timeoutMs = 500;
        limits.firstRetryDelayMs = 50;
        limits.maximumAttempts = 4;
        TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 12, path, {}, {}}, limits);
        QVERIFY(job.start());
        QVERIFY(waitForEnd(job));

        QCOMPARE(server.requestsFor(busy), 3);
        QCOMPARE(server.requestsFor(throttled), 2);
        // Qt sends a GET again once by itself when a kept-alive connection drops; the job retries past that.
        QVERIFY(server.requestsFor(dropped) >= 2);
        QCOMPARE(server.requestsFor(slow), 2);
        QCOMPARE(server.requestsFor(missing), 1);
        QCOMPARE(server.requestsFor(portal), 1);
        QCOMPARE(server.requestsFor(down), 4);
        QVERIFY(job.retries() >= 2 + 1 + 1 + 3);
        // Retry-After: 1 was honoured, and held every request, not only that tile's.
        const QList<qint64> throttledAt = server.requestTimes(throttled);
        QVERIFY2(throttledAt[1] - throttledAt[0] >= 950, qPrintable(QString::number(throttledAt[1] - throttledAt[0])));
        for (const TileId &tile : tiles)
            for (qint64 at : server.requestTimes(tile.toString()))
                QVERIFY2(at <= throttledAt[0] + 100 || at >= throttledAt[0] + 900, qPrintable(tile.toString()));

        const QStringList failures = job.failures();
        QCOMPARE(failures.size(), 3);
        QVERIFY(failures.contains(missing + QStringLiteral(": HTTP 404 Not Found")));
        QVERIFY(failures.contains(portal + QStringLiteral(": not an image (text/html, 39 bytes)")));
        QVERIFY(failures.contains(down + QStringLiteral(": HTTP 503 Service Unavailable (after 4 attempts)")));
        QList<TileId> good = tiles;
        good.removeIf([&](const TileId &t) { return t.toString() == missing || t.toString() == portal || t.toString() == down; });
        qint64 stored = 0;
        verifyPack(path, good, &stored);
        QCOMPARE(stored, good.size()); // nothing of the bad ones
    }

    void totalLimitRefusesBeforeAnyRequest()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        PrefetchLimits limits;
        limits.maximumTiles = 5;
        TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), TileArea::rectangle(kRiga), 8, 12, dir.filePath(QStringLiteral("x.mbtiles")), {}, {}}, limits);
        QVERIFY(!job.start());
        QCOMPARE(job.state(), TilePrefetch::State::Failed);
        QVERIFY2(job.problem().contains(QStringLiteral("more than the limit of 5")), qPrintable(job.problem()));
        roundTrip(m_network, server);
        QCOMPARE(jobRequests(server), 0);
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.mbtiles"))));
    }

    void pauseAndResume()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        server.setResponseDelay(10);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.mbtiles"));
        const TileArea area = TileArea::rectangle(kRiga);
        PrefetchLimits limits;
        limits.maximumConcurrent = 2;
        TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 13, path, {}, {}}, limits);
        QVERIFY(job.start());
        QTRY_VERIFY(job.downloaded() >= 10);
        job.pause();
        QCOMPARE(job.state(), TilePrefetch::State::Paused);
        QCOMPARE(job.inFlight(), 0);
        // The requests aborted by the pause were already written: the server (on this thread) may
        // still read them, so a round trip first. Nothing new is asked after that: the paused job
        // holds no request and no timer that could send one.
        roundTrip(m_network, server);
        QVERIFY(!job.wakeScheduled());
        const int requestsAtPause = jobRequests(server);
        const qint64 downloadedAtPause = job.downloaded();
        qint64 stored = 0;
        verifyPack(path, {}, &stored);
        QCOMPARE(stored, downloadedAtPause); // what arrived is written at the pause
        roundTrip(m_network, server);
        QCOMPARE(jobRequests(server), requestsAtPause);
        job.resume();
        QVERIFY(waitForEnd(job));
        const QList<TileId> tiles = tilesOf(area, 8, 13);
        verifyPack(path, tiles, &stored);
        QCOMPARE(stored, tiles.size());
        // Only the requests cut short by the pause were asked again.
        QVERIFY(jobRequests(server) <= tiles.size() + limits.maximumConcurrent);
    }

    void aNewJobSkipsWhatIsThere()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("r.mbtiles"));
        const TileArea area = TileArea::rectangle(kRiga);
        {
            TilePrefetch first(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 11, path, {}, {}});
            QVERIFY(first.start());
            QVERIFY(waitForEnd(first));
        }
        const int before = server.requests();
        TilePrefetch second(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 12, path, {}, {}});
        QVERIFY(second.start());
        QVERIFY(waitForEnd(second));
        QCOMPARE(second.skipped(), area.tileCount(8, 11));
        QCOMPARE(server.requests() - before, area.tileCount(12));
        verifyPack(path, tilesOf(area, 8, 12));
    }

    void stoppedMidWayLeavesAValidPack()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        server.setResponseDelay(10);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.mbtiles"));
        qint64 downloaded = 0;
        {
            TilePrefetch job(&m_network, {TileUrlTemplate(server.urlTemplate()), TileArea::rectangle(kRiga), 8, 13, path, {}, {}});
            QVERIFY(job.start());
            QTRY_VERIFY(job.downloaded() >= 15);
            downloaded = job.downloaded();
        } // destroyed while running
        qint64 stored = 0;
        verifyPack(path, {}, &stored);
        QVERIFY(stored >= downloaded);
        MbTilesFile file;
        QVERIFY(file.open(path, MbTilesFile::Mode::ReadOnly, nullptr));
        for (quint64 packed : file.storedTiles(0, 24)) {
            const TileId tile{int(packed >> 58), int((packed >> 29) & 0x1fffffff), int(packed & 0x1fffffff)};
            QCOMPARE(QImage::fromData(file.tile(tile).value()).pixelColor(1, 1), FaultyTileServer::colourFor(tile.z, tile.x, tile.y));
        }
    }

    void killedMidWayLeavesAValidPackThatResumes()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        server.setResponseDelay(3);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("k.mbtiles"));
        const TileArea area = TileArea::rectangle(kRiga);
        QList<TileId> tiles = tilesOf(area, 8, 14);
        for (int round = 0; round < 3; ++round) {
            QProcess helper;
            helper.start(QStringLiteral(PREFETCH_HELPER),
                         {server.urlTemplate(), path, QStringLiteral("8"), QStringLiteral("14"), QString::number(kRiga.south),
                          QString::number(kRiga.west), QString::number(kRiga.north), QString::number(kRiga.east)});
            QVERIFY(helper.waitForStarted());
            const int target = server.requests() + 25 + round * 7;
            QTRY_VERIFY_WITH_TIMEOUT(server.requests() >= target || helper.state() == QProcess::NotRunning, 30000);
            helper.kill(); // SIGKILL: no flush, no clean close
            helper.waitForFinished();
            // A killed writer's batch is rolled back by SQLite's journal at the next open for writing.
            MbTilesFile recover;
            QString error;
            QVERIFY2(recover.open(path, MbTilesFile::Mode::ReadWrite, &error), qPrintable(error));
            recover.close();
            qint64 stored = 0;
            verifyPack(path, {}, &stored);
            qInfo("round %d: killed after %d requests, %lld tiles in the pack", round, server.requests(), stored);
        }
        MbTilesFile before;
        QVERIFY(before.open(path, MbTilesFile::Mode::ReadOnly, nullptr));
        const QSet<quint64> storedBefore = before.storedTiles(0, 24);
        before.close();
        QHash<QString, int> requestsBefore;
        for (const TileId &tile : tiles)
            requestsBefore.insert(tile.toString(), server.requestsFor(tile.toString()));
        TilePrefetch resume(&m_network, {TileUrlTemplate(server.urlTemplate()), area, 8, 14, path, {}, {}});
        QVERIFY(resume.start());
        QVERIFY(waitForEnd(resume));
        QCOMPARE(resume.skipped(), storedBefore.size());
        for (const TileId &tile : tiles)
            if (storedBefore.contains(tile.packed()))
                QCOMPARE(server.requestsFor(tile.toString()), requestsBefore.value(tile.toString()));
        verifyPack(path, tiles);
    }
};

QTEST_MAIN(TestTilePrefetch)
#include "tst_tileprefetch.moc"
