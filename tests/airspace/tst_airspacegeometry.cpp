// The 3D check against hand-worked cases: legs on a tangent plane (metres east/north of an origin),
// heights chosen so the crossings can be worked out with a pencil.
#include "AirspaceCheck.h"
#include "AirspaceRule.h"
#include "Geodesy.h"
#include "ValidationGate.h"

#include <QtTest>

using namespace sortie::airspace;
using sortie::mission::GeoPoint;
using sortie::mission::LocalTangentPlane;
using sortie::mission::WaypointRole;
using sortie::terrain::ProfileRoute;
using sortie::terrain::ProfileWaypoint;

namespace {
const GeoPoint kOrigin{56.95, 24.1};

struct At
{
    double x, y, altitude;
    HeightReference reference = HeightReference::Amsl;
    WaypointRole role = WaypointRole::Pass;
};

ProfileRoute routeThrough(const LocalTangentPlane &plane, const std::vector<At> &points)
{
    ProfileRoute r;
    r.name = QStringLiteral("test");
    for (const At &p : points) {
        ProfileWaypoint w;
        w.position = plane.unproject({p.x, p.y});
        w.altitude = p.altitude;
        w.reference = p.reference;
        w.role = p.role;
        w.row = int(r.waypoints.size());
        r.waypoints.push_back(w);
    }
    return r;
}

Zone square(const LocalTangentPlane &plane, double x0, double y0, double x1, double y1, ZoneKind kind = ZoneKind::Exclusion)
{
    Zone z;
    z.name = QStringLiteral("square");
    z.kind = kind;
    z.shape = ZonePolygons{{ZonePolygon{{{plane.unproject({x0, y0}), plane.unproject({x1, y0}), plane.unproject({x1, y1}),
                                          plane.unproject({x0, y1})}}}}};
    return z;
}

AirspaceReport check(const LocalTangentPlane &plane, const std::vector<At> &points, const std::vector<Zone> &zones, double buffer = 20)
{
    return checkAirspace(flownPath(routeThrough(plane, points), nullptr, {}, &plane), zones, buffer);
}

bool near(double a, double b, double tolerance = 0.05)
{
    return std::abs(a - b) <= tolerance;
}
} // namespace

class TstAirspaceGeometry : public QObject
{
    Q_OBJECT
private slots:
    // Straight through a 100 m square: in at 50 m, out at 150 m, named and numbered.
    void aLegThroughASquare()
    {
        const LocalTangentPlane plane(kOrigin);
        const AirspaceReport r = check(plane, {{-150, 50, 100}, {-50, 50, 100}, {150, 50, 100}}, {square(plane, 0, 0, 100, 100)});
        QCOMPARE(r.zones, 1);
        QCOMPARE(r.violations.size(), size_t(1));
        const AirspaceViolation &v = r.violations.front();
        QCOMPARE(v.leg, 2);
        QCOMPARE(v.kind, ViolationKind::InsideExclusion);
        QVERIFY2(near(v.fromDistance, 150) && near(v.toDistance, 250), qPrintable(QStringLiteral("%1 %2").arg(v.fromDistance).arg(v.toDistance)));
        QVERIFY(r.warnings.empty());
    }

    // The line x + y = 200 touches the corner (100, 100) only: no violation, a warning (0 m away).
    // x + y = 190 cuts the corner between (90, 100) and (100, 90): 50√2 to 60√2 m from its start.
    // x + y = 200 + 5√2 passes 5 m outside: a warning with 5 m.
    void aLegGrazingACorner()
    {
        const LocalTangentPlane plane(kOrigin);
        const Zone z = square(plane, 0, 0, 100, 100);
        AirspaceReport touch = check(plane, {{50, 150, 100}, {150, 50, 100}}, {z});
        QVERIFY(touch.violations.empty());
        QCOMPARE(touch.warnings.size(), size_t(1));
        QVERIFY(near(touch.warnings.front().clearance, 0));

        AirspaceReport cut = check(plane, {{40, 150, 100}, {150, 40, 100}}, {z});
        QCOMPARE(cut.violations.size(), size_t(1));
        QVERIFY2(near(cut.violations.front().fromDistance, 50 * M_SQRT2) && near(cut.violations.front().toDistance, 60 * M_SQRT2),
                 qPrintable(QStringLiteral("%1 %2").arg(cut.violations.front().fromDistance).arg(cut.violations.front().toDistance)));

        const double c = 200 + 5 * M_SQRT2;
        AirspaceReport past = check(plane, {{c - 150, 150, 100}, {150, c - 150, 100}}, {z});
        QVERIFY(past.violations.empty());
        QCOMPARE(past.warnings.size(), size_t(1));
        QVERIFY(near(past.warnings.front().clearance, 5, 0.01));
        QVERIFY(check(plane, {{c - 150, 150, 100}, {150, c - 150, 100}}, {z}, 4).warnings.empty());  // a 4 m buffer: nothing
    }

