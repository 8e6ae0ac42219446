// sortie-log coverage as the operator runs it after landing, a separate process: a survey's photos
// (JPEGs whose camera times the test sets) placed on the flight log the vehicle's telemetry made,
// the overlap it flew measured, a hole where photos are missing, the GeoTIFF written, and each
// mistake in the command named.
#include "GeotagTestSupport.h"
#include "SortieLogRun.h"
#include "LocalTangentPlane.h"
#include "SurveyFlightTestSupport.h"
#include "MissionFiles.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

using namespace sortie;
using sortie::test::describe;
using sortie::test::Run;
using sortie::test::sortieLog;

class TestCoverageCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_photos, m_gappy, m_log, m_gpx;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        const test::SurveyFlight flight = test::flySurvey();
        QCOMPARE(test::writeSurvey(m_dir.path(), flight), QString());
        m_log = m_dir.filePath(QStringLiteral("survey.sortielog"));
        m_photos = m_dir.filePath(QStringLiteral("card"));
        m_gappy = m_dir.filePath(QStringLiteral("card-with-a-gap"));
        std::vector<test::GpxPoint> gpx;
        for (const auto &s : flight.samples)
            gpx.push_back({int64_t(s[0]), s[1], s[2], s[3]});
        m_gpx = m_dir.filePath(QStringLiteral("survey.gpx"));
        test::writeGpx(m_gpx, gpx);
    }

    void aSurveyFlownAsPlannedHasNoHole()
    {
        const QString tif = m_dir.filePath(QStringLiteral("overlap.tif"));
        const Run r = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                 QStringLiteral("--out"), tif, QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("photos")).toInt(), 85);
        QCOMPARE(json.value(QStringLiteral("placed")).toInt(), 85);
        QCOMPARE(json.value(QStringLiteral("camera")).toString(), test::kSurveyCamera);
        QCOMPARE(json.value(QStringLiteral("ground")).toString(), QStringLiteral("flat at the take-off point"));
        QCOMPARE(json.value(QStringLiteral("crs")).toString(), QStringLiteral("EPSG:32635"));
        QCOMPARE(json.value(QStringLiteral("raster")).toString(), tif);
        // The heading is the course flown (the log holds none): the legs' overlaps come out as flown.
        const double forward = json.value(QStringLiteral("forwardOverlap")).toObject().value(QStringLiteral("p50")).toDouble();
        const double side = json.value(QStringLiteral("sideOverlap")).toObject().value(QStringLiteral("p50")).toDouble();
        QVERIFY2(std::fabs(forward - 80) < 1, qPrintable(describe(r)));
        QVERIFY2(std::fabs(side - 70) < 1, qPrintable(describe(r)));
        // 60 m × 13.2 mm / (8.8 mm × 5472 px) = 1.64 cm
        QVERIFY2(std::fabs(json.value(QStringLiteral("gsdCm")).toObject().value(QStringLiteral("p50")).toDouble() - 1.64) < 0.01, qPrintable(describe(r)));
        QCOMPARE(json.value(QStringLiteral("holes")).toArray().size(), 0);
        QCOMPARE(json.value(QStringLiteral("covered")).toDouble(), 1.0);
        // No hole, nothing to re-fly: no route is written.
        const QString reflyPath = m_dir.filePath(QStringLiteral("nothing.sortie"));
        const Run refly = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                     QStringLiteral("--out"), tif, QStringLiteral("--refly"), reflyPath});
        QVERIFY2(refly.exitCode == 0 && refly.out.contains("no hole: nothing to re-fly"), qPrintable(describe(refly)));
        QVERIFY(!QFile::exists(reflyPath));
        QFile file(tif);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.read(4), QByteArray("II*\0", 4)); // a little-endian TIFF
    }

    void missingPhotosAreAHoleNamedWithItsPlace()
    {
        const Run r = sortieLog({QStringLiteral("coverage"), m_gappy, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                 QStringLiteral("--out"), m_dir.filePath(QStringLiteral("gap.tif"))});
        QVERIFY2(r.exitCode == 2, qPrintable(describe(r)));
        QVERIFY2(r.out.contains("70 of 70 photos placed") && r.out.contains("hole of ") && r.out.contains("images per cell in"), qPrintable(describe(r)));
        const Run json = sortieLog({QStringLiteral("coverage"), m_gappy, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), m_dir.filePath(QStringLiteral("gap.tif")), QStringLiteral("--json")});
        QVERIFY2(json.exitCode == 2, qPrintable(describe(json)));
        const QJsonArray holes = QJsonDocument::fromJson(json.out).object().value(QStringLiteral("holes")).toArray();
        QCOMPARE(QJsonDocument::fromJson(json.out).object().value(QStringLiteral("refly")), QJsonValue(QJsonValue::Null)); // not asked
        QVERIFY(!holes.isEmpty());
        // Around the middle leg (54 m east) at 96 m along.
        const QJsonArray centre = holes.first().toObject().value(QStringLiteral("centre")).toArray();
        const mission::LocalTangentPlane plane({56.95, 24.10});
        const auto at = plane.project({centre.at(1).toDouble(), centre.at(0).toDouble()});
        QVERIFY2(std::fabs(at.x - 54) < 10 && std::fabs(at.y - 96) < 15, qPrintable(QStringLiteral("%1, %2").arg(at.x).arg(at.y)));

        // Re-fly the gaps: a route of one area scan per hole, with the survey's camera, height,
        // overlap and legs, that the mission files read back.
        const QString reflyPath = m_dir.filePath(QStringLiteral("refly.sortie"));
        const Run refly = sortieLog({QStringLiteral("coverage"), m_gappy, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                     QStringLiteral("--out"), m_dir.filePath(QStringLiteral("gap.tif")), QStringLiteral("--refly"), reflyPath,
                                     QStringLiteral("--json")});
        QVERIFY2(refly.exitCode == 2, qPrintable(describe(refly)));
        const QJsonObject written = QJsonDocument::fromJson(refly.out).object().value(QStringLiteral("refly")).toObject();
        QCOMPARE(written.value(QStringLiteral("file")).toString(), reflyPath);
        QCOMPARE(written.value(QStringLiteral("scans")).toInt(), int(holes.size()));
        const auto loaded = mission::formats::loadMission(reflyPath);
        QVERIFY2(loaded, qPrintable(loaded ? QString() : loaded.error().toString()));
        QCOMPARE(loaded->mission.routes.size(), size_t(1));
        const mission::Route &route = loaded->mission.routes.front();
        QCOMPARE(route.segments.size(), size_t(holes.size()));
        const auto *scan = std::get_if<mission::AreaScan>(&route.segments.front());
        QVERIFY(scan);
        QCOMPARE(scan->parameters.camera.name, test::kSurveyCamera);
        QCOMPARE(scan->parameters.altitude, 60.0);
        QCOMPARE(scan->parameters.altitudeType, mission::AltitudeType::Agl);
        QCOMPARE(scan->parameters.frontOverlapPercent, 80.0);
        QCOMPARE(scan->parameters.sideOverlapPercent, 70.0);
        QVERIFY2(std::fabs(std::remainder(scan->parameters.directionDeg, 180.0)) < 2, qPrintable(QString::number(scan->parameters.directionDeg)));
        // The scan's polygon holds the hole's centre.
        double minLat = 90, maxLat = -90, minLon = 180, maxLon = -180;
        for (const auto &p : scan->polygon) {
            minLat = std::min(minLat, p.latitude), maxLat = std::max(maxLat, p.latitude);
            minLon = std::min(minLon, p.longitude), maxLon = std::max(maxLon, p.longitude);
        }
        QVERIFY(centre.at(1).toDouble() > minLat && centre.at(1).toDouble() < maxLat);
        QVERIFY(centre.at(0).toDouble() > minLon && centre.at(0).toDouble() < maxLon);
    }

    void aGpxTrackNeedsTheGroundsHeight()
    {
        // A GPX gives AMSL only: without the ground's height no photo has a height above it.
        const Run none = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), m_dir.filePath(QStringLiteral("gpx.tif"))});
        QVERIFY2(none.exitCode == 1 && none.err.contains("no photo has a position, a height above the ground and a heading"), qPrintable(describe(none)));
        const Run flat = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), m_dir.filePath(QStringLiteral("gpx.tif")), QStringLiteral("--ground-amsl"),
                                    QStringLiteral("40"), QStringLiteral("--json")});
        QVERIFY2(flat.exitCode == 0, qPrintable(describe(flat)));
        const QJsonObject json = QJsonDocument::fromJson(flat.out).object();
        QCOMPARE(json.value(QStringLiteral("ground")).toString(), QStringLiteral("flat at 40 m AMSL"));
        QVERIFY(std::fabs(json.value(QStringLiteral("gsdCm")).toObject().value(QStringLiteral("p50")).toDouble() - 1.64) < 0.01);
    }

    // The ground from a DEM: a slope rising 0.1 m a metre to the east from the take-off's 40 m, so
    // the legs further east fly lower above it (60 m over the first, 49.2 m over the fifth).
    void aDemGivesEachPhotoItsOwnHeight()
    {
        const QString demPath = m_dir.filePath(QStringLiteral("slope.tif"));
        {
            GDALAllRegister();
            GDALDriver *gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
            QVERIFY(gtiff);
            const int w = 400, h = 400;
            const double west = 24.0980, north = 56.9540, step = 0.00002; // about 1.2 m east, 2.2 m north
            std::unique_ptr<GDALDataset> d(gtiff->Create(demPath.toUtf8().constData(), w, h, 1, GDT_Float32, nullptr));
            QVERIFY(d);
            double transform[6] = {west, step, 0, north, 0, -step};
            d->SetGeoTransform(transform);
            OGRSpatialReference wgs84;
            wgs84.importFromEPSG(4326);
            d->SetSpatialRef(&wgs84);
            const mission::LocalTangentPlane plane({56.95, 24.10});
            std::vector<float> ground(size_t(w) * h);
            for (int row = 0; row < h; ++row)
                for (int col = 0; col < w; ++col) {
                    const auto at = plane.project({north - (row + 0.5) * step, west + (col + 0.5) * step});
                    ground[size_t(row) * w + col] = float(40 + 0.1 * at.x);
                }
            QCOMPARE(d->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, ground.data(), w, h, GDT_Float32, 0, 0), CE_None);
        }
        const Run r = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                 QStringLiteral("--out"), m_dir.filePath(QStringLiteral("dem.tif")), QStringLiteral("--dem"), demPath,
                                 QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0 || r.exitCode == 2, qPrintable(describe(r)));
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("placed")).toInt(), 85);
        QVERIFY2(json.value(QStringLiteral("ground")).toString().startsWith(QStringLiteral("the DEM ")), qPrintable(describe(r)));
        const QJsonObject height = json.value(QStringLiteral("heightAboveGround")).toObject();
        QVERIFY2(std::fabs(height.value(QStringLiteral("max")).toDouble() - 60) < 0.3, qPrintable(describe(r)));
        QVERIFY2(std::fabs(height.value(QStringLiteral("min")).toDouble() - 49.2) < 0.3, qPrintable(describe(r)));
        // Lower over the eastern legs: finer pixels there (49.2 m: 1.35 cm against 60 m: 1.64 cm).
        QVERIFY2(std::fabs(json.value(QStringLiteral("gsdCm")).toObject().value(QStringLiteral("min")).toDouble() - 1.35) < 0.01, qPrintable(describe(r)));

        // Where the DEM has no ground the photo is named; both grounds at once is refused.
        const Run both = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), m_dir.filePath(QStringLiteral("dem.tif")), QStringLiteral("--dem"), demPath,
                                    QStringLiteral("--ground-amsl"), QStringLiteral("40")});
        QVERIFY2(both.exitCode == 1 && both.err.contains("give one"), qPrintable(describe(both)));
        const Run missing = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                       QStringLiteral("--out"), m_dir.filePath(QStringLiteral("dem.tif")), QStringLiteral("--dem"),
                                       m_dir.filePath(QStringLiteral("no-such.tif"))});
        QVERIFY2(missing.exitCode == 1 && missing.err.contains("no-such.tif"), qPrintable(describe(missing)));
    }

    void mistakesAreNamed()
    {
        const QString tif = m_dir.filePath(QStringLiteral("x.tif"));
        const Run camera = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"),
                                      QStringLiteral("Brownie"), QStringLiteral("--out"), tif});
        QVERIFY2(camera.exitCode == 1 && camera.err.contains("no camera \"Brownie\"") && camera.err.contains(test::kSurveyCamera.toUtf8()), qPrintable(describe(camera)));
        const Run out = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera});
        QVERIFY2(out.exitCode == 1 && out.err.contains("coverage needs --out"), qPrintable(describe(out)));
        const Run cell = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), tif, QStringLiteral("--cell"), QStringLiteral("-1")});
        QVERIFY2(cell.exitCode == 1 && cell.err.contains("--cell takes a number from 0.01 to 100"), qPrintable(describe(cell)));
        const Run late = sortieLog({QStringLiteral("coverage"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--camera"), test::kSurveyCamera,
                                    QStringLiteral("--out"), tif, QStringLiteral("--offset"), QStringLiteral("3600"), QStringLiteral("--json")});
        QVERIFY2(late.exitCode == 1 && late.err.contains("no photo has a position"), qPrintable(describe(late)));
        QVERIFY(!QFile::exists(tif));
    }
};

QTEST_GUILESS_MAIN(TestCoverageCli)
#include "tst_coveragecli.moc"
