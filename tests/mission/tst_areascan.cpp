// Area-scan generation: a square, a concave polygon, degenerate ones, and the same square near
// the pole and across the antimeridian.
#include "AreaScanPlanner.h"
#include "Geodesy.h"
#include "PolygonGeometry.h"

#include <QtTest>

#include <cmath>

using namespace sortie::mission;

namespace {
// A polygon from metre offsets (east, north) around a centre, through the tangent plane.
std::vector<GeoPoint> shape(const GeoPoint &centre, const std::vector<PlanePoint> &offsets)
{
    const LocalTangentPlane plane(centre);
    std::vector<GeoPoint> out;
    for (const auto &o : offsets)
        out.push_back(plane.unproject(o));
    return out;
}

std::vector<GeoPoint> square(const GeoPoint &centre, double side)
{
    const double h = side / 2;
    return shape(centre, {{-h, -h}, {h, -h}, {h, h}, {-h, h}});
}

bool inside(const std::vector<GeoPoint> &polygon, const GeoPoint &p, double toleranceMeters)
{
    const LocalTangentPlane plane(LocalTangentPlane::centroidOf(polygon));
    std::vector<PlanePoint> pts;
    for (const auto &g : polygon)
        pts.push_back(plane.project(g));
    const PlanePoint q = plane.project(p);
    for (double dy : {0.0, toleranceMeters, -toleranceMeters}) {
        const auto xs = polygon::crossingsAt(pts, q.y + dy);
        for (size_t i = 0; i + 1 < xs.size(); i += 2)
            if (q.x >= xs[i] - toleranceMeters && q.x <= xs[i + 1] + toleranceMeters)
                return true;
    }
    return false;
}

AreaScan scanOf(std::vector<GeoPoint> polygon, double direction = 0.0)
{
    AreaScan s;
    s.polygon = std::move(polygon);
    s.parameters.altitude = 60;
    s.parameters.frontOverlapPercent = 75;
    s.parameters.sideOverlapPercent = 65;
    s.parameters.directionDeg = direction;
    s.parameters.turnaroundMeters = 10;
    return s;
}

void checkSquarePlan(const AreaScanPlan &p)
{
    // Default camera at 60 m: 90 m across, 60 m along the track.
    QVERIFY(std::abs(p.transectSpacing - 90 * 0.35) < 1e-9);
    QVERIFY(std::abs(p.triggerDistance - 60 * 0.25) < 1e-9);
    QCOMPARE(int(p.transects.size()), 32);  // ceil(1000 / 31.5)
    int photos = 0;
    for (const Transect &t : p.transects) {
        QVERIFY2(std::abs(t.length - 1000.0) < 0.5, qPrintable(QString::number(t.length)));
        QCOMPARE(t.photos, 67);  // floor(1000 / 15) + 1
        photos += t.photos;
    }
    QCOMPARE(p.photoCount, photos);
    QCOMPARE(p.photoCount, 32 * 67);
    QCOMPARE(int(p.path.size()), 4 * 32);
    QCOMPARE(p.cells, 1);
    QVERIFY(std::abs(p.areaSquareMeters - 1e6) < 10);
}
}

