// Elevation rasters through GDAL: GeoTIFFs this test writes (EPSG:4326, UTM, ellipsoidal heights,
// a compound CRS, nodata cells), a .hgt tile read by GDAL against the hand-written reader, what
// --dem opens (file, folder, bad file) and the bounded chunk cache.
#include "DemOpener.h"
#include "DemRaster.h"
#include "Egm96Geoid.h"
#include "GdalDemSource.h"
#include "GeoTiffWriter.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace sortie;
using namespace sortie::raster;
using namespace sortie::raster::test;
using terrain::ElevationSample;

namespace {

// 10×10 pixels of 0.1° over 24..25 E, 56..57 N; h = 100 + 10·column + row at each pixel centre.
GeoTiffSpec degreesSpec(const QString &crs = QStringLiteral("EPSG:4326"))
{
    GeoTiffSpec s;
    s.width = s.height = 10;
    const double gt[6] = {24.0, 0.1, 0, 57.0, 0, -0.1};
    std::copy(gt, gt + 6, s.geoTransform);
    s.crs = crs;
    return s;
}
double linear(int, int r, int c) { return 100 + 10 * c + r; }
// The same linear field anywhere between the pixel centres.
double expectedAt(double lat, double lon)
{
    const double c = (lon - 24.0) / 0.1 - 0.5, r = (57.0 - lat) / 0.1 - 0.5;
    return 100 + 10 * c + r;
}

// Where a WGS-84 point lies in UTM zone 35N, by PROJ through OGR.
QPointF toUtm35(double lat, double lon)
{
    OGRSpatialReference wgs84, utm;
    wgs84.importFromEPSG(4326);
    utm.importFromEPSG(32635);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    auto *t = OGRCreateCoordinateTransformation(&wgs84, &utm);
    double x = lon, y = lat;
    t->Transform(1, &x, &y);
    OGRCoordinateTransformation::DestroyCT(t);
    return {x, y};
}

} // namespace

class TestGdalDem : public QObject
{
    Q_OBJECT

private slots:
    void geographicRasterIsInterpolatedBilinearly();
    void utmRasterIsSampledThroughItsCrs();
    void ellipsoidalHeightsBecomeAmsl();
    void orthometricAndUnstatedHeightsAreKept();
    void nodataIsMissingNeverZero();
    void hgtThroughGdalEqualsTheHandWrittenReader();
    void demOpensFilesAndFolders();
    void badFilesAreNamedWithGdalsReason();
    void chunkCacheStaysBounded();

private:
    QTemporaryDir m_dir;
};

void TestGdalDem::geographicRasterIsInterpolatedBilinearly()
{
    const QString path = m_dir.filePath(QStringLiteral("wgs84.tif"));
    QVERIFY(writeGeoTiff(path, degreesSpec(), linear));
    QString error;
    auto dem = DemRaster::open(path, &error);
    QVERIFY2(dem, qPrintable(error));
    QCOMPARE(dem->verticalDatum().kind, VerticalDatum::Kind::Unstated);
    // On a pixel centre: that pixel.
    ElevationSample s = dem->sample(56.95 - 0.1 * 3, 24.05 + 0.1 * 4);
    QVERIFY(s.hasValue());
    QCOMPARE(s.ground, 100.0 + 40 + 3);
    // Between centres: the bilinear blend (exact for a linear field).
    for (auto [lat, lon] : {std::pair{56.5, 24.5}, {56.123, 24.777}, {56.93, 24.07}}) {
        s = dem->sample(lat, lon);
        QVERIFY(s.hasValue());
        QVERIFY2(std::abs(s.ground - expectedAt(lat, lon)) < 1e-6, qPrintable(QString::number(s.ground)));
    }
    // The outer half pixel is the edge pixel's; outside the raster there is no data.
    QVERIFY(std::abs(dem->sample(56.98, 24.02).ground - 100.0) < 1e-9);
    QCOMPARE(dem->sample(57.01, 24.5).status, terrain::SampleStatus::NoData);
    QCOMPARE(dem->sample(56.5, 23.99).status, terrain::SampleStatus::NoData);
}

void TestGdalDem::utmRasterIsSampledThroughItsCrs()
{
    // 200 m pixels in UTM 35N around Riga; h = 50 + 0.01·(E − E0) + 0.02·(N − N0) (E0, N0 the corner).
    const QPointF corner = toUtm35(57.0, 24.0);
    const double e0 = std::floor(corner.x()), n0 = std::floor(corner.y());
    GeoTiffSpec s;
    s.width = s.height = 100;
    const double gt[6] = {e0, 200, 0, n0, 0, -200};
    std::copy(gt, gt + 6, s.geoTransform);
    s.crs = QStringLiteral("EPSG:32635");
    s.tiled = true;
    const QString path = m_dir.filePath(QStringLiteral("utm.tif"));
    QVERIFY(writeGeoTiff(path, s, [&](int, int r, int c) {
        const double e = e0 + 200 * (c + 0.5), n = n0 - 200 * (r + 0.5);
        return 50 + 0.01 * (e - e0) + 0.02 * (n0 - n);
    }));
    QString error;
    auto dem = DemRaster::open(path, &error);
    QVERIFY2(dem, qPrintable(error));
    for (auto [lat, lon] : {std::pair{56.95, 24.1}, {56.9, 24.2}, {56.88, 24.31}}) {
        const QPointF p = toUtm35(lat, lon);
        const double expected = 50 + 0.01 * (p.x() - e0) + 0.02 * (n0 - p.y());
        const ElevationSample got = dem->sample(lat, lon);
        QVERIFY(got.hasValue());
        QVERIFY2(std::abs(got.ground - expected) < 1e-3, qPrintable(QStringLiteral("%1 vs %2").arg(got.ground).arg(expected)));
    }
    QCOMPARE(dem->sample(57.5, 24.1).status, terrain::SampleStatus::NoData);
}

