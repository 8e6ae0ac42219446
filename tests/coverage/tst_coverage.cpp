// What a flight's photos cover (core/coverage): the overlap a lawnmower survey was flown with is
// what the report measures; photos taken out of it leave a hole where they were; the raster GDAL
// reads back is the one judged; a photo without a height is named, never placed at 0.
#include "AreaScanPlanner.h"
#include "CoverageTestSurvey.h"
#include "ReflyRoute.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

using namespace sortie;

class TestCoverage : public QObject
{
    Q_OBJECT

    static std::optional<coverage::CoverageReport> judge(const std::vector<coverage::Shot> &shots, coverage::CoverageRaster *raster = nullptr)
    {
        coverage::CoverageOptions options;
        options.camera = test::surveyCamera();
        options.cellMeters = 1.0;
        QString error;
        auto report = coverage::computeCoverage(shots, options, raster, &error);
        if (!report)
            qWarning().noquote() << error;
        return report;
    }

private slots:
    void aSurveyFlownAsPlannedHasItsOverlapAndNoHole()
    {
        const test::Survey plan; // 80 % forward, 70 % side, from 100 m
        const auto shots = test::flySurvey(plan, test::surveyCamera());
        const auto report = judge(shots);
        QVERIFY(report);
        QCOMPARE(report->photos, int(shots.size()));
        QCOMPARE(report->placed, int(shots.size()));
        QCOMPARE(report->crs, QStringLiteral("EPSG:32635")); // Riga is in UTM zone 35 north
        QVERIFY(report->forwardOverlap && report->sideOverlap && report->gsdCm && report->imagesPerPoint);
        QVERIFY2(std::fabs(report->forwardOverlap->p50 - 80) < 0.5, qPrintable(QString::number(report->forwardOverlap->p50)));
        QVERIFY2(std::fabs(report->forwardOverlap->p5 - 80) < 0.5, qPrintable(QString::number(report->forwardOverlap->p5)));
        QVERIFY2(std::fabs(report->sideOverlap->p50 - 70) < 0.5, qPrintable(QString::number(report->sideOverlap->p50)));
        // 100 m × 13.2 mm / (8.8 mm × 5472 px) = 2.74 cm
        QVERIFY(std::fabs(report->gsdCm->p50 - 2.74) < 0.01);
        // 80 % forward sees a point about five times along a leg, 70 % side on two or three legs.
        QVERIFY2(report->imagesPerPoint->p50 >= 10, qPrintable(QString::number(report->imagesPerPoint->p50)));
        QVERIFY2(report->imagesPerPoint->min >= 5, qPrintable(QString::number(report->imagesPerPoint->min)));
        QCOMPARE(report->coveredFraction, 1.0);
        QVERIFY(report->holes.empty());
        // The area judged: the hull of the centres, 360 × 400 m.
        QVERIFY2(std::fabs(report->areaSquareMeters - 360.0 * 400.0) < 0.02 * 360 * 400, qPrintable(QString::number(report->areaSquareMeters)));
    }

    void photosMissingFromALegLeaveAHoleWhereTheyWere()
    {
        auto shots = test::flySurvey(test::Survey{}, test::surveyCamera());
        // The fifth leg (x = 180 m) flies north; its photos 8 to 14 (y = 140 to 260 m) were not taken,
        // and two legs beside it lost theirs too: a card that filled up for a while.
        std::vector<coverage::Shot> kept;
        double gapLatitude = 0, gapLongitude = 0;
        int gap = 0;
        const size_t perLeg = 21;
        for (size_t i = 0; i < shots.size(); ++i) {
            const size_t leg = i / perLeg, n = i % perLeg;
            const size_t along = leg % 2 == 0 ? n : perLeg - 1 - n; // y / 20 m
            if (leg >= 3 && leg <= 5 && along >= 7 && along <= 13) {
                if (leg == 4) {
                    gapLatitude += shots[i].latitude;
                    gapLongitude += shots[i].longitude;
                    ++gap;
                }
                continue;
            }
            kept.push_back(shots[i]);
        }
        QCOMPARE(gap, 7);
        const auto report = judge(kept);
        QVERIFY(report);
        QVERIFY(report->coveredFraction < 1.0);
        QVERIFY(!report->holes.empty());
        const coverage::Hole &hole = report->holes.front();
        // Three legs of 45 m lost 7 photos of 20 m: the middle one's neighbours still see some of it.
        QVERIFY2(hole.areaSquareMeters > 1000 && hole.areaSquareMeters < 3 * 45 * 160, qPrintable(QString::number(hole.areaSquareMeters)));
        const mission::LocalTangentPlane plane({gapLatitude / gap, gapLongitude / gap});
        const auto offset = plane.project({hole.centreLatitude, hole.centreLongitude});
        QVERIFY2(std::hypot(offset.x, offset.y) < 15, qPrintable(QStringLiteral("%1, %2").arg(offset.x).arg(offset.y)));
        QVERIFY(hole.ring.size() >= 4);
        QCOMPARE(hole.ring.front(), hole.ring.back());
        // The JSON names it with its polygon in longitude, latitude.
        const QJsonObject json = report->toJson();
        const QJsonObject first = json.value(QStringLiteral("holes")).toArray().first().toObject();
        QCOMPARE(first.value(QStringLiteral("polygon")).toArray().size(), int(hole.ring.size()));
        QVERIFY(std::fabs(first.value(QStringLiteral("centre")).toArray().at(0).toDouble() - hole.centreLongitude) < 1e-6);
    }

