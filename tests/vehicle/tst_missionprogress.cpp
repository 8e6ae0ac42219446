// Mission progress: which waypoint, how far and how long the rest is, the bearing to it.
#include "MissionProgress.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace sortie::vehicle;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
// 0.001° of latitude on the sphere QtPositioning uses (6371.0072 km).
constexpr double kMilliDegree = 6371007.2 * kRad * 0.001;

MissionItem at(double latDeg, double lonDeg, double speed = 0)
{
    return {latDeg, lonDeg, 30, speed, 0, {}};
}
} // namespace

class TestMissionProgress : public QObject
{
    Q_OBJECT

private slots:
    void alongTheRemainingLegs()
    {
        // Three waypoints due north, 0.001° apart; the vehicle halfway to the second.
        const std::vector<MissionItem> mission{at(56.000, 24.0), at(56.001, 24.0, 10), at(56.002, 24.0, 4)};
        const QGeoCoordinate position(56.0005, 24.0);
        const auto p = MissionProgress::compute(mission, 1, position, 8.0);
        QVERIFY(p.isFlying());
        QCOMPARE(p.count, 3);
        QCOMPARE(p.active, 1);
        QVERIFY(std::abs(p.distanceToActive - kMilliDegree / 2) < 0.05);
        QVERIFY(std::abs(p.distanceLeft - kMilliDegree * 1.5) < 0.05);
        // Each leg at its own planned speed: half a leg at 10 m/s, a whole one at 4 m/s.
        QVERIFY(std::abs(p.timeLeft - (kMilliDegree / 2 / 10 + kMilliDegree / 4)) < 0.01);
        QVERIFY(std::abs(p.bearingToActive) < 1e-4 || std::abs(p.bearingToActive - 360) < 1e-4);
    }

    void legsWithoutASpeedUseTheVehiclesOrTheCruiseSpeed()
    {
        const std::vector<MissionItem> mission{at(56.000, 24.0), at(56.001, 24.0)};
        const QGeoCoordinate position(56.000, 24.0);
        // Moving at 6 m/s: the remaining leg at 6 m/s.
        QVERIFY(std::abs(MissionProgress::compute(mission, 1, position, 6.0).timeLeft - kMilliDegree / 6) < 0.01);
        // Standing (before take-off): the cruise speed, not an endless time.
        QVERIFY(std::abs(MissionProgress::compute(mission, 1, position, 0.0, 5.0).timeLeft - kMilliDegree / 5) < 0.01);
        QVERIFY(std::abs(MissionProgress::compute(mission, 1, position, qQNaN(), 5.0).timeLeft - kMilliDegree / 5) < 0.01);
    }

    void bearingPointsTheWay()
    {
        const std::vector<MissionItem> mission{at(56.0, 24.001)};
        const auto east = MissionProgress::compute(mission, 0, QGeoCoordinate(56.0, 24.0), 5);
        QVERIFY(std::abs(east.bearingToActive - 90) < 0.06);
        const auto west = MissionProgress::compute(mission, 0, QGeoCoordinate(56.0, 24.002), 5);
        QVERIFY(std::abs(west.bearingToActive - 270) < 0.06); // never negative
        QVERIFY(std::isnan(bearingBetween(QGeoCoordinate(), QGeoCoordinate(56, 24))));
    }

    void unknownIsMissingNotZero()
    {
        const std::vector<MissionItem> mission{at(56.000, 24.0), at(56.001, 24.0)};
        // No active waypoint reported: the count is known, the rest is missing.
        const auto idle = MissionProgress::compute(mission, -1, QGeoCoordinate(56.0, 24.0), 5);
        QVERIFY(!idle.isFlying());
        QCOMPARE(idle.count, 2);
        QVERIFY(std::isnan(idle.distanceLeft) && std::isnan(idle.timeLeft));
        // No position yet.
        const auto blind = MissionProgress::compute(mission, 1, QGeoCoordinate(), 5);
        QVERIFY(std::isnan(blind.distanceLeft));
        // No mission at all.
        const auto none = MissionProgress::compute({}, 0, QGeoCoordinate(56.0, 24.0), 5);
        QCOMPARE(none.count, 0);
        QVERIFY(!none.isFlying() && !none.isComplete());
        QVERIFY(std::isnan(none.distanceLeft));
        // Past the last waypoint: complete, nothing left.
        const auto done = MissionProgress::compute(mission, 2, QGeoCoordinate(56.0, 24.0), 5);
        QVERIFY(done.isComplete());
        QCOMPARE(done.distanceLeft, 0.0);
        QCOMPARE(done.timeLeft, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestMissionProgress)
#include "tst_missionprogress.moc"
