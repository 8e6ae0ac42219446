// The simulator's route processing, on its own: distances and times per segment, the validation
// messages with the failing segment marked, and the flight plan an uploaded route becomes.
#include "Messages.pb.h"
#include "SimRouteProcessor.h"

#include <QtTest>

#include <cmath>

using sortie::sim::SimRouteLimits;
using sortie::sim::SimRouteProcessor;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;
constexpr double kGround = 10;

pb::SegmentDefinition point(double latDeg, double lonDeg, double altitude, const char *speed = nullptr,
                            pb::AltitudeType type = pb::AT_AGL)
{
    pb::SegmentDefinition s;
    s.set_algorithmclassname(SimRouteProcessor::kWaypointAlgorithm);
    s.set_uuid("seg-" + std::to_string(int(latDeg * 1e4)));
    s.mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(latDeg * kRad);
    p->set_longitude(lonDeg * kRad);
    if (type == pb::AT_AGL)
        p->set_aglaltitude(altitude);
    else
        p->set_wgs84altitude(altitude);
    p->set_altitudetype(type);
    if (speed) {
        auto *v = s.add_parametervalues();
        v->set_name("speed");
        v->set_value(speed);
    }
    return s;
}

// Two points 0.001 degrees of latitude apart: 111.2 m on the sphere.
pb::Route twoPoints(double secondAltitude = 50, const char *speed = "5.0")
{
    pb::Route r;
    r.set_id(7);
    r.set_version(3);
    r.set_initialspeed(4);
    *r.add_segments() = point(56.976, 24.073, 50);
    *r.add_segments() = point(56.977, 24.073, secondAltitude, speed);
    return r;
}

QString firstMessage(const pb::ProcessedSegment &s)
{
    return s.messageset().messages_size() ? QString::fromStdString(s.messageset().messages(0).defaulttext()) : QString();
}

} // namespace

class TestSimRouteProcessor : public QObject
{
    Q_OBJECT

private slots:
    void estimatesDistanceAndTimePerSegment()
    {
        SimRouteLimits limits;
        limits.climbRate = 2;
        const auto out = SimRouteProcessor::process(twoPoints(60), limits, kGround);
        QCOMPARE(out.route().id(), 7);
        QCOMPARE(out.segments_size(), 2);
        QCOMPARE(out.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(out.segments(0).estimateddistance(), 0.0);
        QCOMPARE(out.segments(0).estimatedtime(), 50 / 2.0); // climb from the ground at 2 m/s
        QVERIFY(std::abs(out.segments(1).estimateddistance() - 111.2) < 0.5);
        // 111.2 m at 5 m/s (the segment's speed, not the route's initial 4), plus 10 m of climb at 2 m/s.
        QVERIFY(std::abs(out.segments(1).estimatedtime() - (out.segments(1).estimateddistance() / 5 + 5)) < 1e-9);
        QCOMPARE(out.estimateddistance(), out.segments(1).estimateddistance());

        const auto &actions = out.segments(1).segmentactions();
        QCOMPARE(actions.size(), 2);
        QCOMPARE(actions[0].speedchange().groundspeed(), 5.0);
        const auto &w = actions[1].waypoint();
        QCOMPARE(w.wgs84altitude(), kGround + 60);
        QCOMPARE(w.elevation(), kGround);
        QCOMPARE(w.altitudeframe(), pb::AF_AGL);
        QCOMPARE(out.segments(1).uuid(), std::string("seg-569770"));
    }

    void absoluteAltitudesAreTakenAboveTheGround()
    {
        pb::Route r;
        *r.add_segments() = point(56.976, 24.073, 70, nullptr, pb::AT_WGS84);
        const auto out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(0).segmentactions(1).waypoint().wgs84altitude(), 70.0);
        QCOMPARE(out.segments(0).segmentactions(1).waypoint().altitudeframe(), pb::AF_WGS84);
        QCOMPARE(out.segments(0).segmentactions(0).speedchange().groundspeed(), 5.0); // default speed
    }

