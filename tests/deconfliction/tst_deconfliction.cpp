// Deconfliction of routes on a common clock against hand-worked crossings, the motion pieces
// against the time model's positionAt, and the search against dense sampling of random flights.
// Routes are laid out in metres east (x) and north (y) of one origin (DeconflictionSamples.h);
// every timeline here has no acceleration, so a leg of d metres at v m/s takes d/v seconds.
#include "ConflictSearch.h"
#include "DeconflictionSamples.h"
#include "Near.h"

#include <QRandomGenerator>
#include <QtTest>

using namespace sortie::deconfliction;
using namespace sortie::mission;
using namespace sortie::test;

namespace {
ScheduledFlight flight(const std::vector<Leg> &points, double start = 0.0)
{
    ScheduledFlight f;
    f.timeline = lineTimeline(points);
    f.start = start;
    return f;
}

// West to east through the origin, 2000 m at 10 m/s: at (−1000 + 10t, 0), over the origin at 100 s.
const std::vector<Leg> kEastbound{{-1000, 0}, {1000, 0}};
// South to north, the same: at (0, −1000 + 10t).
const std::vector<Leg> kNorthbound{{0, -1000}, {0, 1000}};

PlanePoint onPlane(const GeoPoint &p)
{
    return samplePlane().project(p);
}
} // namespace

class TstDeconfliction : public QObject
{
    Q_OBJECT
private slots:
    // Head-on on one line, both from t = 0 at 10 m/s, 1000 m apart: closing at 20 m/s, under 20 m
    // while |1000 − 20t| < 20, t in (49, 51); they meet over the origin at t = 50.
    void headOnAtTheSameTime()
    {
        const ConflictReport r = findConflicts({flight({{-500, 0}, {500, 0}}), flight({{500, 0}, {-500, 0}})});
        QCOMPARE(r.pairs, 1);
        QCOMPARE(r.conflicts.size(), size_t(1));
        const Conflict &c = r.conflicts.front();
        QCOMPARE(c.first, 0);
        QCOMPARE(c.second, 1);
        QNEAR(c.interval.begin, 49, 1e-3);
        QNEAR(c.interval.end, 51, 1e-3);
        QNEAR(c.time, 50, 1e-3);
        QNEAR(c.horizontal, 0, 1e-2);
        QNEAR(c.vertical, 0, 1e-9);
        QCOMPARE(c.firstAt.leg, 1);
        QCOMPARE(c.secondAt.leg, 1);
        QNEAR(onPlane(c.firstAt.position).x, 0, 1e-2);
        QNEAR(onPlane(c.secondAt.position).x, 0, 1e-2);
        QNEAR(c.firstAt.altitude, 50, 1e-9);
    }

    // Crossing at right angles, both from t = 0: b − a = (1000 − 10t, −1000 + 10t), so the distance
    // is √2·|1000 − 10t|, under 20 m for |1000 − 10t| < 10√2: t in (98.586, 101.414), 0 m at 100 s.
    void crossingAtTheSameTime()
    {
        const ConflictReport r = findConflicts({flight(kEastbound), flight(kNorthbound)});
        QCOMPARE(r.conflicts.size(), size_t(1));
        const Conflict &c = r.conflicts.front();
        QNEAR(c.interval.begin, 100 - std::sqrt(2.0), 1e-3);
        QNEAR(c.interval.end, 100 + std::sqrt(2.0), 1e-3);
        QNEAR(c.time, 100, 1e-3);
        QNEAR(c.horizontal, 0, 1e-2);
    }

