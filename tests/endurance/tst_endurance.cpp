// The time model and the energy estimate on routes worked out by hand: every expected figure is
// computed here from the profile's numbers, not by the code under test.
#include "EnduranceEstimate.h"
#include "EnduranceRule.h"
#include "Geodesy.h"
#include "RouteStatistics.h"

#include <QtTest>

using namespace sortie::endurance;
using namespace sortie::mission;

namespace {
const GeoPoint kOrigin{56.95, 24.1};

// Powers chosen so that 3600 W·s is 1 Wh: hover 360 W is 0.1 Wh per second.
EnergyProfile quad()
{
    EnergyProfile p;
    p.name = QStringLiteral("Test quad");
    p.batteryWh = 100;
    p.reserve = 0.2;
    p.cruiseSpeed = 10;
    p.climbRate = 2;
    p.descentRate = 1;
    p.hoverPowerW = 360;
    p.cruisePowerW = 288;
    p.climbPowerW = 540;
    p.descentPowerW = 180;
    return p;
}

Waypoint at(const GeoPoint &g, double altitude, double speed, WaypointRole role = WaypointRole::Pass)
{
    Waypoint w;
    w.position = g;
    w.altitude = altitude;
    w.speed = speed;
    w.role = role;
    return w;
}

// Points on one geodesic from the origin, `metres` along it at `azimuth`.
GeoPoint along(double azimuth, double metres)
{
    return geodesicDirect(kOrigin, azimuth, metres).point;
}

EnduranceEstimate estimate(const Route &r, const EnergyProfile &p = quad(), const FlightConditions &c = {})
{
    const Result<EnduranceEstimate> e = estimateEndurance(r, p, c);
    if (!e)
        qFatal("%s", qPrintable(e.error().toString()));
    return e.value();
}

// Distances come from the geodesy to about 10 µm: 1e-6 Wh is 0.45 mm of flight at 288 W and 10 m/s.
bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) <= tolerance;
}
#define QNEAR(a, b, tol) QVERIFY2(near(double(a), double(b), (tol)), qPrintable(QStringLiteral("%1 != %2").arg(double(a), 0, 'f', 9).arg(double(b), 0, 'f', 9)))
} // namespace

class TstEndurance : public QObject
{
    Q_OBJECT
private slots:
    // 1000 m at 10 m/s (cruise: 288 W) then 500 m at 5 m/s, where the curve gives
    // 360 + (288 - 360)·(5/10)² = 342 W.
    void levelLegs()
    {
        Route r;
        r.segments = {at(kOrigin, 50, 10), at(along(90, 1000), 50, 10), at(along(90, 1500), 50, 5)};
        const EnduranceEstimate e = estimate(r);
        QCOMPARE(e.legs.size(), size_t(2));
        QNEAR(e.legs[0].seconds, 100.0, 1e-6);
        QNEAR(e.legs[0].energyWh, 288.0 * 100 / 3600, 1e-6);
        QNEAR(e.legs[1].seconds, 100.0, 1e-6);
        QNEAR(e.legs[1].energyWh, 342.0 * 100 / 3600, 1e-6);
        QNEAR(e.flightTimeSeconds, 200.0, 1e-6);
        QNEAR(e.energyWh, 8.0 + 9.5, 1e-6);
        QNEAR(e.batteryAtEnd, 1 - 17.5 / 100, 1e-6);
        QCOMPARE(e.batteriesNeeded, 1);
        QVERIFY(e.changes.empty());
        QVERIFY(!e.pointOfNoReturn && !e.homeKnown);
        const PhaseSeconds s = e.timeline.legs()[0].phases();
        QNEAR(s.level, 100.0, 1e-6);
        QCOMPARE(s.climb + s.descent + s.hover + s.manoeuvre, 0.0);
        // A leg with no speed of its own flies at the profile's cruise speed.
        std::get<Waypoint>(r.segments[2]).speed = 0;
        QNEAR(estimate(r).legs[1].seconds, 50.0, 1e-6);
    }

