// The map reading a pack: the web source serves the pack's tiles without a request, and in
// cache-only mode makes no request at all (the server counts); the Offline maps controller takes
// the open route's area, estimates, downloads and reports progress.
#include "FaultyTileServer.h"
#include "MbTilesFile.h"
#include "OfflineMaps.h"
#include "QuickScene.h"
#include "XyzTileSource.h"

#include <QQmlEngineExtensionPlugin>

#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QTest>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using sortie::test::FaultyTileServer;

namespace {
std::pair<QImage, QString> fetch(ui::TileSource &source, const ui::TileKey &key)
{
    QSignalSpy ready(&source, &ui::TileSource::tileReady);
    QSignalSpy failed(&source, &ui::TileSource::tileFailed);
    source.requestTile(key);
    for (int i = 0; i < 200 && ready.isEmpty() && failed.isEmpty(); ++i)
        QTest::qWait(25);
    for (const auto &args : ready)
        if (args.at(0).value<ui::TileKey>() == key)
            return {args.at(1).value<QImage>(), {}};
    for (const auto &args : failed)
        if (args.at(0).value<ui::TileKey>() == key)
            return {{}, args.at(1).toString()};
    return {{}, QStringLiteral("no answer")};
}

void writePack(const QString &path, const QList<maptiles::TileId> &tiles)
{
    maptiles::MbTilesFile file;
    QVERIFY(file.open(path, maptiles::MbTilesFile::Mode::ReadWrite, nullptr));
    QList<maptiles::MbTilesFile::Tile> rows;
    for (const auto &t : tiles)
        rows.append({t, FaultyTileServer::pngFor(t.z, t.x, t.y)});
    QVERIFY(file.writeTiles(rows, nullptr));
    maptiles::MbTilesMetadata meta;
    meta.attribution = QStringLiteral("© Pack contributors");
    QVERIFY(file.writeMetadata(meta, nullptr));
}
} // namespace