void TestGdalDem::ellipsoidalHeightsBecomeAmsl()
{
    const QString path = m_dir.filePath(QStringLiteral("ellipsoidal.tif"));
    QVERIFY(writeGeoTiff(path, degreesSpec(QStringLiteral("EPSG:4979")), linear));
    QString error;
    auto dem = DemRaster::open(path, &error);
    QVERIFY2(dem, qPrintable(error));
    QCOMPARE(dem->verticalDatum().kind, VerticalDatum::Kind::Ellipsoidal);
    auto geoid = datum::Egm96Geoid::open(datum::Egm96Geoid::defaultGridPath(), &error);
    QVERIFY2(geoid, qPrintable(error));
    for (auto [lat, lon] : {std::pair{56.5, 24.5}, {56.123, 24.777}}) {
        const double n = geoid->undulation(lat, lon).value();
        QVERIFY(n > 15 && n < 30);  // the geoid stands some 20 m above the ellipsoid near Riga
        const ElevationSample s = dem->sample(lat, lon);
        QVERIFY(s.hasValue());
        QVERIFY2(std::abs(s.ground - (expectedAt(lat, lon) - n)) < 1e-3, qPrintable(QString::number(s.ground)));
    }
}

void TestGdalDem::orthometricAndUnstatedHeightsAreKept()
{
    const QString path = m_dir.filePath(QStringLiteral("egm96.tif"));
    QVERIFY(writeGeoTiff(path, degreesSpec(QStringLiteral("EPSG:4326+5773")), linear));
    QString error;
    auto dem = DemRaster::open(path, &error);
    QVERIFY2(dem, qPrintable(error));
    QCOMPARE(dem->verticalDatum().kind, VerticalDatum::Kind::Orthometric);
    QVERIFY2(dem->verticalDatum().name.contains(QLatin1String("EGM96")), qPrintable(dem->verticalDatum().name));
    QVERIFY(std::abs(dem->sample(56.5, 24.5).ground - expectedAt(56.5, 24.5)) < 1e-6);
}

void TestGdalDem::nodataIsMissingNeverZero()
{
    GeoTiffSpec s = degreesSpec();
    s.noData = -9999;
    const QString path = m_dir.filePath(QStringLiteral("holes.tif"));
    QVERIFY(writeGeoTiff(path, s, [](int b, int r, int c) { return r == 5 && c == 5 ? -9999.0 : linear(b, r, c); }));
    QString error;
    auto dem = DemRaster::open(path, &error);
    QVERIFY2(dem, qPrintable(error));
    const double lat5 = 56.95 - 0.5, lon5 = 24.05 + 0.5;  // the hole's centre
    QCOMPARE(dem->sample(lat5, lon5).status, terrain::SampleStatus::NoData);
    QVERIFY(std::isnan(dem->sample(lat5, lon5).ground));
    // Any blend that gives the hole weight is missing too; its neighbour's centre is not.
    QCOMPARE(dem->sample(lat5 + 0.03, lon5 - 0.04).status, terrain::SampleStatus::NoData);
    const ElevationSample beside = dem->sample(lat5, lon5 + 0.1);
    QVERIFY(beside.hasValue());
    QCOMPARE(beside.ground, 100.0 + 60 + 5);
}

void TestGdalDem::hgtThroughGdalEqualsTheHandWrittenReader()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("N56E024.hgt"));
    QVERIFY(terrain::test::writeHgt(path, 1201, [](int r, int c) {
        if (r >= 600 && r < 604 && c >= 300 && c < 305)
            return int(terrain::HgtTile::kVoid);
        return int(100 + 50 * std::sin(r / 40.0) + 30 * std::cos(c / 25.0));
    }));
    terrain::HgtTileSource handWritten(path);
    QVERIFY2(handWritten.isUsable(), qPrintable(handWritten.error()));
    QString error;
    auto gdal = GdalDemSource::open(path, {path}, &error);
    QVERIFY2(gdal, qPrintable(error));
    QRandomGenerator random(25);
    int voids = 0;
    for (int i = 0; i < 20000; ++i) {
        terrain::GeoPoint p{56 + random.generateDouble(), 24 + random.generateDouble()};
        if (i < 400)  // around the void too
            p = {57 - (598 + random.generateDouble() * 8) / 1200.0, 24 + (298 + random.generateDouble() * 9) / 1200.0};
        if (i == 401)
            p = {57.0, 24.0};  // the corner posts
        if (i == 402)
            p = {56.0, 25.0};
        const ElevationSample a = handWritten.sample(p), b = gdal->sample(p);
        QCOMPARE(b.status, a.status);
        if (a.hasValue())
            QVERIFY2(std::abs(a.ground - b.ground) < 1e-6, qPrintable(QStringLiteral("%1 vs %2 at %3 %4").arg(a.ground).arg(b.ground).arg(p.latitude, 0, 'f', 9).arg(p.longitude, 0, 'f', 9)));
        else
            ++voids;
    }
    QVERIFY(voids > 0);
}

