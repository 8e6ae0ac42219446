// The offline base map: the committed Natural Earth outlines load, and rendered tiles put land
// and sea where they are on Earth, across the antimeridian and at the poles too.
#include "LandOutlines.h"
#include "LandTileRenderer.h"
#include "OfflineTileSource.h"
#include "WebMercator.h"

#include <QFile>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace sortie::ui;

namespace {

struct Place
{
    const char *name;
    double latitude;
    double longitude;
    bool land;
    int minZoom; // small features are a pixel or two wide at low zoom
};

TileKey tileAt(double latitude, double longitude, int z)
{
    const QPointF p = WebMercator::project(latitude, longitude) * std::exp2(z);
    return {z, int(p.x()), std::min(int(p.y()), (1 << z) - 1)};
}

QPoint pixelIn(const TileKey &key, double latitude, double longitude)
{
    const QPointF p = WebMercator::project(latitude, longitude) * std::exp2(key.z) * 256.0;
    return QPoint(std::clamp(int(p.x() - key.x * 256), 0, 255), std::clamp(int(p.y() - key.y * 256), 0, 255));
}

} // namespace

class TestBaseMap : public QObject
{
    Q_OBJECT

private slots:
    void loadsTheCommittedOutlines()
    {
        QString error;
        const auto outlines = LandOutlines::fromResource(&error);
        QVERIFY2(outlines.has_value(), qPrintable(error));
        QVERIFY(outlines->polygons().size() > 1000);
        QVERIFY(outlines->pointCount() > 50000);
    }

    void rejectsDamagedFiles()
    {
        QString error;
        QVERIFY(!LandOutlines::fromData(QByteArray("garbage"), &error));
        QVERIFY(error.contains(QStringLiteral("not compressed")));
        QVERIFY(!LandOutlines::fromData(qCompress(QByteArray("WRONG001")), &error));
        QVERIFY(error.contains(QStringLiteral("does not start with")));
        // A header that promises more polygons than the file holds.
        QByteArray truncated("SLAND001");
        truncated.append("\x05\x00\x00\x00\x02\x00\x00\x00", 8);
        QVERIFY(!LandOutlines::fromData(qCompress(truncated), &error));
        QVERIFY2(error.contains(QStringLiteral("truncated")), qPrintable(error));

        QFile file(QString::fromLatin1(LandOutlines::kResourcePath));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray raw = qUncompress(file.readAll());
        raw.chop(raw.size() / 2);
        QVERIFY(!LandOutlines::fromData(qCompress(raw), &error));
        QVERIFY2(error.contains(QStringLiteral("truncated")), qPrintable(error));
    }

    void landAndSeaWhereTheyAre_data()
    {
        QTest::addColumn<double>("latitude");
        QTest::addColumn<double>("longitude");
        QTest::addColumn<int>("zoom");
        QTest::addColumn<bool>("land");
        const Place places[] = {
            {"Sahara", 23.0, 10.0, true, 0},           {"mid-Pacific", 0.0, -140.0, false, 0},
            {"Siberia", 62.0, 100.0, true, 0},         {"South Atlantic", -30.0, -15.0, false, 0},
            {"Chukotka (west of 180)", 66.0, -173.0, true, 3}, {"Bering Sea", 58.0, -178.0, false, 0},
            {"Antarctica", -80.0, 30.0, true, 0},      {"Amazon", -5.0, -60.0, true, 0},
            {"Caspian Sea (a hole)", 42.0, 50.5, false, 3}, {"Gulf of Riga", 57.6, 23.5, false, 3},
            {"Latvia", 56.9, 25.5, true, 3},
        };
        for (const Place &place : places) {
            for (int zoom : {0, 3, 7}) {
                if (zoom < place.minZoom)
                    continue;
                QTest::addRow("%s z%d", place.name, zoom) << place.latitude << place.longitude << zoom << place.land;
            }
        }
    }

    void landAndSeaWhereTheyAre()
    {
        QFETCH(double, latitude);
        QFETCH(double, longitude);
        QFETCH(int, zoom);
        QFETCH(bool, land);
        QString error;
        static const auto outlines = LandOutlines::fromResource(&error);
        QVERIFY2(outlines, qPrintable(error));
        const MapPalette palette = MapPalette::light();
        const TileKey key = tileAt(latitude, longitude, zoom);
        const QImage tile = LandTileRenderer::render(*outlines, key, palette);
        QCOMPARE(tile.size(), QSize(256, 256));
        const QColor seen = tile.pixelColor(pixelIn(key, latitude, longitude));
        QCOMPARE(seen, land ? palette.land : palette.sea);
    }

    void sourceRendersOnWorkerThreadsAndFollowsDarkMode()
    {
        OfflineTileSource source;
        QVERIFY(source.isReachable());
        QCOMPARE(source.attribution(), QStringLiteral("Land outlines: Natural Earth"));
        QSignalSpy ready(&source, &TileSource::tileReady);
        QSignalSpy invalidated(&source, &TileSource::invalidated);
        source.requestTile(tileAt(23, 10, 2));
        QVERIFY(ready.wait(5000));
        QImage image = ready.takeFirst().at(1).value<QImage>();
        QCOMPARE(image.pixelColor(pixelIn(tileAt(23, 10, 2), 23, 10)), MapPalette::light().land);

        source.setPalette(MapPalette::dark());
        QCOMPARE(invalidated.count(), 1);
        source.requestTile(tileAt(0, -140, 2));
        QVERIFY(ready.wait(5000));
        image = ready.takeFirst().at(1).value<QImage>();
        QCOMPARE(image.pixelColor(pixelIn(tileAt(0, -140, 2), 0, -140)), MapPalette::dark().sea);
    }
};

QTEST_GUILESS_MAIN(TestBaseMap)
#include "tst_basemap.moc"