    void altitudeAboveTheRouteMaximumMarksTheSegment()
    {
        pb::Route r = twoPoints(130);
        r.set_maxaltitude(120);
        const auto out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(out.segments(1).status(), pb::RPS_INVALID);
        QCOMPARE(out.segments(1).wrongpointnumber(), 0);
        QCOMPARE(out.segments(1).messageset().messages(0).severity(), pb::MS_ERROR);
        QCOMPARE(firstMessage(out.segments(1)), QStringLiteral("Segment 2 (Waypoint): Altitude 130.0 m is above the route's maximum altitude of 120.0 m"));
        QCOMPARE(out.segments(1).segmentactions_size(), 0);
    }

    void profileLimitsAreChecked()
    {
        pb::VehicleProfile profile;
        for (auto [type, value] : {std::pair{pb::VPT_MAX_HORIZONTAL_SPEED, 8.0}, {pb::VPT_MAX_ALTITUDE_AGL, 100.0}}) {
            auto *p = profile.add_parameters();
            p->set_type(type);
            p->set_value(value);
        }
        const auto limits = SimRouteLimits::of(profile);
        auto out = SimRouteProcessor::process(twoPoints(50, "12"), limits, kGround);
        QCOMPARE(out.segments(1).status(), pb::RPS_INVALID);
        QCOMPARE(firstMessage(out.segments(1)), QStringLiteral("Segment 2 (Waypoint): Speed 12.0 m/s is above the vehicle profile's limit of 8.0 m/s"));
        out = SimRouteProcessor::process(twoPoints(101), limits, kGround);
        QCOMPARE(firstMessage(out.segments(1)), QStringLiteral("Segment 2 (Waypoint): Altitude 101.0 m AGL is above the vehicle profile's limit of 100.0 m"));
        pb::Route fast = twoPoints(50, "9");
        fast.set_maxspeed(8.5);
        out = SimRouteProcessor::process(fast, {}, kGround);
        QCOMPARE(firstMessage(out.segments(1)), QStringLiteral("Segment 2 (Waypoint): Speed 9.0 m/s is above the route's maximum speed of 8.5 m/s"));
    }

    void softProblemsAreWarningsAndHardOnesErrors()
    {
        pb::Route r = twoPoints(15);
        r.set_safealtitude(20);
        auto out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(1).status(), pb::RPS_PROCESSED);
        QCOMPARE(out.segments(1).messageset().messages(0).severity(), pb::MS_WARNING);

