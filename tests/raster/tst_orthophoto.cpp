// An orthophoto in UTM with four coloured quadrants, cut into Web Mercator tiles: every pixel of a
// rendered tile is checked against where its centre falls in the image (by PROJ, independently of
// the warp): the right colour inside, transparent outside and where the alpha band says so; the
// same from overviews when zoomed out.
#include "GeoTiffWriter.h"
#include "OrthophotoRenderer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>

using namespace sortie::raster;
using namespace sortie::raster::test;

namespace {

constexpr double kHalfWorld = 20037508.342789244;
constexpr double kPixel = 10.0;  // metres
constexpr int kSize = 200;       // pixels a side: 2 km
using Rgb = std::array<int, 3>;
const Rgb kQuadrant[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};  // NW, NE, SW, SE

struct Utm
{
    OGRCoordinateTransformation *toUtm = nullptr;
    Utm()
    {
        OGRSpatialReference wgs84, utm;
        wgs84.importFromEPSG(4326);
        utm.importFromEPSG(32635);
        wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        toUtm = OGRCreateCoordinateTransformation(&wgs84, &utm);
    }
    ~Utm() { OGRCoordinateTransformation::DestroyCT(toUtm); }
    QPointF operator()(double lat, double lon) const
    {
        double x = lon, y = lat;
        toUtm->Transform(1, &x, &y);
        return {x, y};
    }
};

// The geographic position of a tile pixel's centre.
std::pair<double, double> pixelCentre(int z, int x, int y, int i, int j, int size)
{
    const double span = 2 * kHalfWorld / double(1 << z);
    const double mx = -kHalfWorld + x * span + (i + 0.5) * span / size;
    const double my = kHalfWorld - y * span - (j + 0.5) * span / size;
    const double lon = mx / 6378137.0 * 180.0 / M_PI;
    const double lat = std::atan(std::sinh(my / 6378137.0)) * 180.0 / M_PI;
    return {lat, lon};
}

std::pair<int, int> tileOf(double lat, double lon, int z)
{
    const double n = 1 << z;
    const double x = (lon + 180.0) / 360.0 * n;
    const double s = std::sin(lat * M_PI / 180.0);
    const double y = (0.5 - std::log((1 + s) / (1 - s)) / (4 * M_PI)) * n;
    return {int(x), int(y)};
}

} // namespace

class TestOrthophoto : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void tilesShowTheQuadrantsInPlace_data();
    void tilesShowTheQuadrantsInPlace();
    void alphaBandMakesPixelsTransparent();
    void tilesAwayFromTheImageAreEmpty();
    void badFileIsRefusedWithGdalsReason();

private:
    // Checks every pixel of tile z/x/y; counts the pixels of each kind.
    void checkTile(OrthophotoRenderer &renderer, int z, int x, int y, double marginPixels, bool neTransparent);

    QTemporaryDir m_dir;
    Utm m_utm;
    double m_e0 = 0, m_n0 = 0;  // the image's north-west corner, UTM metres
    QPointF m_centreGeo;        // lat, lon of the image's centre
};

void TestOrthophoto::initTestCase()
{
    const QPointF corner = m_utm(56.95, 24.1);
    m_e0 = std::floor(corner.x()), m_n0 = std::floor(corner.y());
    m_centreGeo = {56.95 - 0.009, 24.1 + 0.016};
    auto write = [&](const QString &name, int bands, std::vector<int> overviews) {
        GeoTiffSpec s;
        s.width = s.height = kSize;
        const double gt[6] = {m_e0, kPixel, 0, m_n0, 0, -kPixel};
        std::copy(gt, gt + 6, s.geoTransform);
        s.crs = QStringLiteral("EPSG:32635");
        s.bands = bands;
        s.type = GDT_Byte;
        s.alphaLast = bands == 4;
        s.tiled = true;
        s.overviews = std::move(overviews);
        return writeGeoTiff(m_dir.filePath(name), s, [](int b, int r, int c) {
            const int q = (r < kSize / 2 ? 0 : 2) + (c < kSize / 2 ? 0 : 1);
            if (b == 3)
                return q == 1 ? 0.0 : 255.0;  // alpha: the north-east quadrant is see-through
            return double(kQuadrant[q][size_t(b)]);
        });
    };
    QVERIFY(write(QStringLiteral("quadrants.tif"), 3, {}));
    QVERIFY(write(QStringLiteral("quadrants-ovr.tif"), 3, {2, 4, 8}));
    QVERIFY(write(QStringLiteral("quadrants-alpha.tif"), 4, {}));
}

