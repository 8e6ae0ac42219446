// A folder of many elevation rasters (IndexedDemSource): the files' boxes indexed once, a file opened
// only when a point falls in its box and at most N open at a time; heights right across 200 tiles,
// bad files named once while the others answer, rotated and degenerate geotransforms.
#include "DemOpener.h"
#include "DemRaster.h"
#include "GeoTiffWriter.h"
#include "IndexedDemSource.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace sortie;
using namespace sortie::raster;
using namespace sortie::raster::test;

namespace {

// 200 tiles of 0.1° (20 columns × 10 rows over 24..26 E, 56..57 N), each 8×8 pixels of 0.0125°.
constexpr int kColumns = 20, kRows = 10, kPixels = 8;
constexpr double kTile = 0.1, kPixel = kTile / kPixels;
// The height at global pixel (row, column), counted from the north-west corner of the whole folder.
double heightAt(int row, int column) { return 50 + 0.5 * row + 0.25 * column; }

QString tileName(int row, int column) { return QStringLiteral("t%1_%2.tif").arg(row, 2, 10, QLatin1Char('0')).arg(column, 2, 10, QLatin1Char('0')); }

bool writeTiles(const QString &folder)
{
    for (int tr = 0; tr < kRows; ++tr)
        for (int tc = 0; tc < kColumns; ++tc) {
            GeoTiffSpec s;
            s.width = s.height = kPixels;
            const double gt[6] = {24.0 + tc * kTile, kPixel, 0, 57.0 - tr * kTile, 0, -kPixel};
            std::copy(gt, gt + 6, s.geoTransform);
            if (!writeGeoTiff(folder + QLatin1Char('/') + tileName(tr, tc), s,
                              [&](int, int r, int c) { return heightAt(tr * kPixels + r, tc * kPixels + c); }))
                return false;
        }
    return true;
}

bool writeGarbage(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write("II*\0this is not a TIFF at all", 30) == 30;
}

} // namespace

