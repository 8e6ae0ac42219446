// Resuming a mission stopped half-way (core/resume): where the rest starts, what the camera does
// there, how the vehicle gets there, and what cannot be resumed.
#include "ResumeRoute.h"
#include "ResumeTestRoute.h"

#include "Geodesy.h"
#include "SegmentWaypoints.h"

#include <QtTest>

using namespace sortie;
using namespace sortie::mission;

namespace {

// Where a series by distance takes its photos along a path of waypoints, as an autopilot's trigger
// does: one at the first point, then one every `interval` metres flown.
std::vector<GeoPoint> photosAlong(const std::vector<GeoPoint> &path, double interval)
{
    std::vector<GeoPoint> photos{path.front()};
    double sinceLast = 0;
    for (size_t i = 0; i + 1 < path.size(); ++i) {
        const auto leg = geodesicInverse(path[i], path[i + 1]);
        double at = 0;
        while (at + (interval - sinceLast) <= leg->distance) {
            at += interval - sinceLast;
            sinceLast = 0;
            photos.push_back(geodesicDirect(path[i], leg->azimuth1Deg, at).point);
        }
        sinceLast += leg->distance - at;
    }
    return photos;
}

std::vector<GeoPoint> positions(const std::vector<Waypoint> &points)
{
    std::vector<GeoPoint> out;
    for (const Waypoint &w : points)
        out.push_back(w.position);
    return out;
}

std::vector<Waypoint> scanPoints(const Route &route, size_t row = 1)
{
    auto points = segmentWaypoints(route, row, route.segments[row - 1].index() == 0 ? std::optional(anchorOf(route.segments[row - 1])) : std::nullopt);
    return points ? *points : std::vector<Waypoint>{};
}

double triggerOf(const std::vector<Waypoint> &scan)
{
    return std::get<CameraSeriesByDistanceAction>(scan.front().actions.front()).intervalMeters;
}

} // namespace