    // A zone from 100 to 200 m AMSL. Level at 50 m: under it (50 m below, beyond the buffer); at
    // 250 m: over it. Climbing 50 -> 150 m over 200 m (h = 50 + d/2) reaches the floor at d = 100:
    // inside from 100 to 150 m. Descending 300 -> 100 (h = 300 - d) is below the ceiling from d = 100.
    void underTheFloorAndOverTheCeiling()
    {
        const LocalTangentPlane plane(kOrigin);
        Zone z = square(plane, 0, 0, 100, 100);
        z.floor = HeightLimit{100, HeightReference::Amsl};
        z.ceiling = HeightLimit{200, HeightReference::Amsl};
        QVERIFY(check(plane, {{-50, 50, 50}, {150, 50, 50}}, {z}).violations.empty());
        QVERIFY(check(plane, {{-50, 50, 50}, {150, 50, 50}}, {z}).warnings.empty());
        QVERIFY(check(plane, {{-50, 50, 250}, {150, 50, 250}}, {z}).violations.empty());
        const AirspaceReport under15 = check(plane, {{-50, 50, 85}, {150, 50, 85}}, {z});
        QVERIFY(under15.violations.empty());
        QCOMPARE(under15.warnings.size(), size_t(1));
        QVERIFY(near(under15.warnings.front().clearance, 15));

        const AirspaceReport climb = check(plane, {{-50, 50, 50}, {150, 50, 150}}, {z});
        QCOMPARE(climb.violations.size(), size_t(1));
        QVERIFY(near(climb.violations.front().fromDistance, 100) && near(climb.violations.front().toDistance, 150));
        const AirspaceReport descent = check(plane, {{-50, 50, 300}, {150, 50, 100}}, {z});
        QCOMPARE(descent.violations.size(), size_t(1));
        QVERIFY(near(descent.violations.front().fromDistance, 100) && near(descent.violations.front().toDistance, 150));
        const QString message = violationMessage(descent.violations.front(), z);
        QVERIFY2(message == QStringLiteral("Leg 1 enters 'square' from 100 m to 150 m (floor 100 m AMSL, ceiling 200 m AMSL)."),
                 qPrintable(message));
    }

    // A circle of 100 m at the origin; the line y = 50 crosses it at x = ±√(100² - 50²) = ±86.603.
    void aCircle()
    {
        const LocalTangentPlane plane(kOrigin);
        Zone z;
        z.name = QStringLiteral("circle");
        z.shape = ZoneCircle{kOrigin, 100};
        const AirspaceReport r = check(plane, {{-200, 50, 30}, {200, 50, 30}}, {z});
        QCOMPARE(r.violations.size(), size_t(1));
        const double h = std::sqrt(100.0 * 100 - 50 * 50);
        QVERIFY2(near(r.violations.front().fromDistance, 200 - h) && near(r.violations.front().toDistance, 200 + h),
                 qPrintable(QStringLiteral("%1 %2").arg(r.violations.front().fromDistance).arg(r.violations.front().toDistance)));
        QVERIFY(check(plane, {{-200, 110, 30}, {200, 110, 30}}, {z}).violations.empty());
        QCOMPARE(check(plane, {{-200, 110, 30}, {200, 110, 30}}, {z}).warnings.size(), size_t(1));
    }