class TestAreaScan : public QObject
{
    Q_OBJECT
private slots:
    void square()
    {
        const auto polygon = ::square({56.95, 24.1}, 1000);
        const AreaScanOutcome o = planAreaScan(scanOf(polygon));
        QVERIFY2(o.ok(), qPrintable(o.message));
        checkSquarePlan(*o.plan);
        // Boustrophedon: each transect runs the opposite way to the one before, northward or southward.
        for (size_t i = 1; i < o.plan->transects.size(); ++i) {
            const auto &a = o.plan->transects[i - 1], &b = o.plan->transects[i];
            QVERIFY((a.end.latitude > a.start.latitude) != (b.end.latitude > b.start.latitude));
            QVERIFY(geodesicDistance(a.end, b.start) < 31.6);  // the next pass starts beside the last one's end
        }
        for (const auto &t : o.plan->transects)
            QVERIFY(inside(polygon, t.start, 0.01) && inside(polygon, t.end, 0.01));
    }
    void directionRotatesTransects()
    {
        const AreaScanOutcome o = planAreaScan(scanOf(::square({10, 10}, 1000), 90));
        QVERIFY(o.ok());
        const auto g = geodesicInverse(o.plan->transects[0].start, o.plan->transects[0].end);
        QVERIFY(std::abs(std::fmod(g->azimuth1Deg, 180.0) - 90.0) < 0.01);
    }
    void groundSampleDistanceMode()
    {
        AreaScan s = scanOf(::square({0, 0}, 500));
        s.parameters.heightMode = ScanHeightMode::GroundSampleDistance;
        s.parameters.groundSampleDistanceCm = 2.0;
        const AreaScanOutcome o = planAreaScan(s);
        QVERIFY(o.ok());
        // 13.2 mm / 5472 px at 8.8 mm: 0.02 m * 8.8 * 5472 / 13.2 = 72.96 m
        QVERIFY(std::abs(o.plan->altitude - 0.02 * 8.8 * 5472 / 13.2) < 1e-9);
        QVERIFY(std::abs(o.plan->groundSampleDistanceCm - 2.0) < 1e-12);
    }
    void concavePolygonStaysInside()
    {
        // A U open to the north: 300 m square with a 100 m wide, 200 m deep notch.
        const auto polygon = shape({47.4, 8.5}, {{-150, -150}, {150, -150}, {150, 150}, {50, 150}, {50, -50},
                                                 {-50, -50}, {-50, 150}, {-150, 150}});
        const AreaScanOutcome o = planAreaScan(scanOf(polygon, 90));  // east-west passes cross the notch
        QVERIFY2(o.ok(), qPrintable(o.message));
        QVERIFY(o.plan->cells >= 3);  // base and two arms
        for (const Transect &t : o.plan->transects) {
            for (int k = 0; k <= 20; ++k) {
                const double f = k / 20.0;
                const GeoPoint p{t.start.latitude + f * (t.end.latitude - t.start.latitude),
                                 t.start.longitude + f * (t.end.longitude - t.start.longitude)};
                QVERIFY2(inside(polygon, p, 0.05), "a transect leaves the concave polygon");
            }
            QVERIFY(t.length <= 300.01);
        }
        // Coverage: the transects add up to the polygon's area divided by the spacing (within one pass).
        double total = 0;
        for (const auto &t : o.plan->transects)
            total += t.length;
        const double expected = o.plan->areaSquareMeters / o.plan->transectSpacing;
        QVERIFY2(std::abs(total - expected) < 300, qPrintable(QString("%1 vs %2").arg(total).arg(expected)));
    }
    void degenerate_data()
    {
        QTest::addColumn<int>("which");
        QTest::addColumn<int>("problem");
        QTest::newRow("two vertices") << 0 << int(ScanProblem::TooFewVertices);
        QTest::newRow("collinear") << 1 << int(ScanProblem::SelfIntersecting);
        QTest::newRow("bow tie") << 2 << int(ScanProblem::SelfIntersecting);
        QTest::newRow("no area") << 3 << int(ScanProblem::NoArea);
        QTest::newRow("too large") << 4 << int(ScanProblem::TooLarge);
        QTest::newRow("bad camera") << 5 << int(ScanProblem::InvalidCamera);
        QTest::newRow("bad overlap") << 6 << int(ScanProblem::InvalidOverlap);
        QTest::newRow("invalid vertex") << 7 << int(ScanProblem::InvalidVertex);
    }
    void degenerate()
    {
        QFETCH(int, which);
        QFETCH(int, problem);
        const GeoPoint c{30, 30};
        AreaScan s;
        switch (which) {
        case 0: s = scanOf(shape(c, {{0, 0}, {100, 0}})); break;
        case 1: s = scanOf(shape(c, {{0, 0}, {100, 0}, {200, 0}})); break;
        case 2: s = scanOf(shape(c, {{0, 0}, {100, 100}, {100, 0}, {0, 100}})); break;
        case 3: s = scanOf(shape(c, {{0, 0}, {0.5, 0}, {0, 0.5}})); break;
        case 4: s = scanOf(::square(c, 120000)); break;
        case 5: s = scanOf(::square(c, 100)); s.parameters.camera.focalLengthMm = 0; break;
        case 6: s = scanOf(::square(c, 100)); s.parameters.sideOverlapPercent = 100; break;
        case 7: s = scanOf({{0, 0}, {0, 1}, {95, 1}}); break;
        }
        const AreaScanOutcome o = planAreaScan(s);
        QVERIFY(!o.ok());
        QCOMPARE(int(o.problem), problem);
        QVERIFY(!o.message.isEmpty());
    }
    void nearThePole()
    {
        const auto polygon = ::square({89.995, 0}, 1000);  // the pole is 555 m away: inside the square's reach
        const AreaScanOutcome o = planAreaScan(scanOf(polygon));
        QVERIFY2(o.ok(), qPrintable(o.message));
        checkSquarePlan(*o.plan);
        const AreaScanOutcome aroundPole = planAreaScan(scanOf(::square({90, 0}, 1000)));
        QVERIFY2(aroundPole.ok(), qPrintable(aroundPole.message));
        checkSquarePlan(*aroundPole.plan);
    }
    void acrossTheAntimeridian()
    {
        const auto polygon = ::square({-16.5, 180.0}, 1000);
        bool east = false, west = false;
        for (const auto &g : polygon)
            (g.longitude > 0 ? east : west) = true;
        QVERIFY(east && west);
        const AreaScanOutcome o = planAreaScan(scanOf(polygon));
        QVERIFY2(o.ok(), qPrintable(o.message));
        checkSquarePlan(*o.plan);
        for (const auto &t : o.plan->transects)
            QVERIFY(std::abs(std::abs(t.start.longitude) - 180.0) < 0.01);
    }
};

QTEST_GUILESS_MAIN(TestAreaScan)
#include "tst_areascan.moc"