    // The gaps re-flown: the route of an area scan per hole, flown as its plan says (a photo every
    // trigger distance along each transect), fills the hole.
    void theGapsReflownLeaveNoHole()
    {
        auto shots = test::flySurvey(test::Survey{}, test::surveyCamera());
        std::vector<coverage::Shot> kept;
        for (size_t i = 0; i < shots.size(); ++i) {
            const size_t leg = i / 21, n = i % 21, along = leg % 2 == 0 ? n : 20 - n;
            if (!(leg >= 3 && leg <= 5 && along >= 7 && along <= 13))
                kept.push_back(shots[i]);
        }
        const auto gappy = judge(kept);
        QVERIFY(gappy && !gappy->holes.empty());
        QVERIFY(gappy->legBearing);
        QVERIFY2(std::fabs(std::remainder(*gappy->legBearing, 180.0)) < 1, qPrintable(QString::number(*gappy->legBearing)));
        QVERIFY(gappy->heightAboveGround && gappy->heightAboveGround->p50 == 100);
        const coverage::Hole &hole = gappy->holes.front();
        QVERIFY(hole.scanRing.size() >= 4 && hole.scanRing.front() == hole.scanRing.back());

        coverage::ReflyOptions options;
        options.camera = test::surveyCamera();
        options.heightAboveGround = gappy->heightAboveGround->p50;
        options.legBearing = gappy->legBearing;
        QStringList notes;
        const auto route = coverage::reflyRoute(gappy->holes, options, &notes);
        QVERIFY2(route, qPrintable(notes.join(QLatin1Char('\n'))));
        QCOMPARE(route->segments.size(), gappy->holes.size());
        const auto &scan = std::get<mission::AreaScan>(route->segments.front());
        QCOMPARE(scan.parameters.altitude, 100.0);
        QCOMPARE(scan.parameters.frontOverlapPercent, 80.0);
        QCOMPARE(scan.parameters.directionDeg, *gappy->legBearing);
        QCOMPARE(scan.polygon.size(), hole.scanRing.size() - 1); // open, as a scan's polygon is

        // Fly it: every trigger distance along each transect, heading along it.
        const mission::AreaScanOutcome planned = mission::planAreaScan(scan);
        QVERIFY2(planned.ok(), qPrintable(planned.message));
        std::vector<coverage::Shot> both = kept;
        for (const mission::Transect &t : planned.plan->transects) {
            const mission::LocalTangentPlane plane(t.start);
            const auto end = plane.project(t.end);
            const double length = std::hypot(end.x, end.y);
            const double heading = std::atan2(end.x, end.y) * 180 / 3.14159265358979;
            for (double d = 0; d <= length + 1e-6; d += planned.plan->triggerDistance) {
                const mission::GeoPoint p = plane.unproject({end.x * d / length, end.y * d / length});
                coverage::Shot shot;
                shot.name = QStringLiteral("REFLY_%1.JPG").arg(both.size());
                shot.latitude = p.latitude;
                shot.longitude = p.longitude;
                shot.heightAboveGround = 100;
                shot.headingDegrees = heading;
                both.push_back(shot);
            }
        }
        QVERIFY(both.size() > kept.size());
        const auto filled = judge(both);
        QVERIFY(filled);
        QVERIFY2(filled->holes.empty(), qPrintable(QStringLiteral("%1 holes, the first %2 m²").arg(filled->holes.size()).arg(filled->holes.empty() ? 0 : filled->holes.front().areaSquareMeters)));
        QCOMPARE(filled->coveredFraction, 1.0);
    }

    void thinOverlapIsAHoleEverywhere()
    {
        test::Survey sparse;
        sparse.forward = 0.4;
        sparse.side = 0.2;
        const auto report = judge(test::flySurvey(sparse, test::surveyCamera()));
        QVERIFY(report);
        QVERIFY2(std::fabs(report->forwardOverlap->p50 - 40) < 0.5, qPrintable(QString::number(report->forwardOverlap->p50)));
        QVERIFY2(std::fabs(report->sideOverlap->p50 - 20) < 0.5, qPrintable(QString::number(report->sideOverlap->p50)));
        QVERIFY(report->imagesPerPoint->p50 < 5);
        QVERIFY(report->coveredFraction < 0.2);
    }

