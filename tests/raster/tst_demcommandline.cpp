// --dem with the operator's own rasters, from the command line: sortie-plan profile run as a
// process over a UTM GeoTIFF with a nodata hole (ground where the file has it, null in the hole,
// never 0), a folder of GeoTIFFs, a bad file named with GDAL's reason (sortie-plan and sortie-sim
// exit with it), and sortie's own --dem refusing the same file before anything starts.
#include "GeoTiffWriter.h"
#include "LaunchOptions.h"
#include "PlanRun.h"

#include <nlohmann/json.hpp>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::raster::test;

class TestDemCommandLine : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

private slots:
    void initTestCase()
    {
        // 120 m of ground in UTM 35N around 56.5 N 24.5 E (100 m pixels), with a nodata hole.
        OGRSpatialReference wgs84, utm;
        wgs84.importFromEPSG(4326);
        utm.importFromEPSG(32635);
        wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        auto *t = OGRCreateCoordinateTransformation(&wgs84, &utm);
        double e = 24.4, n = 56.6;
        t->Transform(1, &e, &n);
        OGRCoordinateTransformation::DestroyCT(t);
        GeoTiffSpec s;
        s.width = s.height = 200;
        const double gt[6] = {std::floor(e), 100, 0, std::floor(n), 0, -100};
        std::copy(gt, gt + 6, s.geoTransform);
        s.crs = QStringLiteral("EPSG:32635");
        s.noData = -9999;
        QVERIFY(QDir(m_dir.path()).mkdir(QStringLiteral("dems")));
        // The hole: columns 118-125 (about 24.52-24.53 E at 56.5 N is near column 120).
        QVERIFY(writeGeoTiff(path("dems/utm.tif"), s, [](int, int, int c) { return c >= 110 && c <= 125 ? -9999.0 : 120.0; }));
        QFile wpl(path("route.waypoints"));
        QVERIFY(wpl.open(QIODevice::WriteOnly));
        wpl.write("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t56.5\t24.45\t200\t1\n1\t0\t0\t16\t0\t0\t0\t0\t56.5\t24.45\t200\t1\n"
                  "2\t0\t0\t16\t0\t0\t0\t0\t56.5\t24.6\t200\t1\n");
        wpl.close();
        QFile bad(path("broken.tif"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("II*\0 not a tiff", 15);
    }

    void profileFromAGeoTiffInUtm()
    {
        for (const char *dem : {"dems/utm.tif", "dems"}) {
            const sortie::test::PlanRun r = sortie::test::runPlan({QStringLiteral("profile"), path("route.waypoints"), QStringLiteral("--dem"), path(dem), QStringLiteral("--json")});
            QVERIFY2(r.code == 0, r.err.constData());
            const auto t = nlohmann::json::parse(r.out.toStdString())["routes"][0]["terrain"];
            int ground = 0, nulls = 0;
            for (const auto &s : t["samples"]) {
                if (s["ground"].is_null()) {
                    ++nulls;
                } else {
                    QCOMPARE(s["ground"].get<double>(), 120.0);
                    ++ground;
                }
            }
            QVERIFY(ground > 100);
            QVERIFY(nulls > 10);  // the hole is missing, never 0 m
            QCOMPARE(t["minClearance"].get<double>(), 80.0);
            QVERIFY(!t["noData"].empty());
        }
    }

    void badFileNamedWithGdalsReason()
    {
        const sortie::test::PlanRun r = sortie::test::runPlan({QStringLiteral("profile"), path("route.waypoints"), QStringLiteral("--dem"), path("broken.tif")});
        QCOMPARE(r.code, 1);
        const QByteArray expected = "sortie-plan: " + path("broken.tif").toUtf8() + ": ";
        QVERIFY2(r.err.startsWith(expected) && r.err.size() > expected.size() + 10, r.err.constData());
        const sortie::test::PlanRun stats = sortie::test::runPlan({QStringLiteral("stats"), path("route.waypoints"), QStringLiteral("--dem"), path("broken.tif")});
        QCOMPARE(stats.code, 1);
        QVERIFY2(stats.err.contains(path("broken.tif").toUtf8()), stats.err.constData());
    }

    void simulatorRefusesABadDem()
    {
        QProcess sim;
        sim.start(QStringLiteral(SORTIE_SIM_BIN), {QStringLiteral("--port"), QStringLiteral("0"), QStringLiteral("--dem"), path("broken.tif")});
        QVERIFY(sim.waitForFinished(30000));
        QVERIFY(sim.exitCode() != 0);
        const QByteArray err = sim.readAllStandardError();
        QVERIFY2(err.contains(path("broken.tif").toUtf8()), err.constData());
    }

    void sortieRefusesABadDemBeforeStarting()
    {
        const auto parsed = sortie::app::LaunchOptions::parse({QStringLiteral("sortie"), QStringLiteral("--dem"), path("broken.tif")});
        const QString *error = std::get_if<QString>(&parsed);
        QVERIFY(error);
        QVERIFY2(error->startsWith(QLatin1String("--dem: ") + path("broken.tif") + QLatin1String(": ")), qPrintable(*error));
        const auto good = sortie::app::LaunchOptions::parse({QStringLiteral("sortie"), QStringLiteral("--dem"), path("dems/utm.tif")});
        QVERIFY(std::holds_alternative<sortie::app::LaunchOptions>(good));
        QCOMPARE(std::get<sortie::app::LaunchOptions>(good).demPath, path("dems/utm.tif"));
    }
};

QTEST_GUILESS_MAIN(TestDemCommandLine)
#include "tst_demcommandline.moc"