    // Take-off to 50 m (25 s at 2 m/s), then straight up 40 m more (20 s): 45 s at climbPowerW.
    void pureClimb()
    {
        Route r;
        r.segments = {at(kOrigin, 50, 10, WaypointRole::Takeoff), at(kOrigin, 90, 10)};
        const EnduranceEstimate e = estimate(r);
        QCOMPARE(e.legs.size(), size_t(1));
        QNEAR(e.legs[0].seconds, 45.0, 1e-6);
        QNEAR(e.legs[0].energyWh, 540.0 * 45 / 3600, 1e-6);
        QNEAR(e.timeline.legs()[0].phases().climb, 45.0, 1e-6);
        // Landing at the end: 90 m down at 1 m/s at descentPowerW, counted in the last leg.
        std::get<Waypoint>(r.segments[1]).role = WaypointRole::Land;
        const EnduranceEstimate landed = estimate(r);
        QNEAR(landed.legs[0].seconds, 45.0 + 90.0, 1e-6);
        QNEAR(landed.legs[0].energyWh, (540.0 * 45 + 180.0 * 90) / 3600, 1e-6);
    }

    // Climbing while flying: the longer of the two times, level power plus the climb's excess over
    // hover for the climbing seconds. 1000 m at 10 m/s (100 s) while climbing 60 m (30 s).
    void climbWhileFlying()
    {
        Route r;
        r.segments = {at(kOrigin, 40, 10), at(along(90, 1000), 100, 10)};
        const EnduranceEstimate e = estimate(r);
        QNEAR(e.legs[0].seconds, 100.0, 1e-6);
        QNEAR(e.legs[0].energyWh, (288.0 * 100 + (540.0 - 360.0) * 30) / 3600, 1e-6);
        // Descending 60 m (60 s): level power less the descent's saving, 288 + 180 - 360 = 108 W,
        // but never below descentPowerW (180 W).
        std::get<Waypoint>(r.segments[1]).altitude = -20;
        std::get<Waypoint>(r.segments[0]).altitude = 40;
        const EnduranceEstimate down = estimate(r);
        QNEAR(down.legs[0].energyWh, (288.0 * 40 + 180.0 * 60) / 3600, 1e-6);
    }

    // A 30 s wait before the first leg and a panorama at the second point: 360° at 36°/s (10 s)
    // with a 2 s pause at each of its 5 stops (0°, 90°, 180°, 270°, 360°): 20 s. Both at hover power.
    void hoverActions()
    {
        Route r;
        Waypoint a = at(kOrigin, 50, 10);
        a.actions.push_back(WaitAction{30, false});
        Waypoint b = at(along(90, 1000), 50, 10);
        PanoramaAction pano;
        pano.angleDeg = 360;
        pano.stepAngleDeg = 90;
        pano.stepDelaySeconds = 2;
        pano.rotationSpeedDegPerSecond = 36;
        b.actions.push_back(pano);
        r.segments = {a, b};
        QNEAR(actionSeconds(b.actions), 20.0, 1e-6);
        const EnduranceEstimate e = estimate(r);
        QNEAR(e.legs[0].seconds, 30.0 + 100.0 + 20.0, 1e-6);
        QNEAR(e.legs[0].energyWh, (360.0 * 50 + 288.0 * 100) / 3600, 1e-6);
        QNEAR(e.timeline.legs()[0].phases().hover, 50.0, 1e-6);
        // The statistics' flight time is the same model's.
        QNEAR(computeStatistics(r).flightTimeSeconds, 150.0, 1e-6);
    }

