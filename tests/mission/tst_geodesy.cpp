// Geodesy against published reference values: Vincenty's five test lines (Survey Review 1975,
// Table II), the WGS-84 meridian quadrant and equatorial degree, plus round trips.
#include "Geodesy.h"
#include "LocalTangentPlane.h"
#include "RouteStatistics.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace sortie::mission;

namespace {
double dms(double d, double m, double s)
{
    const double sign = (d < 0 || (d == 0 && (m < 0 || s < 0))) ? -1.0 : 1.0;
    return sign * (std::abs(d) + std::abs(m) / 60.0 + std::abs(s) / 3600.0);
}
constexpr double kArcSec = 1.0 / 3600.0;

struct Line { const char *name; Ellipsoid e; double lat1, lat2, dlon, az1, az2, s; };

const Ellipsoid bessel{6377397.155, 1.0 / 299.1528128};
const Ellipsoid international{6378388.0, 1.0 / 297.0};

std::vector<Line> vincentyLines()
{
    return {
        {"a", bessel, dms(55, 45, 0), dms(-33, 26, 0), dms(108, 13, 0), dms(96, 36, 8.79960), dms(137, 52, 22.01454), 14110526.170},
        {"b", international, dms(37, 19, 54.95367), dms(26, 7, 42.83946), dms(41, 28, 35.50729), dms(95, 27, 59.63089), dms(118, 5, 58.96161), 4085966.703},
        {"c", international, dms(35, 16, 11.24862), dms(67, 22, 14.77638), dms(137, 47, 28.31435), dms(15, 44, 23.74850), dms(144, 55, 39.92147), 8084823.839},
        {"d", international, dms(1, 0, 0), dms(0, -59, -53.83076), dms(179, 17, 48.02997), dms(89, 0, 0), dms(91, 0, 6.11733), 19960000.000},
        {"e", international, dms(1, 0, 0), dms(1, 1, 15.18952), dms(179, 46, 17.84244), dms(4, 59, 59.99995), dms(174, 59, 59.88481), 19780006.558},
    };
}
}