    // The northbound vehicle a minute later: at (0, −1600 + 10t), so b − a = (1000 − 10t, 10t − 1600).
    // The distance squared, 200t² − 52000t + 3,560,000, is least at t = 130: (−300, −300), 424.26 m —
    // no conflict. With 500 m as the horizontal separation: (1000 − u)² + (u − 1600)² < 500² with
    // u = 10t gives u² − 2600u + 1,655,000 < 0, u = 1300 ± √140000 / 2: t in (111.292, 148.708).
    void theSameCrossingAMinuteApart()
    {
        const std::vector<ScheduledFlight> flights{flight(kEastbound), flight(kNorthbound, 60)};
        const ConflictReport r = findConflicts(flights);
        QCOMPARE(r.pairs, 1);
        QVERIFY(r.conflicts.empty());

        const ConflictReport wide = findConflicts(flights, {{500, 15}, {}});
        QCOMPARE(wide.conflicts.size(), size_t(1));
        const Conflict &c = wide.conflicts.front();
        QNEAR(c.interval.begin, 130 - std::sqrt(140000.0) / 20, 1e-3);
        QNEAR(c.interval.end, 130 + std::sqrt(140000.0) / 20, 1e-3);
        QNEAR(c.time, 130, 1e-3);
        QNEAR(c.horizontal, 300 * std::sqrt(2.0), 1e-2);
        const PlanePoint a = onPlane(c.firstAt.position), b = onPlane(c.secondAt.position);
        QNEAR(a.x, 300, 1e-2);
        QNEAR(a.y, 0, 1e-2);
        QNEAR(b.x, 0, 1e-2);
        QNEAR(b.y, -300, 1e-2);
    }

    // The same crossing at the same time with the northbound vehicle 14.9 m higher (64.9 m against
    // 50 m): a conflict, 14.9 m apart in height at the closest approach; 15.1 m higher: none.
    void verticalSeparationJustBelowAndAboveV()
    {
        const ConflictReport below = findConflicts({flight(kEastbound), flight({{0, -1000, 64.9}, {0, 1000, 64.9}})});
        QCOMPARE(below.conflicts.size(), size_t(1));
        QNEAR(below.conflicts.front().vertical, 14.9, 1e-9);
        QNEAR(below.conflicts.front().secondAt.altitude, 64.9, 1e-9);
        const ConflictReport above = findConflicts({flight(kEastbound), flight({{0, -1000, 65.1}, {0, 1000, 65.1}})});
        QVERIFY(above.conflicts.empty());
    }

    // Crossing at the same time while the northbound vehicle changes height evenly along its leg
    // (no climb rate: the command line's model). Climbing from 0 m to 100 m over its 200 s it is at
    // t/2 m, level with the eastbound one's 50 m over the origin at 100 s: 0 m apart both ways.
    // Descending from 110 m to 10 m it is at 110 − t/2: 60 m there, 10 m above: still a conflict.
    void climbingThroughTheOthersHeight()
    {
        const ConflictReport r = findConflicts({flight(kEastbound), flight({{0, -1000, 0}, {0, 1000, 100}})});
        QCOMPARE(r.conflicts.size(), size_t(1));
        QNEAR(r.conflicts.front().time, 100, 1e-3);
        QNEAR(r.conflicts.front().vertical, 0, 1e-6);
        const ConflictReport d = findConflicts({flight(kEastbound), flight({{0, -1000, 110}, {0, 1000, 10}})});
        QCOMPARE(d.conflicts.size(), size_t(1));
        QNEAR(d.conflicts.front().vertical, 10, 1e-6);
    }