class TestDemFolderIndex : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(writeTiles(m_dir.path()));
    }

    void twoHundredTilesAnswerWithAtMostSixteenOpen()
    {
        QString error;
        std::unique_ptr<terrain::ElevationSource> dem = openDem(m_dir.path(), &error);
        QVERIFY2(dem, qPrintable(error));
        auto *indexed = qobject_cast<IndexedDemSource *>(dem.get());
        QVERIFY(indexed);
        QCOMPARE(indexed->indexedCount(), kColumns * kRows);
        QCOMPARE(indexed->openCount(), 0);  // headers read, every file closed again
        QCOMPARE(indexed->maxOpen(), IndexedDemSource::kDefaultMaxOpen);
        QVERIFY(indexed->problems().isEmpty());
        // Pixel centres all over the folder, in random order: each is that pixel's height exactly.
        QRandomGenerator random(25);
        for (int i = 0; i < 2000; ++i) {
            const int row = int(random.bounded(kRows * kPixels)), column = int(random.bounded(kColumns * kPixels));
            const double lat = 57.0 - (row + 0.5) * kPixel, lon = 24.0 + (column + 0.5) * kPixel;
            const terrain::ElevationSample s = dem->sample({lat, lon});
            QVERIFY2(s.hasValue(), qPrintable(QStringLiteral("no height at %1, %2").arg(lat).arg(lon)));
            QCOMPARE(s.ground, heightAt(row, column));
            QVERIFY(indexed->openCount() <= IndexedDemSource::kDefaultMaxOpen);
        }
        QCOMPARE(indexed->openCount(), IndexedDemSource::kDefaultMaxOpen);
        QVERIFY(indexed->opens() > kColumns * kRows);  // closed ones were opened again
        // Outside every tile: no data, and nothing opened for it.
        const long opens = indexed->opens();
        QCOMPARE(dem->sample({10.0, 10.0}).status, terrain::SampleStatus::NoData);
        QCOMPARE(dem->sample({57.5, 25.0}).status, terrain::SampleStatus::NoData);
        QCOMPARE(indexed->opens(), opens);
    }

    void aPathReusesTheOpenTiles()
    {
        QStringList files;
        for (const QString &name : QDir(m_dir.path()).entryList({QStringLiteral("*.tif")}, QDir::Files, QDir::Name))
            files << m_dir.filePath(name);
        QString error;
        auto dem = IndexedDemSource::open(m_dir.path(), files, &error, 4);
        QVERIFY2(dem, qPrintable(error));
        // West to east along one row of tiles: each tile opened once, never more than 4 open.
        const double lat = 56.55;
        for (int i = 0; i < 400; ++i) {
            QVERIFY(dem->sample({lat, 24.0 + (i + 0.5) * (2.0 / 400)}).hasValue());
            QVERIFY(dem->openCount() <= 4);
        }
        QCOMPARE(dem->opens(), long(kColumns));
    }

    void badFilesAreNamedOnceAndTheOthersAnswer()
    {
        QTemporaryDir dir;
        GeoTiffSpec s;
        s.width = s.height = 4;
        const double gt[6] = {24.0, 0.25, 0, 57.0, 0, -0.25};
        std::copy(gt, gt + 6, s.geoTransform);
        QVERIFY(writeGeoTiff(dir.filePath(QStringLiteral("good.tif")), s, [](int, int, int) { return 77; }));
        QVERIFY(writeGarbage(dir.filePath(QStringLiteral("broken.tif"))));
        GeoTiffSpec flat = s;  // a zero pixel height: no pixel can be placed
        flat.geoTransform[5] = 0;
        QVERIFY(writeGeoTiff(dir.filePath(QStringLiteral("flat.tif")), flat, [](int, int, int) { return 1; }));
        QString error;
        auto dem = openDem(dir.path(), &error);
        QVERIFY2(dem, qPrintable(error));
        QCOMPARE(dem->sample({56.5, 24.5}).ground, 77.0);
        for (int i = 0; i < 10; ++i)
            dem->sample({56.1 + i * 0.08, 24.1});
        const QStringList problems = dem->problems();
        QCOMPARE(problems.size(), 2);
        QVERIFY2(problems[0].startsWith(dir.filePath(QStringLiteral("broken.tif")) + QLatin1String(": ")), qPrintable(problems[0]));
        QVERIFY2(problems[0].size() > dir.filePath(QStringLiteral("broken.tif")).size() + 10, qPrintable(problems[0]));  // GDAL's reason
        QVERIFY2(problems[1].contains(QLatin1String("flat.tif")) && problems[1].contains(QLatin1String("inverted")), qPrintable(problems[1]));
        // Only bad files: the folder fails, naming the first.
        QVERIFY(QFile::remove(dir.filePath(QStringLiteral("good.tif"))));
        QVERIFY(!openDem(dir.path(), &error));
        QVERIFY2(error.contains(QLatin1String("broken.tif")), qPrintable(error));
    }

    // A raster turned by 30°: its box holds all four corners, so every pixel centre is found.
    void rotatedRasterIsFoundEverywhere()
    {
        QTemporaryDir dir;
        GeoTiffSpec s;
        s.width = 12, s.height = 6;
        const double a = 30 * M_PI / 180, size = 0.01;
        const double gt[6] = {24.0, size * std::cos(a), size * std::sin(a), 57.0, size * std::sin(a), -size * std::cos(a)};
        std::copy(gt, gt + 6, s.geoTransform);
        QVERIFY(writeGeoTiff(dir.filePath(QStringLiteral("turned.tif")), s, [](int, int r, int c) { return 10 * r + c; }));
        QVERIFY(writeGeoTiff(dir.filePath(QStringLiteral("z-other.tif")), s, [](int, int, int) { return -1; }));  // the same place, later in order
        QString error;
        auto dem = openDem(dir.path(), &error);
        QVERIFY2(dem, qPrintable(error));
        for (int r = 0; r < s.height; ++r)
            for (int c = 0; c < s.width; ++c) {
                const double lon = gt[0] + gt[1] * (c + 0.5) + gt[2] * (r + 0.5);
                const double lat = gt[3] + gt[4] * (c + 0.5) + gt[5] * (r + 0.5);
                const terrain::ElevationSample h = dem->sample({lat, lon});
                QVERIFY2(h.hasValue(), qPrintable(QStringLiteral("pixel %1, %2").arg(r).arg(c)));
                QVERIFY(std::abs(h.ground - (10 * r + c)) < 1e-6);  // z-other.tif is asked only where turned.tif has no value
            }
    }

    // Geotransforms that cannot place pixels, or place them where PROJ's TransformBounds would loop
    // forever (found by fuzz_raster), are refused with the file named; a huge claimed size is read in
    // bounded chunks, never allocated whole.
    void degenerateGeotransformsAreRefused()
    {
        QTemporaryDir dir;
        struct Case
        {
            const char *name;
            double gt[6];
            const char *crs;
        };
        const Case cases[] = {
            {"zero-width.tif", {24.0, 0.0, 0, 57.0, 0, -0.1}, "EPSG:4326"},
            {"far-away.tif", {-1.3e180, 0.25, 0, 6.6e179, 0, -0.25}, "EPSG:3857"},  // TransformBounds never returned
            {"far-utm.tif", {1e20, 30, 0, 6e6, 0, -30}, "EPSG:32635"},
            {"too-thin.tif", {3e8, 1e-12, 0, 6e6, 0, -30}, "EPSG:32635"},
        };
        for (const Case &c : cases) {
            GeoTiffSpec s;
            s.width = s.height = 4;
            std::copy(c.gt, c.gt + 6, s.geoTransform);
            s.crs = QString::fromLatin1(c.crs);
            const QString path = dir.filePath(QString::fromLatin1(c.name));
            QVERIFY(writeGeoTiff(path, s, [](int, int, int) { return 1; }));
            QString error;
            QVERIFY2(!DemRaster::open(path, &error), c.name);
            QVERIFY2(error.startsWith(path + QLatin1String(": ")), qPrintable(error));
        }
        // 2²⁰ pixels a side, sparse on disk: opened, sampled, and no more than 4 chunks held.
        GDALAllRegister();
        const QString huge = dir.filePath(QStringLiteral("huge.tif"));
        CPLStringList options;
        options.SetNameValue("TILED", "YES");
        options.SetNameValue("SPARSE_OK", "TRUE");
        GDALDataset *ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(huge.toUtf8().constData(), 1 << 20, 1 << 20, 1, GDT_Float32, options.List());
        QVERIFY(ds);
        double gt[6] = {24.0, 1e-6, 0, 57.0, 0, -1e-6};
        ds->SetGeoTransform(gt);
        OGRSpatialReference wgs84;
        wgs84.importFromEPSG(4326);
        ds->SetSpatialRef(&wgs84);
        GDALClose(ds);
        QString error;
        auto dem = DemRaster::open(huge, &error, 4);
        QVERIFY2(dem, qPrintable(error));
        QCOMPARE(dem->width(), 1 << 20);
        for (int i = 0; i < 10; ++i)
            QVERIFY(dem->sample(57.0 - 0.1 * i, 24.0 + 0.1 * i).hasValue());
        QVERIFY(dem->cachedChunks() <= 4);
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestDemFolderIndex)
#include "tst_demfolderindex.moc"