    // A cone frustum: radius 50 m at its floor (0 m AMSL), 150 m at its ceiling (100 m): r = 50 + h.
    // Level at 50 m (r = 100) along y = 0 from x = -300: inside from 200 to 400 m. Climbing from 0
    // to 100 m over 600 m (h = d/6): inside while |d - 300| <= 50 + d/6, from 1500/7 to 420 m.
    void aConeFrustum()
    {
        const LocalTangentPlane plane(kOrigin);
        Zone z;
        z.name = QStringLiteral("cone");
        z.shape = ZoneConeFrustum{kOrigin, 50, 150};
        z.floor = HeightLimit{0, HeightReference::Amsl};
        z.ceiling = HeightLimit{100, HeightReference::Amsl};
        const AirspaceReport level = check(plane, {{-300, 0, 50}, {300, 0, 50}}, {z});
        QCOMPARE(level.violations.size(), size_t(1));
        QVERIFY(near(level.violations.front().fromDistance, 200) && near(level.violations.front().toDistance, 400));
        QVERIFY(check(plane, {{-300, 0, 150}, {300, 0, 150}}, {z}).violations.empty());
        const AirspaceReport climb = check(plane, {{-300, 0, 0}, {300, 0, 100}}, {z});
        QCOMPARE(climb.violations.size(), size_t(1));
        QVERIFY2(near(climb.violations.front().fromDistance, 1500.0 / 7) && near(climb.violations.front().toDistance, 420),
                 qPrintable(QStringLiteral("%1 %2").arg(climb.violations.front().fromDistance).arg(climb.violations.front().toDistance)));
    }

    // 70°N: a zone given in degrees (69.99..70.01 N, 24.97..25.03 E) and a circle; legs along the
    // meridian, distances checked against WGS-84 geodesics (Vincenty), not the plane.
    void highLatitude()
    {
        const GeoPoint start{69.98, 25.0}, end{70.02, 25.0};
        Zone box;
        box.name = QStringLiteral("box");
        box.shape = ZonePolygons{{ZonePolygon{{{{69.99, 24.97}, {69.99, 25.03}, {70.01, 25.03}, {70.01, 24.97}}}}}};
        ProfileRoute route;
        for (const GeoPoint &p : {start, end}) {
            ProfileWaypoint w;
            w.position = p;
            w.altitude = 100;
            route.waypoints.push_back(w);
        }
        const AirspaceReport r = checkAirspace(flownPath(route, nullptr), {box});
        QCOMPARE(r.violations.size(), size_t(1));
        const double from = sortie::mission::geodesicDistance(start, {69.99, 25.0}), to = sortie::mission::geodesicDistance(start, {70.01, 25.0});
        QVERIFY2(near(r.violations.front().fromDistance, from, 0.5) && near(r.violations.front().toDistance, to, 0.5),
                 qPrintable(QStringLiteral("%1 %2 vs %3 %4").arg(r.violations.front().fromDistance).arg(r.violations.front().toDistance).arg(from).arg(to)));

        // A 300 m circle 100 m east of the meridian's centre: a chord of 2·√(300² - 100²).
        const GeoPoint centre = sortie::mission::geodesicDirect({70.0, 25.0}, 270, 100).point;
        Zone circle;
        circle.name = QStringLiteral("circle");
        circle.shape = ZoneCircle{centre, 300};
        const AirspaceReport c = checkAirspace(flownPath(route, nullptr), {circle});
        QCOMPARE(c.violations.size(), size_t(1));
        const double mid = sortie::mission::geodesicDistance(start, {70.0, 25.0}), half = std::sqrt(300.0 * 300 - 100 * 100);
        QVERIFY2(near(c.violations.front().fromDistance, mid - half, 0.5) && near(c.violations.front().toDistance, mid + half, 0.5),
                 qPrintable(QStringLiteral("%1 %2").arg(c.violations.front().fromDistance).arg(c.violations.front().toDistance)));
    }