void TestGdalDem::demOpensFilesAndFolders()
{
    QTemporaryDir dir;
    QVERIFY(writeGeoTiff(dir.filePath(QStringLiteral("east.tif")), degreesSpec(), linear));
    QVERIFY(terrain::test::writeHgt(dir.filePath(QStringLiteral("N55E024.hgt")), 1201, [](int, int) { return 42; }));
    QString error;
    // A GeoTIFF file.
    auto file = openDem(dir.filePath(QStringLiteral("east.tif")), &error);
    QVERIFY2(file, qPrintable(error));
    QVERIFY(std::abs(file->sample({56.5, 24.5}).ground - expectedAt(56.5, 24.5)) < 1e-6);
    QVERIFY(file->name().contains(QLatin1String("east.tif")));
    // A .hgt tile: the hand-written reader.
    auto tile = openDem(dir.filePath(QStringLiteral("N55E024.hgt")), &error);
    QVERIFY2(tile, qPrintable(error));
    QVERIFY(qobject_cast<terrain::HgtTileSource *>(tile.get()));
    // A folder of both: each answers where it has data.
    auto folder = openDem(dir.path(), &error);
    QVERIFY2(folder, qPrintable(error));
    QCOMPARE(folder->sample({55.5, 24.5}).ground, 42.0);
    QVERIFY(std::abs(folder->sample({56.5, 24.5}).ground - expectedAt(56.5, 24.5)) < 1e-6);
    QCOMPARE(folder->sample({10.0, 10.0}).status, terrain::SampleStatus::NoData);
}

void TestGdalDem::badFilesAreNamedWithGdalsReason()
{
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("broken.tif"));
    QFile f(garbage);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("II*\0this is not a TIFF at all", 30);
    f.close();
    QString error;
    QVERIFY(!openDem(garbage, &error));
    QVERIFY2(error.startsWith(garbage + QLatin1String(": ")), qPrintable(error));
    QVERIFY2(error.size() > garbage.size() + 10, qPrintable(error));  // GDAL's reason follows the name
    // In a folder the bad file is named too.
    QVERIFY(!openDem(dir.path(), &error));
    QVERIFY2(error.contains(QLatin1String("broken.tif")), qPrintable(error));
    // Not georeferenced: a plain TIFF.
    GDALAllRegister();
    const QString plain = dir.filePath(QStringLiteral("plain.tiff"));
    GDALDataset *ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(plain.toUtf8().constData(), 4, 4, 1, GDT_Byte, nullptr);
    GDALClose(ds);
    QVERIFY(!openDem(plain, &error));
    QVERIFY2(error.contains(QLatin1String("plain.tiff")) && error.contains(QLatin1String("georeferenced")), qPrintable(error));
    QVERIFY(!openDem(dir.filePath(QStringLiteral("missing.tif")), &error));
    QVERIFY2(error.contains(QLatin1String("no such file")), qPrintable(error));
}

void TestGdalDem::chunkCacheStaysBounded()
{
    GeoTiffSpec s;
    s.width = s.height = 2048;
    const double gt[6] = {24.0, 1.0 / 2048, 0, 57.0, 0, -1.0 / 2048};
    std::copy(gt, gt + 6, s.geoTransform);
    s.tiled = true;
    const QString path = m_dir.filePath(QStringLiteral("big.tif"));
    QVERIFY(writeGeoTiff(path, s, [](int, int r, int c) { return r + c; }));
    QString error;
    auto dem = DemRaster::open(path, &error, 4);
    QVERIFY2(dem, qPrintable(error));
    for (int i = 0; i <= 100; ++i) {
        const double f = i / 100.0;
        QVERIFY(dem->sample(57.0 - f * 0.999, 24.0 + f * 0.999).hasValue());
        QVERIFY(dem->cachedChunks() <= 4);
    }
    QVERIFY(dem->chunkReads() >= 8);  // the diagonal crosses 8 chunks, each read once
    const long reads = dem->chunkReads();
    dem->sample(57.0 - 0.999, 24.999);  // the last chunk is still cached
    QCOMPARE(dem->chunkReads(), reads);
}

QTEST_GUILESS_MAIN(TestGdalDem)
#include "tst_gdaldem.moc"