void TestOrthophoto::checkTile(OrthophotoRenderer &renderer, int z, int x, int y, double margin, bool neTransparent)
{
    QString error;
    const RgbaTile tile = renderer.render(z, x, y, 256, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(tile.size, 256);
    QVERIFY(tile.covered);
    int inside = 0, outside = 0;
    std::array<int, 4> seen{};
    for (int j = 0; j < 256; ++j) {
        for (int i = 0; i < 256; ++i) {
            const auto [lat, lon] = pixelCentre(z, x, y, i, j, 256);
            const QPointF p = m_utm(lat, lon);
            const double column = (p.x() - m_e0) / kPixel, row = (m_n0 - p.y()) / kPixel;
            const double nearEdge = std::min({std::abs(column), std::abs(row), std::abs(column - kSize), std::abs(row - kSize),
                                              std::abs(column - kSize / 2), std::abs(row - kSize / 2)});
            if (nearEdge < margin)
                continue;  // blended across an edge
            const unsigned char *px = &tile.rgba[(size_t(j) * 256 + size_t(i)) * 4];
            const bool in = column > 0 && row > 0 && column < kSize && row < kSize;
            const int q = (row < kSize / 2 ? 0 : 2) + (column < kSize / 2 ? 0 : 1);
            if (!in || (neTransparent && q == 1)) {
                QVERIFY2(px[3] == 0, qPrintable(QStringLiteral("pixel %1,%2 should be transparent, alpha %3").arg(i).arg(j).arg(px[3])));
                ++outside;
                continue;
            }
            QVERIFY2(px[3] == 255 && px[0] == kQuadrant[q][0] && px[1] == kQuadrant[q][1] && px[2] == kQuadrant[q][2],
                     qPrintable(QStringLiteral("pixel %1,%2 (quadrant %3): %4 %5 %6 %7").arg(i).arg(j).arg(q).arg(px[0]).arg(px[1]).arg(px[2]).arg(px[3])));
            ++inside;
            ++seen[size_t(q)];
        }
    }
    QVERIFY(inside > 0);
    QVERIFY(outside > 0);
    for (int q = 0; q < 4; ++q)
        QVERIFY2(seen[size_t(q)] > 0 || (neTransparent && q == 1), qPrintable(QStringLiteral("quadrant %1 not seen").arg(q)));
}

void TestOrthophoto::tilesShowTheQuadrantsInPlace_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("zoom");
    QTest::addColumn<double>("margin");  // in image pixels: how close to an edge blending may reach
    // z13: a tile pixel is some 10 m of ground, one image pixel; z11: four image pixels.
    QTest::newRow("full resolution, z13") << "quadrants.tif" << 13 << 2.0;
    QTest::newRow("no overviews, z11") << "quadrants.tif" << 11 << 6.0;
    QTest::newRow("overviews, z11") << "quadrants-ovr.tif" << 11 << 10.0;
    QTest::newRow("overviews, z13") << "quadrants-ovr.tif" << 13 << 2.0;
}

void TestOrthophoto::tilesShowTheQuadrantsInPlace()
{
    QFETCH(QString, file);
    QFETCH(int, zoom);
    QFETCH(double, margin);
    QString error;
    auto renderer = OrthophotoRenderer::open(m_dir.filePath(file), &error);
    QVERIFY2(renderer, qPrintable(error));
    QVERIFY(std::abs(renderer->north() - 56.95) < 0.01 && std::abs(renderer->west() - 24.1) < 0.01);
    const auto [x, y] = tileOf(m_centreGeo.x(), m_centreGeo.y(), zoom);
    checkTile(*renderer, zoom, x, y, margin, false);
}

void TestOrthophoto::alphaBandMakesPixelsTransparent()
{
    QString error;
    auto renderer = OrthophotoRenderer::open(m_dir.filePath(QStringLiteral("quadrants-alpha.tif")), &error);
    QVERIFY2(renderer, qPrintable(error));
    const auto [x, y] = tileOf(m_centreGeo.x(), m_centreGeo.y(), 13);
    checkTile(*renderer, 13, x, y, 2.0, true);
}

void TestOrthophoto::tilesAwayFromTheImageAreEmpty()
{
    QString error;
    auto renderer = OrthophotoRenderer::open(m_dir.filePath(QStringLiteral("quadrants.tif")), &error);
    QVERIFY2(renderer, qPrintable(error));
    const auto [x, y] = tileOf(40.0, 10.0, 13);
    QVERIFY(!renderer->touches(13, x, y));
    const RgbaTile tile = renderer->render(13, x, y, 256, &error);
    QVERIFY(!tile.covered);
    QCOMPARE(int(tile.rgba.size()), 256 * 256 * 4);
    QVERIFY(std::all_of(tile.rgba.begin(), tile.rgba.end(), [](unsigned char v) { return v == 0; }));
}

void TestOrthophoto::badFileIsRefusedWithGdalsReason()
{
    QString error;
    const QString path = m_dir.filePath(QStringLiteral("not-an-image.tif"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("definitely not an image");
    f.close();
    QVERIFY(!OrthophotoRenderer::open(path, &error));
    QVERIFY2(error.startsWith(path + QLatin1String(": ")) && error.size() > path.size() + 10, qPrintable(error));
}

QTEST_GUILESS_MAIN(TestOrthophoto)
#include "tst_orthophoto.moc"