    // Leaving an inclusion zone is a violation from where the leg crosses its edge.
    void leavingAnInclusionZone()
    {
        const LocalTangentPlane plane(kOrigin);
        const Zone fence = square(plane, 0, 0, 100, 100, ZoneKind::Inclusion);
        const AirspaceReport r = check(plane, {{50, 50, 30}, {150, 50, 30}}, {fence});
        QCOMPARE(r.violations.size(), size_t(1));
        QCOMPARE(r.violations.front().kind, ViolationKind::OutsideInclusion);
        QVERIFY(near(r.violations.front().fromDistance, 50) && near(r.violations.front().toDistance, 100));
        const AirspaceReport inside = check(plane, {{50, 50, 30}, {90, 50, 30}}, {fence});
        QVERIFY(inside.violations.empty());
        QCOMPARE(inside.warnings.size(), size_t(1));  // 10 m from the edge
        QVERIFY(near(inside.warnings.front().clearance, 10));
        // Two inclusion zones side by side are one permitted area.
        const AirspaceReport both = check(plane, {{50, 50, 30}, {150, 50, 30}}, {fence, square(plane, 100, 0, 200, 100, ZoneKind::Inclusion)});
        QVERIFY(both.violations.empty());
    }

    // The take-off climb is flown: at 60 m AGL a leg passes over a 20..40 m AGL zone, but the climb
    // from the ground at the first point goes through it (at 0 m along the route).
    void theTakeoffClimbAndLandingDescent()
    {
        const LocalTangentPlane plane(kOrigin);
        Zone z = square(plane, 0, 0, 100, 100);
        z.floor = HeightLimit{20, HeightReference::AboveTerrain};
        z.ceiling = HeightLimit{40, HeightReference::AboveTerrain};
        const auto agl = HeightReference::AboveTerrain;
        QVERIFY(check(plane, {{50, 50, 60, agl}, {300, 50, 60, agl}}, {z}).violations.empty());
        const AirspaceReport up = check(plane, {{50, 50, 60, agl, WaypointRole::Takeoff}, {300, 50, 60, agl}}, {z});
        QCOMPARE(up.violations.size(), size_t(1));
        QCOMPARE(up.violations.front().leg, 1);
        QVERIFY(near(up.violations.front().fromDistance, 0) && near(up.violations.front().toDistance, 0));
        const AirspaceReport down = check(plane, {{300, 50, 60, agl}, {50, 50, 60, agl, WaypointRole::Land}}, {z});
        QCOMPARE(down.violations.size(), size_t(1));
        QVERIFY(near(down.violations.front().fromDistance, 250) && near(down.violations.front().toDistance, 250));
    }

    // An AGL route without terrain data has no AMSL height: inside an AMSL zone's shadow it counts
    // as inside, and says why.
    void anUnknownHeightCountsAsInside()
    {
        const LocalTangentPlane plane(kOrigin);
        Zone z = square(plane, 0, 0, 100, 100);
        z.floor = HeightLimit{500, HeightReference::Amsl};
        const AirspaceReport r = check(plane, {{-50, 50, 60, HeightReference::AboveTerrain}, {150, 50, 60, HeightReference::AboveTerrain}}, {z});
        QCOMPARE(r.violations.size(), size_t(1));
        QVERIFY(r.violations.front().heightUnknown);
        QVERIFY(violationMessage(r.violations.front(), z).contains(QStringLiteral("unknown")));
        // Inside an inclusion zone with an AMSL ceiling, the same route may be above it: outside.
        Zone fence = square(plane, -100, 0, 200, 100, ZoneKind::Inclusion);
        fence.ceiling = HeightLimit{300, HeightReference::Amsl};
        const AirspaceReport f = check(plane, {{-50, 50, 60, HeightReference::AboveTerrain}, {150, 50, 60, HeightReference::AboveTerrain}}, {fence});
        QCOMPARE(f.violations.size(), size_t(1));
        QCOMPARE(f.violations.front().kind, ViolationKind::OutsideInclusion);
        QVERIFY(f.violations.front().heightUnknown);
        QVERIFY(near(f.violations.front().fromDistance, 0) && near(f.violations.front().toDistance, 200));
    }