class TestResume : public QObject
{
    Q_OBJECT

private slots:
    // Stopped after a photo half-way through the scan: the rest starts where the next photo was due,
    // with the series on, so the photos of both flights are the ones one flight would have taken.
    void resumesWhereTheNextPhotoWasDue()
    {
        const Route route = test::resumeTestRoute();
        const std::vector<Waypoint> scan = scanPoints(route);
        QVERIFY(scan.size() > 8);
        const double trigger = triggerOf(scan);
        QVERIFY(trigger > 5);
        const std::vector<GeoPoint> uninterrupted = photosAlong(positions(scan), trigger);
        const size_t last = uninterrupted.size() / 2;

        resume::ResumeRequest request;
        request.lastPhoto = uninterrupted[last];
        request.takeoff = test::kResumeHome;
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY2(plan, qPrintable(plan ? QString() : plan.error().message));
        QCOMPARE(plan->resumedRow, 1);
        QVERIFY2(geodesicDistance(plan->resumeAt, uninterrupted[last + 1]) < 0.05,
                 qPrintable(QString::number(geodesicDistance(plan->resumeAt, uninterrupted[last + 1]))));
        QVERIFY(plan->offPath < 0.01);

        const std::vector<Segment> &segments = plan->route.segments;
        const Waypoint *takeoff = asWaypoint(segments.front());
        QVERIFY(takeoff);
        QCOMPARE(takeoff->role, WaypointRole::Takeoff);
        QCOMPARE(takeoff->position, test::kResumeHome);
        QCOMPARE(takeoff->altitude, 60.0);  // the scan's height is above the route's safe 30 m: no climb over
        const Waypoint *resumed = asWaypoint(segments[1]);
        QVERIFY(resumed);
        QCOMPARE(resumed->position, plan->resumeAt);
        QCOMPARE(resumed->altitude, 60.0);
        QCOMPARE(resumed->actions.size(), size_t(1));
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(resumed->actions.front()).intervalMeters, trigger);
        // The rest of the scan as its waypoints, the series stopped at its last; the landing as it was.
        QCOMPARE(segments.back(), route.segments.back());
        std::vector<Waypoint> rest;
        for (size_t i = 1; i + 1 < segments.size(); ++i)
            rest.push_back(*asWaypoint(segments[i]));
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(rest.back().actions.back()).intervalMeters, 0.0);
        QCOMPARE(rest.back().position, scan.back().position);

        // Flown, the resumed series takes exactly the photos the first flight did not.
        const std::vector<GeoPoint> second = photosAlong(positions(rest), trigger);
        QCOMPARE(second.size(), uninterrupted.size() - last - 1);
        for (size_t i = 0; i < second.size(); ++i)
            QVERIFY2(geodesicDistance(second[i], uninterrupted[last + 1 + i]) < 0.05, qPrintable(QString::number(i)));
        QVERIFY(plan->notes.join(u' ').contains(QStringLiteral("every %1 m").arg(trigger)));
        QCOMPARE(plan->route.settings.name, QStringLiteral("Field 7 (resumed)"));
    }

    // Stopped at a waypoint it reached: the rest starts there, the series on again at it.
    void resumesAtTheLastWaypointReached()
    {
        const Route route = test::resumeTestRoute();
        const std::vector<Waypoint> scan = scanPoints(route);
        resume::ResumeRequest request;
        request.from = resume::ResumeRequest::From::LastWaypoint;
        request.reached = {test::kResumeHome};
        for (size_t i = 0; i <= 4; ++i)
            request.reached.push_back(scan[i].position);
        request.takeoff = test::kResumeHome;
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY2(plan, qPrintable(plan ? QString() : plan.error().message));
        const Waypoint *resumed = asWaypoint(plan->route.segments[1]);
        QCOMPARE(resumed->position, scan[4].position);
        QCOMPARE(resumed->actions.size(), size_t(1));
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(resumed->actions.front()).intervalMeters, triggerOf(scan));
        QCOMPARE(asWaypoint(plan->route.segments[2])->position, scan[5].position);
        QCOMPARE(plan->route.segments.size(), size_t(2 + scan.size() - 5 + 1));
    }

    // Asked for a higher flight over, it climbs there first and goes down to the scan's height at the
    // resume point.
    void fliesOverAtTheTransitHeight()
    {
        const Route route = test::resumeTestRoute();
        const std::vector<Waypoint> scan = scanPoints(route);
        resume::ResumeRequest request;
        request.from = resume::ResumeRequest::From::LastWaypoint;
        request.reached = {test::kResumeHome, scan[0].position, scan[1].position, scan[2].position, scan[3].position};
        request.takeoff = test::kResumeHome;
        request.transitAltitude = 90;
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY(plan);
        QCOMPARE(asWaypoint(plan->route.segments[0])->altitude, 90.0);
        const Waypoint *over = asWaypoint(plan->route.segments[1]);
        QCOMPARE(over->position, scan[3].position);
        QCOMPARE(over->altitude, 90.0);
        QVERIFY(over->actions.empty());
        QCOMPARE(asWaypoint(plan->route.segments[2])->altitude, 60.0);
        QVERIFY(!asWaypoint(plan->route.segments[2])->actions.empty());
    }

    // A series by time, the gimbal and the heading set at an earlier waypoint are set again at the
    // resume point, a photo interval on at the leg's speed.
    void restoresTheCameraAsItWas()
    {
        const LocalTangentPlane plane(test::kResumeHome);
        Route route;
        route.settings.safeAltitude = 20;
        Waypoint a;
        a.position = test::kResumeHome;
        a.altitude = 40;
        a.speed = 5;
        a.role = WaypointRole::Takeoff;
        route.segments.emplace_back(a);
        Waypoint b = a;
        b.role = WaypointRole::Pass;
        b.position = plane.unproject({100, 0});
        CameraControlAction tilt;
        tilt.tiltDeg = 45;
        HeadingAction heading;
        heading.headingDeg = 120;
        CameraSeriesByTimeAction every2s;
        every2s.intervalSeconds = 2;
        b.actions = {tilt, heading, every2s};
        route.segments.emplace_back(b);
        Waypoint c = b;
        c.position = plane.unproject({300, 0});
        c.actions = {CameraTriggerAction{TriggerState::StartRecording}};
        route.segments.emplace_back(c);
        Waypoint d = c;
        d.position = plane.unproject({500, 0});
        d.actions = {};
        route.segments.emplace_back(d);

        resume::ResumeRequest request;
        request.lastPhoto = plane.unproject({150, 0});
        request.takeoff = test::kResumeHome;
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY2(plan, qPrintable(plan ? QString() : plan.error().message));
        QCOMPARE(plan->resumedRow, 2);
        const PlanePoint at = plane.project(plan->resumeAt);
        QVERIFY2(std::abs(at.x - 160) < 0.01 && std::abs(at.y) < 0.01, qPrintable(QStringLiteral("%1 %2").arg(at.x).arg(at.y)));
        const Waypoint *resumed = asWaypoint(plan->route.segments[1]);
        QCOMPARE(resumed->altitude, 40.0);
        QCOMPARE(resumed->speed, 5.0);
        QCOMPARE(resumed->actions.size(), size_t(3));
        QCOMPARE(std::get<CameraControlAction>(resumed->actions[0]).tiltDeg, std::optional(45.0));
        QCOMPARE(std::get<HeadingAction>(resumed->actions[1]).headingDeg, 120.0);
        QCOMPARE(std::get<CameraSeriesByTimeAction>(resumed->actions[2]).intervalSeconds, 2.0);
        // Then c and d as they were: recording starts at c, as it did.
        QCOMPARE(plan->route.segments.size(), size_t(4));
        QCOMPARE(plan->route.segments[2], route.segments[2]);
        QCOMPARE(plan->route.segments[3], route.segments[3]);

        // Past c, the recording is on again at the resume point as well.
        request.lastPhoto = plane.unproject({350, 0});
        const auto later = resume::resumeRoute(route, request);
        QVERIFY(later);
        const Waypoint *again = asWaypoint(later->route.segments[1]);
        QVERIFY(std::find(again->actions.begin(), again->actions.end(), WaypointAction{CameraTriggerAction{TriggerState::StartRecording}})
                != again->actions.end());
    }

    // Landed at a planned battery change (a landing waypoint), it goes on through that point.
    void goesOnThroughTheLandingThatEndedTheFlight()
    {
        const LocalTangentPlane plane(test::kResumeHome);
        Route route;
        for (int i = 0; i < 5; ++i) {
            Waypoint w;
            w.position = plane.unproject({200.0 * i, 0});
            w.altitude = 40;
            w.role = i == 0 ? WaypointRole::Takeoff : i == 2 || i == 4 ? WaypointRole::Land : WaypointRole::Pass;
            route.segments.emplace_back(w);
        }
        resume::ResumeRequest request;
        request.from = resume::ResumeRequest::From::LastWaypoint;
        request.takeoff = asWaypoint(route.segments[2])->position;
        request.reached = {anchorOf(route.segments[0]), anchorOf(route.segments[1]), anchorOf(route.segments[2])};
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY2(plan, qPrintable(plan ? QString() : plan.error().message));
        QCOMPARE(plan->resumedRow, 2);
        QCOMPARE(plan->route.segments.size(), size_t(4)); // take-off there, waypoint 3 flown through, 4, the landing at 5
        QCOMPARE(asWaypoint(plan->route.segments[1])->role, WaypointRole::Pass);
        QCOMPARE(asWaypoint(plan->route.segments.back())->role, WaypointRole::Land);
    }

    void refusesWhatItCannotResume()
    {
        const Route route = test::resumeTestRoute();
        resume::ResumeRequest request;
        request.takeoff = test::kResumeHome;
        const LocalTangentPlane plane(test::kResumeHome);

        request.lastPhoto = plane.unproject({150, 800});
        auto plan = resume::resumeRoute(route, request);
        QVERIFY(!plan);
        QVERIFY2(plan.error().message.contains(QLatin1String("not this route's flight")), qPrintable(plan.error().message));
        request.lastPhoto = GeoPoint{qQNaN(), qQNaN()};
        QVERIFY(!resume::resumeRoute(route, request));

        // Home is the path's first point and its last: reached in order, it is the last.
        request.from = resume::ResumeRequest::From::LastWaypoint;
        request.reached = {test::kResumeHome};
        QVERIFY(resume::resumeRoute(route, request));
        for (const Waypoint &w : scanPoints(route))
            request.reached.push_back(w.position);
        request.reached.push_back(test::kResumeHome);
        plan = resume::resumeRoute(route, request);
        QVERIFY(!plan);
        QVERIFY2(plan.error().message.contains(QLatin1String("nothing is left")), qPrintable(plan.error().message));
        request.reached = {plane.unproject({150, 800})};
        plan = resume::resumeRoute(route, request);
        QVERIFY(!plan);
        QVERIFY2(plan.error().message.contains(QLatin1String("not this route's flight")), qPrintable(plan.error().message));

        Route unknown = route;
        AlgorithmSegment spiral;
        spiral.algorithm = QStringLiteral("com.example.SpiralAlgorithm");
        unknown.segments.insert(unknown.segments.begin() + 2, spiral);
        request.from = resume::ResumeRequest::From::LastPhoto;
        request.lastPhoto = anchorOf(route.segments[1]);
        plan = resume::resumeRoute(unknown, request);
        QVERIFY(!plan);
        QVERIFY2(plan.error().message.contains(QLatin1String("3 cannot be resumed here")), qPrintable(plan.error().message));
    }
};

QTEST_GUILESS_MAIN(TestResume)
#include "tst_resume.moc"