    // A flying vehicle on the eastbound line with a waypoint at (−500, 0): leg 1 is 500 m (50 s), leg
    // 2 1500 m. 60 s of it are flown at the clock's 0, so it is at (−400 + 10t, 0), over the origin
    // at t = 40. A northbound vehicle from (0, −400) to (0, 400) starting at 0 is there too:
    // b − a = (400 − 10t, −400 + 10t), under 20 m for t in (38.586, 41.414), on legs 2 and 1.
    // Not flying (starting at 0 from its first point) it would reach the origin at 100 s, after
    // the other has landed: no conflict.
    void aFlyingVehiclePartWayAlongItsRoute()
    {
        const std::vector<Leg> route{{-1000, 0}, {-500, 0}, {1000, 0}};
        const ScheduledFlight other = flight({{0, -400}, {0, 400}});
        QVERIFY(findConflicts({flight(route), other}).conflicts.empty());

        ScheduledFlight flying = flight(route);
        flying.flown = 60;
        // Where the caller gets `flown` from: reported at (−400, 30) on leg 2 (index 1), the nearest
        // point of the leg is (−400, 0), 100 m of its 1500 m: 50 s + 100 / 1500 × 150 s = 60 s.
        QNEAR(flownAlongLeg(flying.timeline, 1, samplePlane().unproject({-400, 30})).value(), 60, 1e-3);
        QNEAR(flownAlongLeg(flying.timeline, 1, samplePlane().unproject({-900, 0})).value(), 50, 1e-3);  // before the leg: its start
        QVERIFY(!flownAlongLeg(flying.timeline, 2, {}));
        const ConflictReport r = findConflicts({flying, other});
        QCOMPARE(r.conflicts.size(), size_t(1));
        const Conflict &c = r.conflicts.front();
        QNEAR(c.interval.begin, 40 - std::sqrt(2.0), 1e-3);
        QNEAR(c.interval.end, 40 + std::sqrt(2.0), 1e-3);
        QNEAR(c.time, 40, 1e-3);
        QCOMPARE(c.firstAt.leg, 2);
        QCOMPARE(c.secondAt.leg, 1);

        // It reports itself 30 m north of its line at (−400, 30): it flies straight from there to
        // (1000, 0) in the 140 s left, velocity (10, −30/140). b − a = (400 − 10t, −430 + 10.2143t),
        // least at t = 41.071 (−10.712, −10.485): 14.991 m; under 20 m for t in (40.145, 41.997).
        flying.now = FlightPosition{samplePlane().unproject({-400, 30}), 50};
        const ConflictReport moved = findConflicts({flying, other});
        QCOMPARE(moved.conflicts.size(), size_t(1));
        const Conflict &m = moved.conflicts.front();
        QNEAR(m.interval.begin, 40.14501, 1e-3);
        QNEAR(m.interval.end, 41.99736, 1e-3);
        QNEAR(m.time, 41.07119, 1e-3);
        QNEAR(m.horizontal, 14.99082, 1e-2);
        QNEAR(onPlane(m.firstAt.position).x, 10.71188, 1e-2);
        QNEAR(onPlane(m.firstAt.position).y, 21.19903, 1e-2);
    }

    // A conflict across a waypoint is one conflict: the eastbound vehicle has a waypoint over the
    // origin (legs 1 and 2), the head-on one passes 5 m north of it at t = 50. The windows (49.1, 50)
    // and (50, 50.9) (|1000 − 20t| < √(20² − 5²) = 19.365) merge; the tie at the waypoint goes to
    // the earlier leg.
    void aConflictAcrossAWaypointIsOne()
    {
        const ConflictReport r = findConflicts({flight({{-500, 0}, {0, 0}, {500, 0}}), flight({{500, 5}, {-500, 5}})});
        QCOMPARE(r.conflicts.size(), size_t(1));
        const Conflict &c = r.conflicts.front();
        QNEAR(c.interval.begin, 50 - std::sqrt(375.0) / 20, 1e-3);
        QNEAR(c.interval.end, 50 + std::sqrt(375.0) / 20, 1e-3);
        QNEAR(c.horizontal, 5, 1e-2);
        QCOMPARE(c.firstAt.leg, 1);
    }

    // Against one flight only: three flights where 0 crosses 1, and 1 meets 2 head-on later; against
    // flight 0 there are two pairs and one conflict, all pairs three and two.
    void againstOneFlight()
    {
        const std::vector<ScheduledFlight> flights{flight(kEastbound), flight(kNorthbound), flight({{0, 1100}, {0, 0}})};
        const ConflictReport all = findConflicts(flights);
        QCOMPARE(all.pairs, 3);
        QCOMPARE(all.conflicts.size(), size_t(2));
        const ConflictReport one = findConflicts(flights, {{}, 0});
        QCOMPARE(one.pairs, 2);
        QCOMPARE(one.conflicts.size(), size_t(1));
        QCOMPARE(one.conflicts.front().second, 1);
        QCOMPARE(findConflicts(flights, {{}, 7}).pairs, 0);
    }