        r = twoPoints(50, "fast");
        out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(1).status(), pb::RPS_INVALID);
        QVERIFY(firstMessage(out.segments(1)).contains(QLatin1String("'fast'")));

        r = twoPoints();
        r.mutable_segments(1)->set_algorithmclassname("com.example.routing.SpiralAlgorithm");
        out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(1).status(), pb::RPS_INVALID);
        QCOMPARE(firstMessage(out.segments(1)),
                 QStringLiteral("Segment 2 (SpiralAlgorithm): the simulator has no algorithm 'com.example.routing.SpiralAlgorithm'"));

        r = twoPoints();
        r.mutable_segments(0)->mutable_figure()->clear_points();
        out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(firstMessage(out.segments(0)), QStringLiteral("Segment 1 (Waypoint): The segment has no point"));

        r = twoPoints(-5);
        out = SimRouteProcessor::process(r, {}, kGround);
        QVERIFY(firstMessage(out.segments(1)).contains(QLatin1String("below the ground")));
    }

    void actionsFollowTheirWaypoint()
    {
        pb::Route r = twoPoints();
        r.mutable_segments(1)->add_actiondefinitions()->mutable_waitdefinition()->set_interval(5);
        r.mutable_segments(1)->add_actiondefinitions()->mutable_cameraseriesbydistancedefinition()->set_interval(20);
        const auto plain = SimRouteProcessor::process(twoPoints(), {}, kGround);
        const auto out = SimRouteProcessor::process(r, {}, kGround);
        QCOMPARE(out.segments(1).segmentactions_size(), 4);
        QCOMPARE(out.segments(1).segmentactions(2).wait().interval(), 5.0);
        QCOMPARE(out.segments(1).segmentactions(3).cameraseriesbydistance().interval(), 20.0);
        QCOMPARE(out.segments(1).estimatedtime(), plain.segments(1).estimatedtime() + 5);
    }

    void serversActionsComeBackAsTheirActions()
    {
        // A servo, lidar, drop and a gimbal go through as the Action of the same name, fields by name;
        // a POI above the ground has no processed form here and is said to be kept, not performed.
        pb::Route r = twoPoints();
        auto *servo = r.mutable_segments(1)->add_actiondefinitions()->mutable_repeatservodefinition();
        servo->set_servoid(4);
        servo->set_pwm(1800);
        servo->set_delay(1.5);
        servo->set_count(3);
        r.mutable_segments(1)->add_actiondefinitions()->mutable_lidarrecordingcontroldefinition()->set_targetstate(pb::RS_ON);
        r.mutable_segments(1)->add_actiondefinitions()->mutable_dropdefinition();
        r.mutable_segments(1)->add_actiondefinitions()->mutable_cameracontroldefinition()->set_tilt(1.5);
        auto *poi = r.mutable_segments(1)->add_actiondefinitions()->mutable_poidefinition();
        poi->set_latitude(1);
        poi->set_aglaltitude(10);
        const auto out = SimRouteProcessor::process(r, {}, kGround);
        const auto &actions = out.segments(1).segmentactions();
        QCOMPARE(actions.size(), 2 + 4);
        QCOMPARE(actions[2].repeatservo().servoid(), 4);
        QCOMPARE(actions[2].repeatservo().pwm(), 1800);
        QCOMPARE(actions[2].repeatservo().delay(), 1.5);
        QCOMPARE(actions[2].repeatservo().count(), 3);
        QCOMPARE(actions[3].lidarrecordingcontrol().targetstate(), pb::RS_ON);
        QVERIFY(actions[4].has_drop());
        QCOMPARE(actions[5].cameracontrol().tilt(), 1.5);
        QVERIFY(!actions[5].cameracontrol().has_roll());
        QCOMPARE(firstMessage(out.segments(1)), QStringLiteral("The simulator keeps this action in the route but does not perform it"));
    }

    void hashFollowsTheRoute()
    {
        const auto a = SimRouteProcessor::hash(twoPoints());
        QCOMPARE(a.size(), size_t(32));
        QCOMPARE(SimRouteProcessor::hash(twoPoints()), a);
        QVERIFY(SimRouteProcessor::hash(twoPoints(51)) != a);
    }

    void anUploadedRouteBecomesAFlightPlan()
    {
        const auto processed = SimRouteProcessor::process(twoPoints(60), {}, kGround);
        QString error;
        const auto plan = SimRouteProcessor::flightPlan(processed, kGround, &error);
        QVERIFY(error.isEmpty());
        QCOMPARE(plan.size(), size_t(2));
        QVERIFY(std::abs(plan[1].latitude - 56.977) < 1e-9);
        QCOMPARE(plan[1].altitudeAgl, 60.0);
        QCOMPARE(plan[1].speed, 5.0);
        QCOMPARE(plan[0].speed, 4.0); // the route's initial speed where the segment names none

        pb::Route bad = twoPoints(50);
        bad.set_maxaltitude(20);
        QVERIFY(SimRouteProcessor::flightPlan(SimRouteProcessor::process(bad, {}, kGround), kGround, &error).empty());
        QCOMPARE(error, QStringLiteral("Segment 1 of the route was not processed successfully; fix it and process the route again"));
    }
};

QTEST_APPLESS_MAIN(TestSimRouteProcessor)
#include "tst_simrouteprocessor.moc"
