// Hostile rasters (issue 36): files that would make GDAL read what they name rather than
// themselves. A VRT saved as .tif, a WMS description, a .vrt naming a URL or a raw band, an overview
// file that is a VRT: each refused by the raster layer (DEM and orthophoto alike) naming what GDAL
// found, with a 127.0.0.1 HTTP listener proving that no request left. The promised formats, a .vrt
// mosaic of GeoTIFFs among them, still open.
#include "DemOpener.h"
#include "GeoTiffWriter.h"
#include "OrthophotoRenderer.h"

#include <cpl_conv.h>
#include <cpl_vsi.h>

#include <QFile>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;
using namespace sortie::raster;
using namespace sortie::raster::test;

namespace {

// 10×10 pixels of 0.1° over 24..25 E, 56..57 N, 100 m of ground.
GeoTiffSpec degreesSpec()
{
    GeoTiffSpec s;
    s.width = s.height = 10;
    const double gt[6] = {24.0, 0.1, 0, 57.0, 0, -0.1};
    std::copy(gt, gt + 6, s.geoTransform);
    s.crs = QStringLiteral("EPSG:4326");
    return s;
}

QByteArray vrtNaming(const QByteArray &source, bool relative = true, const QByteArray &bandClass = {})
{
    const QByteArray band = bandClass.isEmpty() ? QByteArray("<VRTRasterBand dataType=\"Float32\" band=\"1\">")
                                                : "<VRTRasterBand dataType=\"Float32\" band=\"1\" subClass=\"" + bandClass + "\">";
    const QByteArray body = bandClass == "VRTRawRasterBand"
        ? "<SourceFilename relativeToVRT=\"1\">" + source + "</SourceFilename><ImageOffset>0</ImageOffset><PixelOffset>4</PixelOffset>"
          "<LineOffset>40</LineOffset>"
        : "<SimpleSource><SourceFilename relativeToVRT=\"" + QByteArray(relative ? "1" : "0") + "\">" + source +
              "</SourceFilename><SourceBand>1</SourceBand></SimpleSource>";
    return "<VRTDataset rasterXSize=\"10\" rasterYSize=\"10\"><SRS>EPSG:4326</SRS>"
           "<GeoTransform>24.0, 0.1, 0, 57.0, 0, -0.1</GeoTransform>" + band + body + "</VRTRasterBand></VRTDataset>\n";
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

} // namespace

class TestHostileRaster : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QTcpServer m_http;  // where a URL in a hostile file points: nothing may connect
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
    QByteArray url(const char *file) const { return "http://127.0.0.1:" + QByteArray::number(m_http.serverPort()) + "/" + file; }
    bool nothingConnected() { return !m_http.waitForNewConnection(0) && !m_http.hasPendingConnections(); }