    void theRasterGdalReadsIsTheOneJudged()
    {
        coverage::CoverageRaster raster;
        const auto report = judge(test::flySurvey(test::Survey{}, test::surveyCamera()), &raster);
        QVERIFY(report);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("overlap.tif"));
        QString error;
        QVERIFY2(coverage::writeCoverageGeoTiff(raster, path, &error), qPrintable(error));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("overlap.tif")});

        GDALAllRegister();
        std::unique_ptr<GDALDataset> d(GDALDataset::Open(path.toUtf8().constData(), GDAL_OF_RASTER | GDAL_OF_READONLY));
        QVERIFY(d);
        QCOMPARE(d->GetRasterXSize(), raster.width);
        QCOMPARE(d->GetRasterYSize(), raster.height);
        QCOMPARE(QString::fromLatin1(d->GetDriver()->GetDescription()), QStringLiteral("GTiff"));
        const OGRSpatialReference *crs = d->GetSpatialRef();
        QVERIFY(crs);
        QCOMPARE(QString::fromLatin1(crs->GetAuthorityCode(nullptr)), QStringLiteral("32635"));
        double t[6];
        QCOMPARE(d->GetGeoTransform(t), CE_None);
        QCOMPARE(t[0], raster.originEast);
        QCOMPARE(t[3], raster.originNorth);
        QCOMPARE(t[1], 1.0);
        std::vector<uint16_t> values(raster.images.size());
        QCOMPARE(d->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, raster.width, raster.height, values.data(), raster.width, raster.height, GDT_UInt16, 0, 0), CE_None);
        QVERIFY(values == raster.images);
        // The middle of the survey is seen by many images, the raster's corner by none.
        QVERIFY(values[size_t(raster.height / 2) * size_t(raster.width) + size_t(raster.width / 2)] >= 10);
        QCOMPARE(values.front(), uint16_t(0));
    }

    void aPhotoWithoutHeightIsNamedNotPlacedAtZero()
    {
        auto shots = test::flySurvey(test::Survey{}, test::surveyCamera());
        shots[3].heightAboveGround = std::numeric_limits<double>::quiet_NaN();
        shots[5].headingDegrees = std::numeric_limits<double>::quiet_NaN();
        shots[7].heightAboveGround = 0.2;
        const auto report = judge(shots);
        QVERIFY(report);
        QCOMPARE(report->placed, int(shots.size()) - 3);
        QCOMPARE(report->unplaced.size(), size_t(3));
        QCOMPARE(report->unplaced[0].file, shots[3].name);
        QVERIFY(report->unplaced[0].reason.contains(QStringLiteral("height")));
        QVERIFY(report->unplaced[1].reason.contains(QStringLiteral("heading")));
        QVERIFY(report->unplaced[2].reason.contains(QStringLiteral("on the ground")));
    }

    void nothingToJudgeIsAnError()
    {
        coverage::CoverageOptions options;
        options.camera = test::surveyCamera();
        options.camera.focalLengthMm = 0;
        QString error;
        QVERIFY(!coverage::computeCoverage(test::flySurvey(test::Survey{}, test::surveyCamera()), options, nullptr, &error));
        QVERIFY2(error.contains(QStringLiteral("focal length")), qPrintable(error));

        options.camera = test::surveyCamera();
        std::vector<coverage::Shot> none(2);
        none[0].heightAboveGround = std::numeric_limits<double>::quiet_NaN();
        none[1].latitude = 95;
        QVERIFY(!coverage::computeCoverage(none, options, nullptr, &error));
        QVERIFY2(error.contains(QStringLiteral("no photo")), qPrintable(error));

        options.cellMeters = 0.001; // a 400 m survey in millimetres
        QVERIFY(!coverage::computeCoverage(test::flySurvey(test::Survey{}, test::surveyCamera()), options, nullptr, &error));
        QVERIFY2(error.contains(QStringLiteral("larger cell")), qPrintable(error));
        // A JSON value not measured is null, never 0.
        QCOMPARE(coverage::CoverageReport{}.toJson().value(QStringLiteral("forwardOverlap")), QJsonValue(QJsonValue::Null));
    }

    void aCorridorOfOneLegIsJudgedAsAStrip()
    {
        test::Survey corridor;
        corridor.widthMeters = 0; // one leg
        const auto report = judge(test::flySurvey(corridor, test::surveyCamera()));
        QVERIFY(report);
        QVERIFY(!report->sideOverlap || report->sideOverlap->count == 0);
        // 400 m long, 37.5 m either side (a quarter of the 150 m footprint), with round ends.
        const double strip = 400 * 75 + 3.14159 * 37.5 * 37.5;
        QVERIFY2(std::fabs(report->areaSquareMeters - strip) < 0.03 * strip, qPrintable(QString::number(report->areaSquareMeters)));
        QCOMPARE(report->toJson().value(QStringLiteral("sideOverlap")), QJsonValue(QJsonValue::Null));
    }
};

QTEST_GUILESS_MAIN(TestCoverage)
#include "tst_coverage.moc"