class TestGeodesy : public QObject
{
    Q_OBJECT
private slots:
    void vincentyDirect_data()
    {
        QTest::addColumn<int>("index");
        for (int i = 0; i < 5; ++i)
            QTest::newRow(vincentyLines()[i].name) << i;
    }
    void vincentyDirect()
    {
        QFETCH(int, index);
        const Line l = vincentyLines()[index];
        const GeodesicDirect d = geodesicDirect({l.lat1, 0.0}, l.az1, l.s, l.e);
        // Published to 0.00001": allow 0.0001" (3 mm).
        QVERIFY2(std::abs(d.point.latitude - l.lat2) < 1e-4 * kArcSec, qPrintable(QString::number(d.point.latitude, 'f', 10)));
        QVERIFY2(std::abs(d.point.longitude - l.dlon) < 1e-4 * kArcSec, qPrintable(QString::number(d.point.longitude, 'f', 10)));
        QVERIFY(std::abs(d.azimuth2Deg - l.az2) < 1e-4 * kArcSec);
    }
    void vincentyInverse_data() { vincentyDirect_data(); }
    void vincentyInverse()
    {
        QFETCH(int, index);
        const Line l = vincentyLines()[index];
        const auto g = geodesicInverse({l.lat1, 0.0}, {l.lat2, l.dlon}, l.e);
        QVERIFY(g.has_value());
        QVERIFY2(std::abs(g->distance - l.s) < 0.002, qPrintable(QString::number(g->distance, 'f', 4)));
        // Line (d) is nearly antipodal: its azimuths are ill-conditioned and agree to 0.002".
        const double tolerance = (index == 3 ? 2e-3 : 1e-4) * kArcSec;
        QVERIFY(std::abs(g->azimuth1Deg - l.az1) < tolerance);
        QVERIFY(std::abs(g->azimuth2Deg - l.az2) < tolerance);
    }
    void wgs84ReferenceDistances()
    {
        // Meridian quadrant of WGS-84: 10,001,965.729 m. One degree of longitude on the equator: a·π/180.
        QVERIFY(std::abs(geodesicDistance({0, 0}, {90, 0}) - 10001965.7293) < 0.001);
        QVERIFY(std::abs(geodesicDistance({0, 0}, {0, 1}) - 111319.4907933) < 0.0001);
        QCOMPARE(geodesicDistance({47.5, 8.5}, {47.5, 8.5}), 0.0);
    }
    void antimeridianAndPoles()
    {
        // The short way across the antimeridian, not around the globe.
        const double across = geodesicDistance({0, 179.999}, {0, -179.999});
        QVERIFY(std::abs(across - 2 * 111.3194907933) < 0.001);
        // Over the pole: two meridians 180° apart.
        const double overPole = geodesicDistance({89.99, 0}, {89.99, 180});
        QVERIFY(std::abs(overPole - 2 * (10001965.7293 - geodesicDistance({0, 0}, {89.99, 0}))) < 0.01);
    }
    void shortLegsAgreeWithVincenty()
    {
        // The fast path for legs within 0.01°, everywhere on the globe.
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0, 1);
        double worst = 0;
        for (int i = 0; i < 50000; ++i) {
            const GeoPoint a{-89.99 + u(rng) * 179.98, -180 + u(rng) * 360};
            const GeoPoint b{std::clamp(a.latitude + (u(rng) * 2 - 1) * kShortLegDegrees, -90.0, 90.0),
                             normalizeLongitude(a.longitude + (u(rng) * 2 - 1) * kShortLegDegrees)};
            const auto exact = geodesicInverse(a, b);
            QVERIFY(exact.has_value());
            worst = std::max(worst, std::abs(geodesicDistance(a, b) - exact->distance));
        }
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
    }
    void nearlyAntipodalFallsBack()
    {
        QVERIFY(!geodesicInverse({0, 0}, {0.5, 179.7}).has_value());
        const double d = geodesicDistance({0, 0}, {0.5, 179.7});
        QVERIFY(d > 19.9e6 && d < 20.1e6);
    }
    void directInverseRoundTrip()
    {
        for (double lat : {-89.5, -45.0, 0.0, 33.3, 60.0, 89.9}) {
            for (double az : {0.0, 37.0, 90.0, 181.0, 300.0}) {
                const GeoPoint a{lat, 170.0};
                const GeodesicDirect d = geodesicDirect(a, az, 12345.678);
                const auto g = geodesicInverse(a, d.point);
                QVERIFY(g.has_value());
                QVERIFY(std::abs(g->distance - 12345.678) < 1e-5);  // 10 µm
            }
        }
    }
    void ecefRoundTrip()
    {
        for (const GeoPoint p : {GeoPoint{0, 0}, GeoPoint{56.95, 24.1}, GeoPoint{-89.9999, 12}, GeoPoint{90, 0}, GeoPoint{-33.9, -179.99}}) {
            double h = 0;
            const GeoPoint q = fromEcef(toEcef(p, 123.4), &h);
            QVERIFY(std::abs(q.latitude - p.latitude) < 1e-10);
            if (std::abs(p.latitude) < 90)
                QVERIFY(std::abs(normalizeLongitude(q.longitude - p.longitude)) < 1e-10);
            QVERIFY(std::abs(h - 123.4) < 1e-6);
        }
    }
    void tangentPlaneRoundTrip()
    {
        for (const GeoPoint o : {GeoPoint{56.95, 24.1}, GeoPoint{89.999, 45}, GeoPoint{-12.0, 179.999}}) {
            const LocalTangentPlane plane(o);
            for (double x : {-3000.0, 0.0, 2500.0}) {
                for (double y : {-2000.0, 0.0, 4000.0}) {
                    const GeoPoint g = plane.unproject({x, y});
                    const PlanePoint back = plane.project(g);
                    QVERIFY(std::abs(back.x - x) < 1e-6 && std::abs(back.y - y) < 1e-6);
                }
            }
        }
        const LocalTangentPlane plane({0, 0});
        QVERIFY(std::isnan(plane.unproject({1e8, 0}).latitude));  // beyond the horizon
    }
    void boundingBoxAcrossAntimeridian()
    {
        const GeoBox box = boundingBoxOf({{10, 179.5}, {11, -179.5}, {10.5, 179.9}});
        QVERIFY(box.crossesAntimeridian());
        QCOMPARE(box.west, 179.5);
        QCOMPARE(box.east, -179.5);
        QCOMPARE(box.south, 10.0);
        QCOMPARE(box.north, 11.0);
        const GeoBox plain = boundingBoxOf({{1, 2}, {3, 4}});
        QVERIFY(!plain.crossesAntimeridian());
        QCOMPARE(plain.west, 2.0);
    }
};

QTEST_GUILESS_MAIN(TestGeodesy)
#include "tst_geodesy.moc"