    // Refused as a DEM and as an orthophoto, the message naming the file and containing `why`.
    void refused(const QString &file, const QString &why)
    {
        QString error;
        QVERIFY2(!openDem(file, &error), qPrintable(file));
        QVERIFY2(error.startsWith(file + QLatin1String(": ")) && error.contains(why), qPrintable(error));
        QVERIFY2(!OrthophotoRenderer::open(file, &error), qPrintable(file));
        QVERIFY2(error.contains(why), qPrintable(error));
        QVERIFY(nothingConnected());
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_http.listen(QHostAddress::LocalHost));
        // Were the network not off, a regression would fail in seconds rather than hang.
        CPLSetConfigOption("GDAL_HTTP_TIMEOUT", "3");
        CPLSetConfigOption("GDAL_HTTP_MAX_RETRY", "0");
        QVERIFY(writeGeoTiff(path("ground.tif"), degreesSpec(), [](int, int, int) { return 100.0; }));
    }

    void aVrtUnderAnotherNameIsRefusedNamingTheDriver()
    {
        QVERIFY(writeFile(path("evil.tif"), vrtNaming("ground.tif")));
        refused(path("evil.tif"), QStringLiteral("driver VRT"));
        // In a folder it is left out, named, and the folder's good raster answers.
        QTemporaryDir folder;
        QVERIFY(writeGeoTiff(folder.filePath(QStringLiteral("good.tif")), degreesSpec(), [](int, int, int) { return 100.0; }));
        QVERIFY(writeFile(folder.filePath(QStringLiteral("evil.tif")), vrtNaming(path("ground.tif").toUtf8(), false)));
        QString error;
        auto dem = openDem(folder.path(), &error);
        QVERIFY2(dem, qPrintable(error));
        QCOMPARE(dem->sample({56.5, 24.5}).ground, 100.0);
        QVERIFY(dem->problems().join(QLatin1Char('\n')).contains(QLatin1String("evil.tif")));
    }

    void aVrtMosaicOfGeoTiffsStillOpens()
    {
        QVERIFY(writeFile(path("mosaic.vrt"), vrtNaming("ground.tif")));
        QString error;
        auto dem = openDem(path("mosaic.vrt"), &error);
        QVERIFY2(dem, qPrintable(error));
        QCOMPARE(dem->sample({56.5, 24.5}).ground, 100.0);
        auto ortho = OrthophotoRenderer::open(path("mosaic.vrt"), &error);
        QVERIFY2(ortho, qPrintable(error));
        // A .vrt naming a .vrt naming the GeoTIFF, too.
        QVERIFY(writeFile(path("outer.vrt"), vrtNaming("mosaic.vrt")));
        QVERIFY2(openDem(path("outer.vrt"), &error), qPrintable(error));
    }

    void aWmsDescriptionIsRefusedAndFetchesNothing()
    {
        const QByteArray wms = "<GDAL_WMS><Service name=\"TMS\"><ServerUrl>" + url("${z}/${x}/${y}.png") +
                               "</ServerUrl></Service><DataWindow><UpperLeftX>-20037508.34</UpperLeftX><UpperLeftY>20037508.34</UpperLeftY>"
                               "<LowerRightX>20037508.34</LowerRightX><LowerRightY>-20037508.34</LowerRightY><TileLevel>18</TileLevel>"
                               "<TileCountX>1</TileCountX><TileCountY>1</TileCountY></DataWindow><Projection>EPSG:3857</Projection>"
                               "<BlockSizeX>256</BlockSizeX><BlockSizeY>256</BlockSizeY><BandsCount>1</BandsCount></GDAL_WMS>\n";
        for (const char *name : {"wms.xml", "wms.tif", "wms.vrt"}) {
            QVERIFY(writeFile(path(name), wms));
            refused(path(name), QStringLiteral("WMS"));
        }
    }

    void aVrtNamingAUrlOrARawBandIsRefused()
    {
        QVERIFY(writeFile(path("remote.vrt"), vrtNaming("/vsicurl/" + url("ground.tif"), false)));
        refused(path("remote.vrt"), QStringLiteral("not a local file"));
        QVERIFY(writeFile(path("remote-wms.vrt"), vrtNaming("WMS:" + url("wms?service=WMS"), false)));
        refused(path("remote-wms.vrt"), QStringLiteral("not a local file"));
        // A raw band reads any file's bytes as pixels.
        QVERIFY(writeFile(path("raw.vrt"), vrtNaming("ground.tif", true, "VRTRawRasterBand")));
        refused(path("raw.vrt"), QStringLiteral("VRTRawRasterBand"));
        // A .vrt naming a VRT saved as .tif.
        QVERIFY(writeFile(path("inner.tif"), vrtNaming("ground.tif")));
        QVERIFY(writeFile(path("outer-evil.vrt"), vrtNaming("inner.tif")));
        refused(path("outer-evil.vrt"), QStringLiteral("driver VRT"));
    }

    void anOverviewFileThatIsAVrtIsRefused()
    {
        QVERIFY(writeGeoTiff(path("with-ovr.tif"), degreesSpec(), [](int, int, int) { return 100.0; }));
        QVERIFY(writeFile(path("with-ovr.tif.ovr"), vrtNaming(path("ground.tif").toUtf8(), false)));
        refused(path("with-ovr.tif"), QStringLiteral("with-ovr.tif.ovr"));
    }

    void gdalsNetworkFileSystemsAreOff()
    {
        QString error;
        QVERIFY(openDem(path("ground.tif"), &error));  // GDAL prepared
        const QByteArray remote = "/vsicurl/" + url("ground.tif");
        VSIStatBufL stat;
        QVERIFY(VSIStatExL(remote.constData(), &stat, VSI_STAT_EXISTS_FLAG) != 0);
        QVERIFY(!VSIFOpenL(remote.constData(), "rb"));
        QVERIFY(!VSIFOpenL(("/vsicurl_streaming/" + url("ground.tif")).constData(), "rb"));
        QVERIFY(nothingConnected());
        refused(QString::fromUtf8(remote), QStringLiteral("no such file"));
    }
};

QTEST_GUILESS_MAIN(TestHostileRaster)
#include "tst_hostileraster.moc"