    // The pieces follow the time model: a take-off waypoint climbing at 2 m/s, a wait, a height
    // change slower than the leg, a landing at 1 m/s; positions agree with positionAt throughout.
    void piecesFollowTheTimeModel()
    {
        Route route = lineRoute({{0, 0, 30, 10}, {300, 0, 60, 10}, {300, 400, 20, 5}, {0, 400, 40, 8}});
        std::get<Waypoint>(route.segments[0]).role = WaypointRole::Takeoff;
        std::get<Waypoint>(route.segments[1]).actions = {WaitAction{12, false}};
        std::get<Waypoint>(route.segments[3]).role = WaypointRole::Land;
        TimingParameters p;
        p.cruiseSpeed = 10;
        p.climbRate = 2;
        p.descentRate = 1;
        ScheduledFlight f;
        f.timeline = timeRoute(route, p).value();
        f.start = 1000;
        const std::vector<MotionPiece> pieces = motionPieces(f, 0, samplePlane());
        QVERIFY(pieces.size() >= 8);
        QNEAR(pieces.front().begin, 1000, 1e-9);
        QNEAR(pieces.back().end, 1000 + f.timeline.totalSeconds(), 1e-9);
        size_t at = 0;
        for (double t = 0; t <= f.timeline.totalSeconds(); t += 0.25) {
            while (at + 1 < pieces.size() && pieces[at].end < 1000 + t)
                ++at;
            const TimelinePosition expected = f.timeline.positionAt(t);
            const LocalState got = pieces[at].stateAt(1000 + t);
            const PlanePoint e = samplePlane().project(expected.position);
            QNEAR(got.east, e.x, 0.05);
            QNEAR(got.north, e.y, 0.05);
            QNEAR(got.up, expected.altitude, 1e-6);
        }
    }

    // Random flights against dense sampling of positionAt (every 0.05 s): every sampled moment
    // clearly inside both separations lies in a reported conflict of that pair, and every reported
    // closest approach is, by positionAt, within the separation.
    void agreesWithSampling()
    {
        QRandomGenerator rng(24);
        TimingParameters p;
        p.cruiseSpeed = 10;
        p.climbRate = 3;
        p.descentRate = 2;
        std::vector<ScheduledFlight> flights;
        for (int i = 0; i < 6; ++i) {
            std::vector<Leg> points;
            for (int k = 0; k < 8; ++k)
                points.push_back({rng.bounded(400.0) - 200, rng.bounded(400.0) - 200, 40 + rng.bounded(30.0), 4 + rng.bounded(8.0)});
            ScheduledFlight f;
            f.timeline = timeRoute(lineRoute(points), p).value();
            f.start = rng.bounded(60.0);
            flights.push_back(f);
        }
        const ConflictReport r = findConflicts(flights);
        QVERIFY(!r.conflicts.empty());
        std::vector<PlanePoint> centres;
        std::vector<GeoPoint> froms;
        for (const ScheduledFlight &f : flights)
            for (const TimedLeg &l : f.timeline.legs())
                froms.push_back(l.from);
        const LocalTangentPlane plane(LocalTangentPlane::centroidOf(froms));
        const auto state = [&](int i, double t) {
            const ScheduledFlight &f = flights[size_t(i)];
            const TimelinePosition at = f.timeline.positionAt(t - f.start);
            const PlanePoint q = plane.project(at.position);
            return LocalState{q.x, q.y, at.altitude, 0, 0, 0};
        };
        const auto inAir = [&](int i, double t) { return t >= flights[size_t(i)].start && t <= flights[size_t(i)].start + flights[size_t(i)].timeline.totalSeconds(); };
        int sampledInside = 0;
        for (int i = 0; i < 6; ++i)
            for (int j = i + 1; j < 6; ++j)
                for (double t = 0; t < 400; t += 0.05) {
                    if (!inAir(i, t) || !inAir(j, t))
                        continue;
                    const LocalState a = state(i, t), b = state(j, t);
                    if (!(std::hypot(a.east - b.east, a.north - b.north) < 19.5 && std::abs(a.up - b.up) < 14.5))
                        continue;
                    ++sampledInside;
                    const bool reported = std::any_of(r.conflicts.begin(), r.conflicts.end(), [&](const Conflict &c) {
                        return c.first == i && c.second == j && t >= c.interval.begin - 1e-6 && t <= c.interval.end + 1e-6;
                    });
                    QVERIFY2(reported, qPrintable(QStringLiteral("flights %1 and %2 at %3 s").arg(i).arg(j).arg(t)));
                }
        QVERIFY(sampledInside > 0);
        for (const Conflict &c : r.conflicts) {
            const LocalState a = state(c.first, c.time), b = state(c.second, c.time);
            QNEAR(std::hypot(a.east - b.east, a.north - b.north), c.horizontal, 0.05);
            QNEAR(std::abs(a.up - b.up), c.vertical, 1e-6);
            QVERIFY(c.horizontal < 20 && c.vertical < 15);
        }
    }
};

QTEST_APPLESS_MAIN(TstDeconfliction)
#include "tst_deconfliction.moc"