    // 1000 m north at 10 m/s air speed. A 4 m/s wind from the north: 6 m/s over the ground; from
    // the south: 14 m/s; 6 m/s from the east: sqrt(10² - 6²) = 8 m/s. Energy is air time at 288 W.
    void headAndTailWind()
    {
        Route north;
        north.segments = {at(kOrigin, 50, 10), at(along(0, 1000), 50, 10)};
        const auto windFrom = [](double speed, double from) { return FlightConditions{Wind{speed, from}, TurnMode::Coordinated}; };
        const EnduranceEstimate head = estimate(north, quad(), windFrom(4, 0));
        QNEAR(head.timeline.legs()[0].groundSpeed, 6.0, 1e-6);
        QNEAR(head.legs[0].seconds, 1000.0 / 6, 1e-6);
        QNEAR(head.legs[0].energyWh, 288.0 * (1000.0 / 6) / 3600, 1e-6);
        const EnduranceEstimate tail = estimate(north, quad(), windFrom(4, 180));
        QNEAR(tail.legs[0].seconds, 1000.0 / 14, 1e-6);
        QNEAR(tail.legs[0].energyWh, 288.0 * (1000.0 / 14) / 3600, 1e-6);
        const EnduranceEstimate cross = estimate(north, quad(), windFrom(6, 90));
        QNEAR(cross.legs[0].seconds, 125.0, 1e-6);
        // A head wind as fast as the air speed: the leg cannot be flown, an error, not infinity.
        const Result<EnduranceEstimate> stuck = estimateEndurance(north, quad(), windFrom(12, 0));
        QVERIFY(!stuck.ok());
        QVERIFY(stuck.error().message.contains(QStringLiteral("leg 1")));
        std::vector<ValidationIssue> issues = enduranceIssues(north, quad(), stuck);
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].rule, QStringLiteral("endurance-wind"));
        QCOMPARE(issues[0].severity, Severity::Error);
    }

    // With 2 m/s² acceleration, a stop costs v/2a = 2.5 s beyond cruising on each leg end that
    // stops. Two 1000 m legs at 10 m/s: coordinated, the route stops at its ends only (205 s);
    // stop-and-turn stops in the middle too (210 s). The extra seconds cost level power.
    void stopAndTurnVersusCoordinated()
    {
        Route r;
        r.segments = {at(kOrigin, 50, 10), at(along(90, 1000), 50, 10), at(along(0, 1000), 50, 10)};
        // The second leg runs from 1000 m east to 1000 m north: its length by the geodesy.
        const double second = geodesicDistance(along(90, 1000), along(0, 1000));
        EnergyProfile p = quad();
        p.acceleration = 2;
        const EnduranceEstimate coordinated = estimate(r, p, {Wind{}, TurnMode::Coordinated});
        QNEAR(coordinated.flightTimeSeconds, 100 + second / 10 + 2.5 + 2.5, 1e-6);
        QNEAR(coordinated.energyWh, 288.0 * (100 + second / 10 + 5) / 3600, 1e-6);
        const EnduranceEstimate stopping = estimate(r, p, {Wind{}, TurnMode::StopAndTurn});
        QNEAR(stopping.flightTimeSeconds, 100 + second / 10 + 4 * 2.5, 1e-6);
        QNEAR(stopping.timeline.legs()[0].phases().manoeuvre, 5.0, 1e-6);
        QNEAR(stopping.energyWh, 288.0 * (100 + second / 10 + 10) / 3600, 1e-6);
        // A leg too short to reach its speed: 20 m from rest to rest at 2 m/s² takes 2·sqrt(20/2).
        Route shortHop;
        shortHop.segments = {at(kOrigin, 50, 10), at(along(90, 20), 50, 10)};
        QNEAR(estimate(shortHop, p).flightTimeSeconds, 2 * std::sqrt(10.0), 1e-6);
    }

    // Four 1000 m legs east at cruise (8 Wh each, 32 Wh) on a 22.5 Wh battery with a 20 % reserve
    // (18 Wh usable), 30 m up, home at the start. Legs 1-2 use 16 Wh: the change is at the end of
    // leg 2 (Waypoint 3, 2000 m); the rest (16 Wh) fits the second battery.
    void batteryChangesAndThePointOfNoReturn()
    {
        Route r;
        for (int i = 0; i <= 4; ++i)
            r.segments.push_back(at(along(90, 1000.0 * i), 30, 10));
        r.settings.home = HomePosition{kOrigin, 0};
        EnergyProfile p = quad();
        p.batteryWh = 22.5;
        const EnduranceEstimate e = estimate(r, p);
        QNEAR(e.energyWh, 32.0, 1e-6);
        QNEAR(e.batteryAtEnd, 1 - 32 / 22.5, 1e-6);
        QCOMPARE(e.batteriesNeeded, 2);
        QCOMPARE(e.changes.size(), size_t(1));
        QCOMPARE(e.changes[0].at.leg, 2);
        QCOMPARE(e.changes[0].at.segment, 2);
        QNEAR(e.changes[0].at.distance, 2000.0, 1e-4);
        QNEAR(e.changes[0].batteryLeft, 1 - 16 / 22.5, 1e-6);
        QVERIFY(!e.changes[0].planned);
        QNEAR(e.lastBatteryAtEnd, 1 - 16 / 22.5, 1e-6);
        // Out at s metres: 0.008·s Wh spent, 0.008·s Wh to fly back at cruise and 30 m down at
        // 1 m/s and 180 W (1.5 Wh). Home is in reach while 18 - 0.016·s - 1.5 >= 0: s = 1031.25.
        QVERIFY(e.pointOfNoReturn.has_value());
        QCOMPARE(e.pointOfNoReturn->leg, 2);
        QNEAR(e.pointOfNoReturn->distance, 1031.25, 0.05);
        QNEAR(energyHomeWh(p, along(90, 1000), 30, kOrigin).value(), 8 + 1.5, 1e-6);

        // The rule: a change with no landing planned is an error on the waypoint.
        std::vector<ValidationIssue> issues = enduranceIssues(r, p, estimateEndurance(r, p));
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].severity, Severity::Error);
        QCOMPARE(issues[0].rule, QStringLiteral("endurance-battery"));
        QCOMPARE(issues[0].segment, 2);

        // Landing at Waypoint 3 plans the change (its 30 m descent adds 1.5 Wh to leg 2: 17.5 Wh).
        // The second battery lands with 1 - 16/22.5 = 28.9 % left: within 10 % of the reserve.
        std::get<Waypoint>(r.segments[2]).role = WaypointRole::Land;
        const EnduranceEstimate planned = estimate(r, p);
        QCOMPARE(planned.changes.size(), size_t(1));
        QVERIFY(planned.changes[0].planned);
        QNEAR(planned.changes[0].batteryLeft, 1 - 17.5 / 22.5, 1e-6);
        issues = enduranceIssues(r, p, estimateEndurance(r, p));
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].severity, Severity::Warning);
        QCOMPARE(issues[0].rule, QStringLiteral("endurance-reserve"));

        // A route that fits with home in reach all along has no point of no return.
        Route shortRoute;
        shortRoute.segments = {r.segments[0], r.segments[1]};
        shortRoute.settings.home = r.settings.home;
        shortRoute.settings.endAction = EndAction::ReturnHome;
        const EnduranceEstimate fits = estimate(shortRoute, p);
        QCOMPARE(fits.legs.size(), size_t(2));  // out and home
        QVERIFY(fits.legs[1].returnHome);
        QNEAR(fits.energyWh, 8 + 8 + 1.5, 1e-6);
        QVERIFY(fits.homeKnown && !fits.pointOfNoReturn);
        // It lands with 1 - 17.5/22.5 = 22 % left: no error, the reserve warning only.
        issues = enduranceIssues(shortRoute, p, estimateEndurance(shortRoute, p));
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].severity, Severity::Warning);
    }

    // The timeline answers where the vehicle is: take-off, the move, the hold, in order.
    void positionOnTheTimeline()
    {
        Route r;
        Waypoint a = at(kOrigin, 20, 10, WaypointRole::Takeoff);  // 10 s up at 2 m/s
        Waypoint b = at(along(90, 1000), 20, 10);
        b.actions.push_back(WaitAction{5, false});
        r.segments = {a, b};
        const RouteTimeline t = estimate(r).timeline;
        QNEAR(t.totalSeconds(), 10 + 100 + 5, 1e-6);
        QNEAR(t.positionAt(5).altitude, 10.0, 1e-6);
        QCOMPARE(t.positionAt(5).position, kOrigin);
        const TimelinePosition mid = t.positionAt(10 + 50);
        QNEAR(geodesicDistance(kOrigin, mid.position), 500.0, 1e-3);
        QCOMPARE(t.positionAt(112).position, along(90, 1000));
        QCOMPARE(t.positionAt(1e9).leg, 0);
    }
};

QTEST_GUILESS_MAIN(TstEndurance)
#include "tst_endurance.moc"