class TestOfflineMaps : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void cacheOnlyMakesNoRequest()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        const QString pack = dir.filePath(QStringLiteral("pack.mbtiles"));
        writePack(pack, {{5, 17, 9}, {6, 35, 19}});
        ui::XyzTileSource source;
        source.setCacheDirectory(dir.filePath(QStringLiteral("cache")));
        source.setCacheOnly(true);
        source.setUrlTemplate(server.urlTemplate());
        source.setPackFile(pack);
        QCOMPARE(source.attribution(), QStringLiteral("© Pack contributors"));
        const auto [image, error] = fetch(source, {5, 17, 9});
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.pixelColor(3, 3), FaultyTileServer::colourFor(5, 17, 9));
        const auto [missing, why] = fetch(source, {5, 18, 9});
        QVERIFY(missing.isNull());
        QVERIFY2(why.contains(QStringLiteral("cache only")), qPrintable(why));
        QCOMPARE(server.requests(), 0);

        // Online, the pack still saves the requests it can.
        source.setCacheOnly(false);
        QVERIFY(!fetch(source, {6, 35, 19}).first.isNull());
        QCOMPARE(server.requests(), 0);
        QVERIFY(!fetch(source, {6, 36, 19}).first.isNull());
        QCOMPARE(server.requests(), 1);
    }

    // A settings file edited by hand: what is not a number in range keeps its default, never 0.
    void unreadableSettingsKeepTheirDefaults()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.ini"));
        int defaultMin = 0, defaultMax = 0;
        double defaultMargin = 0;
        {
            QSettings fresh(dir.filePath(QStringLiteral("fresh.ini")), QSettings::IniFormat);
            maptiles::OfflineMaps maps(&fresh);
            defaultMin = maps.minimumZoom();
            defaultMax = maps.maximumZoom();
            defaultMargin = maps.marginMetres();
        }
        QVERIFY(defaultMargin > 0);
        {
            QSettings settings(path, QSettings::IniFormat);
            settings.setValue(QStringLiteral("offlineMaps/minZoom"), QStringLiteral("twelve"));
            settings.setValue(QStringLiteral("offlineMaps/maxZoom"), 99);
            settings.setValue(QStringLiteral("offlineMaps/margin"), QStringLiteral("-5"));
            settings.setValue(QStringLiteral("offlineMaps/maxConcurrent"), QStringLiteral("many"));
            settings.setValue(QStringLiteral("offlineMaps/area"), QStringLiteral("56.9,x,57.0,24.2"));
        }
        QSettings settings(path, QSettings::IniFormat);
        maptiles::OfflineMaps maps(&settings);
        QCOMPARE(maps.minimumZoom(), defaultMin);
        QCOMPARE(maps.maximumZoom(), defaultMax);
        QCOMPARE(maps.marginMetres(), defaultMargin);
        QCOMPARE(maps.limits().maximumConcurrent, maptiles::PrefetchLimits{}.maximumConcurrent);
        QCOMPARE(maps.tileCount(), -1.0);  // no area: the broken one is not taken as 0,0
    }

    void controllerDownloadsTheRouteArea()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        maptiles::OfflineMaps maps(&settings);
        QCOMPARE(maps.tileCount(), -1.0);
        QVERIFY(!maps.canStart());
        maps.setUrlTemplate(server.urlTemplate());
        QVERIFY2(maps.packFile().endsWith(QStringLiteral("/offline-maps/127.0.0.1.mbtiles")), qPrintable(maps.packFile()));
        maps.setPackFile(dir.filePath(QStringLiteral("route.mbtiles")));
        maps.setMinimumZoom(10);
        maps.setMaximumZoom(13);
        maps.setMarginMetres(300);
        maps.setAttribution(QStringLiteral("© Test"));

        QStandardItemModel route;
        route.setItemRoleNames({{Qt::UserRole, "latitude"}, {Qt::UserRole + 1, "longitude"}});
        for (const auto &[lat, lon] : {std::pair{56.95, 24.10}, {56.96, 24.12}, {56.94, 24.13}}) {
            auto *item = new QStandardItem;
            item->setData(lat, Qt::UserRole);
            item->setData(lon, Qt::UserRole + 1);
            route.appendRow(item);
        }
        QVERIFY(maps.useRouteArea(&route));
        QVERIFY(maps.areaText().contains(QStringLiteral("300 m")));
        const maptiles::TileArea expected = maptiles::TileArea::rectangle(maptiles::GeoBounds{56.94, 24.10, 56.96, 24.13}.grown(300));
        QCOMPARE(maps.tileCount(), double(expected.tileCount(10, 13)));
        QCOMPARE(maps.estimatedBytes(), maps.tileCount() * maptiles::OfflineMaps::kAssumedTileBytes);
        QVERIFY2(maps.estimateText().contains(QStringLiteral("assuming")), qPrintable(maps.estimateText()));
        QVERIFY(maps.canStart());
        maps.start();
        QVERIFY(maps.running());
        QTRY_VERIFY_WITH_TIMEOUT(!maps.running(), 30000);
        QCOMPARE(maps.progress(), 1.0);
        QVERIFY2(maps.progressText().endsWith(QStringLiteral("done")), qPrintable(maps.progressText()));
        QCOMPARE(server.requests(), int(maps.tileCount()));
        // The estimate now uses what a tile of this pack weighs.
        QVERIFY2(maps.estimateText().contains(QStringLiteral("this pack's mean")), qPrintable(maps.estimateText()));

        // A restart remembers the choices and the area.
        maptiles::OfflineMaps again(&settings);
        QCOMPARE(again.minimumZoom(), 10);
        QCOMPARE(again.packFile(), maps.packFile());
        QCOMPARE(again.tileCount(), maps.tileCount());
        QCOMPARE(again.attribution(), QStringLiteral("© Test"));
    }

    // A polygon drawn on the map: counted as TileArea counts it, a bad one refused with its reason
    // (the area there was kept), and remembered across a restart, corners and all.
    void drawnPolygonIsTheArea()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        maptiles::OfflineMaps maps(&settings);
        maps.setMinimumZoom(10);
        maps.setMaximumZoom(15);
        // An L around a lake: concave, so its box would count more tiles.
        const QList<QPointF> lonLat{{24.10, 56.94}, {24.16, 56.94}, {24.16, 56.95}, {24.12, 56.95}, {24.12, 56.98}, {24.10, 56.98}};
        QVariantList corners;
        for (const QPointF &p : lonLat) // as the map tool gives them ...
            corners.append(QVariant::fromValue(QGeoCoordinate(p.y(), p.x())));
        QVERIFY2(maps.usePolygonArea(corners), qPrintable(maps.problem()));
        const maptiles::TileArea expected = maptiles::TileArea::polygon(lonLat);
        QCOMPARE(maps.tileCount(), double(expected.tileCount(10, 15)));
        QVERIFY(maps.tileCount() < double(maptiles::TileArea::rectangle(expected.bounds()).tileCount(10, 15)));
        QVERIFY2(maps.areaText().contains(QStringLiteral("(6 corner")), qPrintable(maps.areaText()));
        QCOMPARE(maps.areaCorners().size(), 6);
        QCOMPARE(maps.areaCorners().at(4).value<QGeoCoordinate>(), QGeoCoordinate(56.98, 24.12));
        QVERIFY(maps.problem().isEmpty());
        const double drawnCount = maps.tileCount();

        // ... or as plain {latitude, longitude} objects; a bow tie is refused, the L kept.
        QSignalSpy estimate(&maps, &maptiles::OfflineMaps::estimateChanged);
        const QVariantList bowTie{QVariantMap{{"latitude", 56.94}, {"longitude", 24.10}}, QVariantMap{{"latitude", 56.98}, {"longitude", 24.16}},
                                  QVariantMap{{"latitude", 56.94}, {"longitude", 24.16}}, QVariantMap{{"latitude", 56.98}, {"longitude", 24.10}}};
        QVERIFY(!maps.usePolygonArea(bowTie));
        QVERIFY2(maps.problem().contains(QStringLiteral("corner 1 and corner 3 cross")), qPrintable(maps.problem()));
        QVERIFY(!maps.usePolygonArea(bowTie.mid(0, 2)));
        QVERIFY2(maps.problem().contains(QStringLiteral("three corners")), qPrintable(maps.problem()));
        QVERIFY(!maps.usePolygonArea({QVariantMap{{"latitude", -17.0}, {"longitude", 179.0}}, QVariantMap{{"latitude", -17.0}, {"longitude", -179.0}},
                                      QVariantMap{{"latitude", -18.0}, {"longitude", -179.0}}}));
        QVERIFY2(maps.problem().contains(QStringLiteral("antimeridian")), qPrintable(maps.problem()));
        QVERIFY(!maps.usePolygonArea({QVariantMap{{"latitude", 56.9}, {"longitude", 24.1}}, QVariantMap{{"latitude", 56.9}},
                                      QVariantMap{{"latitude", 57.0}, {"longitude", 24.2}}}));
        QVERIFY2(maps.problem().contains(QStringLiteral("Corner 2")), qPrintable(maps.problem()));
        QCOMPARE(estimate.count(), 0);
        QCOMPARE(maps.tileCount(), drawnCount);
        QCOMPARE(maps.areaCorners().size(), 6);

        // A restart: the same polygon, not its box.
        {
            maptiles::OfflineMaps again(&settings);
            QCOMPARE(again.tileCount(), drawnCount);
            QCOMPARE(again.areaCorners(), maps.areaCorners());
            QCOMPARE(again.areaText(), maps.areaText());
        }

        // A dragged rectangle replaces it, and a restart remembers the rectangle (not the polygon).
        QVERIFY(maps.useRectangleArea(QGeoCoordinate(56.98, 24.16), QGeoCoordinate(56.94, 24.10)));
        QCOMPARE(maps.tileCount(), double(maptiles::TileArea::rectangle({56.94, 24.10, 56.98, 24.16}).tileCount(10, 15)));
        QCOMPARE(maps.areaCorners().size(), 4);
        QVERIFY(!maps.useRectangleArea(QGeoCoordinate(56.98, 24.16), QGeoCoordinate(56.98, 24.10)));
        QVERIFY2(maps.problem().contains(QStringLiteral("not an area")), qPrintable(maps.problem()));
        maptiles::OfflineMaps afterRectangle(&settings);
        QCOMPARE(afterRectangle.tileCount(), maps.tileCount());
        QCOMPARE(afterRectangle.areaCorners(), maps.areaCorners());
    }

    // Remembered corners edited by hand into nonsense: no area (not the box, another area), never 0,0.
    void unreadableRememberedPolygonIsNoArea()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        settings.setValue(QStringLiteral("offlineMaps/area"), QStringLiteral("56.9,24.1,57.0,24.2"));
        settings.setValue(QStringLiteral("offlineMaps/areaCorners"), QStringLiteral("56.9,24.1;57.0,x;56.95,24.2"));
        maptiles::OfflineMaps maps(&settings);
        QCOMPARE(maps.tileCount(), -1.0);
        QVERIFY(maps.areaCorners().isEmpty());
    }

    // The dialog offscreen: the route's area, the estimate, Download, the progress bar and its text.
    void dialogDrivesTheController()
    {
        FaultyTileServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        maptiles::OfflineMaps maps(&settings);
        maps.setUrlTemplate(server.urlTemplate());
        maps.setPackFile(dir.filePath(QStringLiteral("dialog.mbtiles")));
        maps.setMinimumZoom(9);
        maps.setMaximumZoom(12);
        QStandardItemModel route;
        route.setItemRoleNames({{Qt::UserRole, "latitude"}, {Qt::UserRole + 1, "longitude"}});
        auto *item = new QStandardItem;
        item->setData(56.95, Qt::UserRole);
        item->setData(24.1, Qt::UserRole + 1);
        route.appendRow(item);
        sortie::test::QuickScene scene(R"(
            import QtQuick
            import Sortie.Ui
            Item {
                required property OfflineMaps maps
                required property AbstractItemModel route
                MapView { id: map; objectName: "map"; anchors.fill: parent }
                OfflineMapsDialog { objectName: "dialog"; offlineMaps: maps; routeModel: route; map: map }
            })", QSize(900, 800), {{QStringLiteral("maps"), QVariant::fromValue<QObject *>(&maps)},
                                   {QStringLiteral("route"), QVariant::fromValue<QObject *>(&route)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        QObject *dialog = scene.find(QStringLiteral("dialog"));
        QVERIFY(dialog);
        QMetaObject::invokeMethod(dialog, "open");
        QTRY_VERIFY(dialog->property("opened").toBool());
        QObject *start = scene.find(QStringLiteral("startButton"));
        QVERIFY(start);
        QVERIFY(!start->property("enabled").toBool()); // no area yet
        QMetaObject::invokeMethod(scene.find(QStringLiteral("routeAreaButton")), "clicked");
        QCOMPARE(scene.find(QStringLiteral("estimateLabel"))->property("text").toString(), maps.estimateText());
        QVERIFY(maps.tileCount() > 0);
        QVERIFY(start->property("enabled").toBool());
        QMetaObject::invokeMethod(start, "clicked");
        QTRY_VERIFY_WITH_TIMEOUT(!maps.running(), 30000);
        QCOMPARE(scene.find(QStringLiteral("prefetchProgress"))->property("value").toDouble(), 1.0);
        QVERIFY(scene.find(QStringLiteral("progressLabel"))->property("text").toString().endsWith(QStringLiteral("done")));
        QCOMPARE(server.requests(), int(maps.tileCount()));
    }
};

QTEST_MAIN(TestOfflineMaps)
#include "tst_offlinemaps.moc"