    // Moving one waypoint re-checks its two legs only, and finds what a fresh check finds.
    void recheckingAfterAnEdit()
    {
        const LocalTangentPlane plane(kOrigin);
        std::vector<At> points;
        for (int i = 0; i < 50; ++i)
            points.push_back({i * 40.0 - 1000, (i % 2) * 40.0, 100});
        const std::vector<Zone> zones{square(plane, 0, -50, 100, 10)};
        AirspaceChecker checker(std::make_shared<const ZoneSet>(zones));
        const AirspaceReport first = checker.check(flownPath(routeThrough(plane, points), nullptr, {}, &plane));
        QCOMPARE(checker.legsCheckedLastTime(), 49);
        points[10].y += 500;
        const FlownPath edited = flownPath(routeThrough(plane, points), nullptr, {}, &plane);
        const AirspaceReport again = checker.check(edited);
        QCOMPARE(checker.legsCheckedLastTime(), 2);
        const AirspaceReport fresh = checkAirspace(edited, zones);
        QCOMPARE(again.violations.size(), fresh.violations.size());
        QVERIFY(!fresh.violations.empty());
        for (size_t i = 0; i < fresh.violations.size(); ++i) {
            QCOMPARE(again.violations[i].leg, fresh.violations[i].leg);
            QVERIFY(near(again.violations[i].fromDistance, fresh.violations[i].fromDistance, 1e-9));
        }
        QCOMPARE(first.violations.size(), fresh.violations.size());
        // A waypoint inserted: its two new legs are checked, the rest are found one place on.
        points.insert(points.begin() + 20, At{-200, 300, 100});
        checker.check(flownPath(routeThrough(plane, points), nullptr, {}, &plane));
        QCOMPARE(checker.legsCheckedLastTime(), 2);
    }

    // The rule on a route: the leg into the zone is an error on the row it ends at, and the gate
    // refuses to release the route; the flight home (the leg after the last) is checked too.
    void theRuleBlocksRelease()
    {
        using namespace sortie::mission;
        const LocalTangentPlane plane(kOrigin);
        Route route;
        route.settings.name = QStringLiteral("r");
        for (const double x : {-300.0, -100.0, -50.0}) {
            Waypoint w;
            w.position = plane.unproject({x, 50});
            w.altitude = 40;
            route.segments.push_back(w);
        }
        std::get<Waypoint>(route.segments[2]).position = plane.unproject({250, 50});
        AirspaceRule rule;
        rule.setZones(std::make_shared<const ZoneSet>(std::vector<Zone>{square(plane, 0, 0, 100, 100)}));
        std::vector<ValidationIssue> issues;
        rule.check(route, nullptr, issues);
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues.front().rule, QStringLiteral("airspace-exclusion"));
        QCOMPARE(issues.front().severity, Severity::Error);
        QCOMPARE(issues.front().segment, 2);
        QVERIFY2(issues.front().message.startsWith(QStringLiteral("Leg 2 enters 'square' from 300 m to 400 m")), qPrintable(issues.front().message));
        ValidationReport report;
        report.issues = issues;
        QVERIFY(!permitRelease(report, ValidationOverride::None, QStringLiteral("route")).ok());

        // Ending at x = -100 and flying home to x = 250: the flight home (leg 3) crosses the square.
        route.segments.pop_back();
        route.settings.home = HomePosition{plane.unproject({250, 50}), 0};
        route.settings.endAction = EndAction::ReturnHome;
        const AirspaceReport home = checkAirspace(flownPath(route, nullptr, nullptr, &plane), {square(plane, 0, 0, 100, 100)});
        QCOMPARE(home.violations.size(), size_t(1));
        QCOMPARE(home.violations.front().leg, 2);
        QCOMPARE(home.violations.front().row, -1);
        QVERIFY(near(home.violations.front().fromDistance, 300) && near(home.violations.front().toDistance, 400));
    }
};

QTEST_GUILESS_MAIN(TstAirspaceGeometry)
#include "tst_airspacegeometry.moc"
