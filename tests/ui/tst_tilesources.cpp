// Tile sources against real peers: an HTTP tile server on loopback (with the disk cache and an
// outage), and MBTiles files written with SQLite.
#include "MbTilesTileSource.h"
#include "TileHttpServer.h"
#include "XyzTileSource.h"

#include <QBuffer>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie::ui;
using sortie::test::TileHttpServer;

namespace {

QByteArray png(QColor colour)
{
    QImage image(256, 256, QImage::Format_RGB32);
    image.fill(colour);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return bytes;
}

// Waits for the answer to one request: the image, or a null image and the failure message.
std::pair<QImage, QString> fetch(TileSource &source, const TileKey &key)
{
    QSignalSpy ready(&source, &TileSource::tileReady);
    QSignalSpy failed(&source, &TileSource::tileFailed);
    source.requestTile(key);
    for (int i = 0; i < 100 && ready.isEmpty() && failed.isEmpty(); ++i)
        QTest::qWait(50);
    for (const auto &args : ready) {
        if (args.at(0).value<TileKey>() == key)
            return {args.at(1).value<QImage>(), {}};
    }
    for (const auto &args : failed) {
        if (args.at(0).value<TileKey>() == key)
            return {{}, args.at(1).toString()};
    }
    return {{}, QStringLiteral("no answer")};
}

} // namespace

class TestTileSources : public QObject
{
    Q_OBJECT

private slots:
    void urlTemplates()
    {
        XyzTileSource source;
        QVERIFY(!source.isReachable());
        QVERIFY(source.errorString().contains(QStringLiteral("No tile URL template")));
        QVERIFY(!XyzTileSource::validateTemplate(QStringLiteral("https://a.example/{z}/{x}.png")).isEmpty());
        QVERIFY(!XyzTileSource::validateTemplate(QStringLiteral("ftp://a.example/{z}/{x}/{y}.png")).isEmpty());
        QVERIFY(XyzTileSource::validateTemplate(QStringLiteral("https://a.example/{z}/{x}/{-y}.png")).isEmpty());

        source.setUrlTemplate(QStringLiteral("https://{s}.tiles.example/{z}/{x}/{y}.png?tms={-y}"));
        source.setSubdomains(QStringLiteral("abc"));
        QVERIFY(source.isReachable());
        QCOMPARE(source.name(), QStringLiteral("a.tiles.example"));
        QCOMPARE(source.tileUrl({3, 2, 1}), QUrl(QStringLiteral("https://a.tiles.example/3/2/1.png?tms=6")));
        QCOMPARE(source.tileUrl({3, 2, 2}), QUrl(QStringLiteral("https://b.tiles.example/3/2/2.png?tms=5")));
        QVERIFY(source.tileUrl({3, 9, 1}).isEmpty()); // no such tile
    }

    void fetchesThenServesFromDiskCache()
    {
        QTemporaryDir cache;
        TileHttpServer server;
        QVERIFY(server.listen());
        {
            XyzTileSource source;
            source.setCacheDirectory(cache.path());
            source.setUrlTemplate(server.urlTemplate());
            const auto [image, error] = fetch(source, {4, 5, 6});
            QVERIFY2(!image.isNull(), qPrintable(error));
            QCOMPARE(image.pixelColor(128, 128), TileHttpServer::colourFor(4, 5, 6));
            QCOMPARE(server.requests(), 1);
            QVERIFY(source.isReachable());
        }
        server.close();
        // The server is gone: a new source finds the tile in the disk cache.
        XyzTileSource offline;
        offline.setCacheDirectory(cache.path());
        offline.setUrlTemplate(server.urlTemplate());
        const auto [image, error] = fetch(offline, {4, 5, 6});
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.pixelColor(10, 10), TileHttpServer::colourFor(4, 5, 6));
        QCOMPARE(server.requests(), 1);
    }

    void missingTileIsNotAnOutage()
    {
        QTemporaryDir cache;
        TileHttpServer server;
        QVERIFY(server.listen());
        XyzTileSource source;
        source.setCacheDirectory(cache.path());
        source.setUrlTemplate(QStringLiteral("http://127.0.0.1:%1/missing/{z}/{x}/{y}").arg(server.port()));
        const auto [image, error] = fetch(source, {2, 1, 1});
        QVERIFY(image.isNull());
        QVERIFY2(error.contains(QStringLiteral("HTTP 404")), qPrintable(error));
        QVERIFY(source.isReachable());
    }

    void outageThenRecovery()
    {
        QTemporaryDir cache;
        TileHttpServer server;
        QVERIFY(server.listen());
        const quint16 port = server.port();
        server.close();

        XyzTileSource source;
        source.setCacheDirectory(cache.path());
        source.setRetryInterval(0);
        source.setUrlTemplate(server.urlTemplate());
        QSignalSpy reachability(&source, &TileSource::reachableChanged);
        const auto [nothing, error] = fetch(source, {3, 3, 3});
        QVERIFY(nothing.isNull());
        QVERIFY2(error.contains(QStringLiteral("unreachable")), qPrintable(error));
        QVERIFY(!source.isReachable());
        QVERIFY2(source.errorString().contains(QStringLiteral("unreachable")), qPrintable(source.errorString()));

        // The server comes back on the same port: the next request probes it and succeeds.
        QVERIFY(server.listen(port));
        const auto [image, again] = fetch(source, {3, 3, 3});
        QVERIFY2(!image.isNull(), qPrintable(again));
        QVERIFY(source.isReachable());
        QVERIFY(reachability.count() >= 2);
    }

    void mbtilesReadsTmsRows()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("area.mbtiles"));
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("writer"));
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery q(db);
            QVERIFY(q.exec(QStringLiteral("CREATE TABLE metadata (name TEXT, value TEXT)")));
            QVERIFY(q.exec(QStringLiteral("CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB)")));
            QVERIFY(q.exec(QStringLiteral("INSERT INTO metadata VALUES ('name', 'Test area'), ('attribution', 'Test data'), ('minzoom', '1'), ('maxzoom', '2')")));
            QVERIFY(q.prepare(QStringLiteral("INSERT INTO tiles VALUES (?, ?, ?, ?)")));
            // XYZ tile 1/0/0 (north-west) is TMS row 1.
            q.addBindValue(1);
            q.addBindValue(0);
            q.addBindValue(1);
            q.addBindValue(png(Qt::red));
            QVERIFY(q.exec());
            q.addBindValue(1);
            q.addBindValue(0);
            q.addBindValue(0);
            q.addBindValue(QByteArray("not an image"));
            QVERIFY(q.exec());
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("writer"));

        MbTilesTileSource source;
        source.setFile(QUrl::fromLocalFile(path).toString());
        QVERIFY2(source.isValid(), qPrintable(source.errorString()));
        QCOMPARE(source.name(), QStringLiteral("Test area"));
        QCOMPARE(source.attribution(), QStringLiteral("Test data"));
        QCOMPARE(source.minimumZoomLevel(), 1);
        QCOMPARE(source.maximumZoomLevel(), 2);
        const auto [image, error] = fetch(source, {1, 0, 0});
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.pixelColor(5, 5), QColor(Qt::red));
        const auto [missing, why] = fetch(source, {1, 1, 1});
        QVERIFY(missing.isNull());
        QVERIFY2(why.contains(QStringLiteral("no tile 1/1/1")), qPrintable(why));
        const auto [broken, because] = fetch(source, {1, 0, 1});
        QVERIFY(broken.isNull());
        QVERIFY2(because.contains(QStringLiteral("not a raster image")), qPrintable(because));
    }

    void mbtilesBadFiles()
    {
        QTemporaryDir dir;
        MbTilesTileSource source;
        source.setFile(dir.filePath(QStringLiteral("absent.mbtiles")));
        QVERIFY(!source.isValid());
        QVERIFY(source.errorString().contains(QStringLiteral("does not exist")));
        const auto [image, error] = fetch(source, {0, 0, 0});
        QVERIFY(image.isNull());
        QVERIFY(!error.isEmpty());

        const QString text = dir.filePath(QStringLiteral("notes.mbtiles"));
        QFile file(text);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("these are not tiles\n");
        file.close();
        source.setFile(text);
        QVERIFY(!source.isValid());
        QVERIFY2(source.errorString().contains(QStringLiteral("not an MBTiles file")), qPrintable(source.errorString()));
    }
};

QTEST_GUILESS_MAIN(TestTileSources)
#include "tst_tilesources.moc"
