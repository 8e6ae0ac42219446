// Route <-> HCI, on frames the UgCS SDK produced (tests/data/hci-vectors): an unchanged route goes
// back byte for byte; a route edited in one waypoint sends every other field back exactly,
// unknown fields included; a new route encodes the way the SDK's sample builds one; the processed
// route becomes the plan the vehicle will fly.
#include "AlgorithmCatalog.h"
#include "TestData.h"
#include "AreaScanPlanner.h"
#include "Domain.pb.h"
#include "FlightPath.h"
#include "CameraProto.h"
#include "HciActionMapper.h"
#include "HciRouteMapper.h"
#include "ProcessedPlan.h"
#include "HciText.h"
#include "Messages.pb.h"
#include "RouteValidator.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentParameters.h"

#include <google/protobuf/util/field_comparator.h>
#include <google/protobuf/util/message_differencer.h>

#include <QFile>
#include <QUndoStack>
#include <QtTest>

#include <limits>
#include <numbers>

using namespace sortie::mission;
namespace pb = com::ugcs::ucs::proto;
namespace gpu = google::protobuf::util;

namespace {
template<typename Message>
Message payloadOf(const char *file)
{
    QFile f((QString::fromUtf8(sortieTestData()) + QStringLiteral("/hci-vectors/")) + QLatin1String(file));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("missing vector %s", file);
    const QByteArray frame = f.readAll();
    Message m;
    if (!m.ParseFromArray(frame.constData() + 16, int(frame.size() - 16)))
        qFatal("vector %s does not parse", file);
    return m;
}

pb::Route storedRoute() { return payloadOf<pb::GetObjectResponse>("016-GetObjectResponse.bin").object().route(); }
pb::Route savedRoute() { return payloadOf<pb::CreateOrUpdateObjectResponse>("020-CreateOrUpdateObjectResponse.bin").object().route(); }

Route imported(const pb::Route &r)
{
    Result<HciRouteImport> i = routeFromHci(r);
    if (!i)
        qFatal("%s", qPrintable(i.error().toString()));
    return i->route;
}

QString differences(const google::protobuf::Message &a, const google::protobuf::Message &b, bool approximate = false)
{
    std::string report;
    gpu::DefaultFieldComparator cmp;
    if (approximate) {
        cmp.set_float_comparison(gpu::DefaultFieldComparator::APPROXIMATE);
        cmp.SetDefaultFractionAndMargin(1e-14, 1e-12);
    }
    gpu::MessageDifferencer d;
    d.set_field_comparator(&cmp);
    d.ReportDifferencesToString(&report);
    return d.Compare(a, b) ? QString() : QString::fromStdString(report);
}

constexpr double kDeg = std::numbers::pi / 180.0;

const pb::ParameterValue *findValue(const pb::SegmentDefinition &s, const char *name)
{
    for (const auto &v : s.parametervalues())
        if (v.name() == name)
            return &v;
    return nullptr;
}
}

class TestHciMapping : public QObject
{
    Q_OBJECT
private slots:
    void decodesTheSdkRoute()
    {
        const Route r = imported(storedRoute());
        QCOMPARE(r.settings.name, QStringLiteral("Route A"));
        QCOMPARE(r.settings.safeAltitude, 50.0);
        QCOMPARE(r.settings.maxSpeed, 10.0);
        QCOMPARE(int(r.settings.failsafes.size()), 2);
        QCOMPARE(r.settings.failsafes[1].action, FailsafeAction::Land);
        QCOMPARE(int(r.segments.size()), 2);
        const auto &w = std::get<Waypoint>(r.segments[0]);
        QCOMPARE(w.position.latitude, 0.994160485886994 / kDeg);
        QCOMPARE(w.altitude, 60.0);
        QCOMPARE(w.altitudeType, AltitudeType::Agl);
        QCOMPARE(w.speed, 6.0);
        QCOMPARE(w.turnType, TurnType::StopAndTurn);

        const Route saved = imported(savedRoute());
        const auto &w3 = std::get<Waypoint>(saved.segments[2]);
        QCOMPARE(int(w3.actions.size()), 1);
        QVERIFY(std::get<CameraSeriesByDistanceAction>(w3.actions[0]) == (CameraSeriesByDistanceAction{20, 10, 1}));
        QCOMPARE(saved.settings.profile.maxHorizontalSpeed, 12.0);
        QCOMPARE(saved.settings.profile.climbRate, 4.0);  // no default rate: the maximum is the estimate
    }

    void safeDistanceToTerrainBothWays()
    {
        // The profile's VPT_SAFE_DISTANCE_TO_TERRAIN is the terrain rule's clearance; absent, 10 m.
        QCOMPARE(imported(savedRoute()).settings.profile.safeTerrainDistance, 10.0);
        pb::Route withDistance = savedRoute();
        auto *p = withDistance.mutable_vehicleprofile()->add_parameters();
        p->set_type(pb::VPT_SAFE_DISTANCE_TO_TERRAIN);
        p->set_value(25);
        Route route = imported(withDistance);
        QCOMPARE(route.settings.profile.safeTerrainDistance, 25.0);

        // Edited, it goes back in the same parameter, nothing else of the profile changed.
        route.settings.profile.safeTerrainDistance = 40;
        const pb::Route back = routeToHci(route);
        int found = 0;
        for (const auto &q : back.vehicleprofile().parameters())
            if (q.type() == pb::VPT_SAFE_DISTANCE_TO_TERRAIN) {
                ++found;
                QCOMPARE(q.value(), 40.0);
            }
        QCOMPARE(found, 1);
        QCOMPARE(back.vehicleprofile().parameters_size(), withDistance.vehicleprofile().parameters_size());
        QCOMPARE(imported(back).settings.profile.safeTerrainDistance, 40.0);
    }

    void profileCamerasPlanTheSegmentsThatNameThem()
    {
        // The server's profile carries a camera payload (id 7): the route knows it, and a
        // photogrammetry segment whose `camera` is "7" is planned with its optics everywhere Sortie plans.
        Camera survey;
        survey.name = QStringLiteral("Survey 42 MP");
        survey.sensorWidthMm = 35.9;
        survey.sensorHeightMm = 24.0;
        survey.focalLengthMm = 35.0;
        survey.imageWidthPx = 7952;
        survey.imageHeightPx = 5304;
        pb::Route withCamera = savedRoute();
        *withCamera.mutable_vehicleprofile()->add_payloadprofiles()->mutable_payloadprofile() = payloadFromCamera(survey, 7);
        Route route = imported(withCamera);
        QCOMPARE(route.settings.profile.cameras.size(), size_t(1));
        QCOMPARE(route.settings.profile.cameras[0].id, 7);
        QCOMPARE(route.settings.profile.cameras[0].camera.name, survey.name);
        QVERIFY(std::abs(route.settings.profile.cameras[0].camera.focalLengthMm - 35.0) < 1e-9);
        // Read-only: sending the route back leaves the profile as the server sent it.
        QCOMPARE(routeToHci(route).vehicleprofile().SerializeAsString(), withCamera.vehicleprofile().SerializeAsString());

        const AlgorithmDefinition *def = AlgorithmCatalog::builtIn().byKind(AlgorithmKind::Photogrammetry);
        QVERIFY(def);
        AlgorithmSegment photo;
        photo.algorithm = def->className;
        photo.figure = FigureType::Polygon;
        for (const GeoPoint &g : {GeoPoint{56.95, 24.1}, GeoPoint{56.95, 24.12}, GeoPoint{56.96, 24.12}, GeoPoint{56.96, 24.1}})
            photo.points.push_back({g, 0.0, AltitudeType::Agl});
        for (const ParameterDefinition &p : def->parameters)
            if (!p.defaultValue.isEmpty())
                photo.parameters.push_back({p.name, p.defaultValue});
        photo.setValue(QStringLiteral("camera"), QStringLiteral("7"));
        route.segments.push_back(photo);
        const int row = int(route.segments.size()) - 1;
        const auto pointsOf = [row](const Route &r) {
            int n = 0;
            for (const PathPoint &p : flightPath(r))
                n += p.segment == row ? 1 : 0;
            return n;
        };
        const auto planErrors = [row](const Route &r) {
            int n = 0;
            for (const ValidationIssue &i : validateRoute(r).issues)
                n += i.segment == row && i.rule == QLatin1String("segment-plan") ? 1 : 0;
            return n;
        };
        QVERIFY2(pointsOf(route) > 10, qPrintable(QString::number(pointsOf(route))));
        QCOMPARE(planErrors(route), 0);
        // Without the profile's camera the same segment cannot be planned ("7" names nothing): the path
        // only runs through its corners, and validation says why.
        Route bare = route;
        bare.settings.profile.cameras.clear();
        QCOMPARE(pointsOf(bare), 4);
        QVERIFY(planErrors(bare) > 0);
    }

    void unchangedRouteGoesBackByteForByte()
    {
        // Also a profile with a parameter given twice, the second NaN (found by fuzz_hci_route).
        pb::Route odd = savedRoute();
        auto *twice = odd.mutable_vehicleprofile()->add_parameters();
        twice->set_type(pb::VPT_MAX_CLIMB_RATE);
        twice->set_value(std::numeric_limits<double>::quiet_NaN());
        odd.mutable_segments(0)->mutable_figure()->mutable_points(0)->set_aglaltitude(std::numeric_limits<double>::quiet_NaN());
        // And a waypoint that is no place (a NaN longitude), kept as the server sent it, whose point
        // has no altitude type (found by fuzz_hci_route: NaN != NaN rewrote the point).
        pb::Route nowhere = savedRoute();
        pb::FigurePoint *lost = nowhere.mutable_segments(0)->mutable_figure()->mutable_points(0);
        lost->set_longitude(std::numeric_limits<double>::quiet_NaN());
        lost->clear_altitudetype();
        for (const pb::Route &original : {storedRoute(), savedRoute(), odd, nowhere}) {
            const pb::Route back = routeToHci(imported(original));
            QCOMPARE(back.SerializeAsString(), original.SerializeAsString());
        }
    }

    void editedRouteKeepsEverythingElseIncludingUnknownFields()
    {
        // The server's route, with fields this schema does not know at three depths.
        pb::Route withUnknown = savedRoute();
        withUnknown.mutable_unknown_fields()->AddVarint(900, 7);
        withUnknown.mutable_segments(0)->mutable_unknown_fields()->AddLengthDelimited(901, "future segment field");
        withUnknown.mutable_segments(0)->mutable_figure()->mutable_points(0)->mutable_unknown_fields()->AddFixed64(902, 42);
        withUnknown.mutable_segments(1)->mutable_unknown_fields()->AddVarint(903, 1);
        pb::Route original;
        QVERIFY(original.ParseFromString(withUnknown.SerializeAsString()));
        QCOMPARE(original.unknown_fields().field_count(), 1);

        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        editor.replaceRoute(imported(original), QStringLiteral("Load"));
        editor.moveWaypoints({0}, {QGeoCoordinate(56.97, 24.08)}, EditStep::Continuing);  // a drag, in two steps
        editor.moveWaypoints({0}, {QGeoCoordinate(56.98, 24.09)});
        const pb::Route sent = routeToHci(model.route());

        QCOMPARE(sent.segments(1).SerializeAsString(), original.segments(1).SerializeAsString());
        QCOMPARE(sent.segments(2).SerializeAsString(), original.segments(2).SerializeAsString());
        pb::SegmentDefinition expected = original.segments(0);
        expected.mutable_figure()->mutable_points(0)->set_latitude(56.98 * kDeg);
        expected.mutable_figure()->mutable_points(0)->set_longitude(24.09 * kDeg);
        QCOMPARE(sent.segments(0).SerializeAsString(), expected.SerializeAsString());
        pb::Route rest = sent, restOriginal = original;
        rest.clear_segments();
        restOriginal.clear_segments();
        QCOMPARE(rest.SerializeAsString(), restOriginal.SerializeAsString());
        QCOMPARE(sent.unknown_fields().field_count(), 1);
        QCOMPARE(sent.segments(0).unknown_fields().field_count(), 1);

        // Undo the move: the route is the server's again, byte for byte.
        stack.undo();
        QCOMPARE(routeToHci(model.route()).SerializeAsString(), original.SerializeAsString());
    }

    void bulkEditWritesOnlyWhatChanged()
    {
        const pb::Route original = savedRoute();
        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        editor.replaceRoute(imported(original), QStringLiteral("Load"));
        editor.setSpeed({1, 2}, 9);
        editor.setAltitudeType({2}, AltitudeType::Amsl);
        editor.setAltitude({2}, 140.5);
        QVERIFY(editor.addAction({1}, {{"kind", "cameraTrigger"}, {"state", "singleShot"}}));
        const pb::Route sent = routeToHci(model.route());
        QCOMPARE(sent.segments(0).SerializeAsString(), original.segments(0).SerializeAsString());
        const pb::SegmentDefinition &s1 = sent.segments(1);
        QCOMPARE(s1.parametervalues(0).value(), std::string("9.0"));
        QCOMPARE(s1.parametervalues(0).id(), original.segments(1).parametervalues(0).id());
        for (int i = 1; i < s1.parametervalues_size(); ++i)
            QCOMPARE(s1.parametervalues(i).SerializeAsString(), original.segments(1).parametervalues(i).SerializeAsString());
        QCOMPARE(s1.actiondefinitions_size(), 2);
        QCOMPARE(s1.actiondefinitions(0).SerializeAsString(), original.segments(1).actiondefinitions(0).SerializeAsString());
        QVERIFY(s1.actiondefinitions(1).has_cameratriggerdefinition());
        QVERIFY(!s1.actiondefinitions(1).has_id());
        const pb::SegmentDefinition &s2 = sent.segments(2);
        QCOMPARE(s2.figure().points(0).altitudetype(), pb::AT_WGS84);
        QCOMPARE(s2.figure().points(0).wgs84altitude(), 140.5);
        QCOMPARE(s2.figure().points(0).aglaltitude(), 80.0);  // the old AGL value stays as it was
        bool typeParam = false;
        for (const auto &p : s2.parametervalues())
            if (p.name() == "altitudeType")
                typeParam = p.value() == "AMSL";
        QVERIFY(typeParam);
        QCOMPARE(s2.uuid(), original.segments(2).uuid());
    }

    void untouchedActionsKeepTheirBytes()
    {
        // Found by fuzz_hci_route: an opaque action made every action list look edited, and an
        // absent field was then written as its default.
        pb::Route original = savedRoute();
        pb::SegmentDefinition *s = original.mutable_segments(1);
        s->mutable_actiondefinitions(0)->mutable_waitdefinition()->clear_interval();
        auto *servo = s->add_actiondefinitions();
        servo->set_id(77);
        servo->mutable_setservodefinition()->set_servoid(3);
        servo->mutable_setservodefinition()->set_pwm(1900);
        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        editor.replaceRoute(imported(original), QStringLiteral("Load"));
        const auto &w = std::get<Waypoint>(model.segment(1));
        QCOMPARE(int(w.actions.size()), 2);
        QCOMPARE(describeAction(w.actions[1]), QStringLiteral("Set servo: servo 3, PWM 1900 µs"));
        QCOMPARE(routeToHci(model.route()).SerializeAsString(), original.SerializeAsString());
        editor.setAltitude({1}, 95);
        editor.addAction({1}, {{"kind", "wait"}, {"seconds", 2}});
        const pb::SegmentDefinition sent = routeToHci(model.route()).segments(1);
        QCOMPARE(sent.actiondefinitions_size(), 3);
        QCOMPARE(sent.actiondefinitions(0).SerializeAsString(), s->actiondefinitions(0).SerializeAsString());
        QCOMPARE(sent.actiondefinitions(1).SerializeAsString(), s->actiondefinitions(1).SerializeAsString());
        QCOMPARE(sent.actiondefinitions(2).waitdefinition().interval(), 2.0);
        QCOMPARE(sent.figure().points(0).aglaltitude(), 95.0);
    }

    void gimbalKeepsWhatIsNotSet()
    {
        // A camera control that sets only the tilt (radians; 90° looks down, per the facts file).
        pb::ActionDefinition received;
        received.set_id(5);
        received.mutable_cameracontroldefinition()->set_tilt(std::numbers::pi / 2);
        const WaypointAction read = actionFromHci(received);
        const auto &gimbal = std::get<CameraControlAction>(read);
        QCOMPARE(*gimbal.tiltDeg, 90.0);
        QVERIFY(!gimbal.rollDeg && !gimbal.yawDeg && !gimbal.zoomLevel);
        QCOMPARE(describeAction(read), QStringLiteral("Gimbal tilt 90°"));
        // Untouched: the same bytes. Yaw set: added, tilt kept, roll still absent. Tilt unset: gone.
        pb::ActionDefinition sent = received;
        actionToHci(read, sent);
        QCOMPARE(sent.SerializeAsString(), received.SerializeAsString());
        CameraControlAction edited = gimbal;
        edited.yawDeg = 30;
        actionToHci(edited, sent);
        QVERIFY(std::abs(sent.cameracontroldefinition().yaw() - std::numbers::pi / 6) < 1e-12);
        QCOMPARE(sent.cameracontroldefinition().tilt(), std::numbers::pi / 2);
        QVERIFY(!sent.cameracontroldefinition().has_roll() && !sent.cameracontroldefinition().has_zoomlevel());
        QCOMPARE(sent.id(), 5);
        edited.tiltDeg.reset();
        edited.zoomLevel = 3;
        actionToHci(edited, sent);
        QVERIFY(!sent.cameracontroldefinition().has_tilt());
        QCOMPARE(sent.cameracontroldefinition().zoomlevel(), 3);
        const auto back = std::get<CameraControlAction>(actionFromHci(sent));
        QVERIFY(!back.tiltDeg && !back.rollDeg && back.zoomLevel == 3);
        QVERIFY(std::abs(*back.yawDeg - 30) < 1e-9);
    }

    void newRouteEncodesLikeTheSdkSample()
    {
        const pb::Route sdk = payloadOf<pb::CreateOrUpdateObjectRequest>("019-CreateOrUpdateObjectRequest.bin").object().route();
        Route fresh = imported(sdk);
        fresh.origin = {};
        for (Segment &s : fresh.segments)
            std::get<Waypoint>(s).origin = {};
        const pb::Route encoded = routeToHci(fresh);
        QCOMPARE(encoded.segments_size(), sdk.segments_size());
        for (int i = 0; i < sdk.segments_size(); ++i) {
            const QString diff = differences(encoded.segments(i), sdk.segments(i), true);
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
        }
        QCOMPARE(encoded.safealtitude(), 50.0);
        QCOMPARE(encoded.initialspeed(), 5.0);
        QCOMPARE(encoded.failsafes(0).action(), pb::FA_WAIT);
    }

    void areaScanRoundTrip()
    {
        Route r = imported(savedRoute());
        AreaScan scan;
        scan.polygon = {{56.95, 24.10}, {56.95, 24.11}, {56.955, 24.11}, {56.955, 24.10}};
        scan.parameters.heightMode = ScanHeightMode::GroundSampleDistance;
        scan.parameters.groundSampleDistanceCm = 1.8;
        scan.parameters.directionDeg = 12.5;
        syncDerivedFields(scan.parameters);
        r.segments.push_back(scan);
        const pb::Route sent = routeToHci(r);
        const pb::SegmentDefinition &s = sent.segments(3);
        QCOMPARE(s.algorithmclassname(), std::string(kAreaScanAlgorithm));
        QCOMPARE(s.figure().type(), pb::FT_POLYGON);
        QCOMPARE(s.figure().points_size(), 5);  // sent closed
        QCOMPARE(s.figure().points(4).latitude(), s.figure().points(0).latitude());
        QVERIFY(findValue(s, "overlapSide") && findValue(s, "overlapForward") && findValue(s, "sideDistance"));
        QVERIFY(!findValue(s, "sideOverlap") && !findValue(s, "forwardOverlap"));
        const Route back = imported(sent);
        QVERIFY(std::get<AreaScan>(back.segments[3]) == scan);
        QVERIFY(back == r);
    }

    void processedRouteIsThePlanTheVehicleFlies()
    {
        const Route route = imported(savedRoute());
        const pb::ProcessedRoute processed = payloadOf<pb::ProcessRouteResponse>("039-ProcessRouteResponse.bin").processedroute();
        const ProcessedPlan plan = processedPlanFromHci(processed, &route);
        QVERIFY(plan.flyable());
        QCOMPARE(int(plan.segments.size()), 3);
        QCOMPARE(int(plan.waypoints.size()), 3);
        QCOMPARE(plan.segments[1].routeRow, 1);
        QCOMPARE(plan.segments[1].actionCount, 1);  // the wait
        QCOMPARE(plan.estimatedDistance, 742.36);
        QVERIFY(std::abs(plan.estimatedTime - (21.5 + 83.2 + 58.7)) < 1e-9);
        QCOMPARE(plan.waypoints[2].speed, 7.5);
        QCOMPARE(plan.waypoints[2].altitudeAmsl, 104.35);
        QCOMPARE(plan.waypoints[2].frame, AltitudeFrame::Agl);

        QVERIFY(plan.flyable());
        pb::ProcessedRoute invalid = processed;
        invalid.mutable_segments(1)->set_status(pb::RPS_INVALID);
        auto *msg = invalid.mutable_segments(1)->mutable_messageset()->add_messages();
        msg->set_severity(pb::MS_ERROR);
        msg->set_defaulttext("Waypoint is inside a no-fly zone");
        const ProcessedPlan refused = processedPlanFromHci(invalid, &route);
        QVERIFY(!refused.flyable());
        QCOMPARE(refused.segments[1].messages.size(), size_t(1));
        QVERIFY(refused.segments[1].messages.front().error);
        QCOMPARE(refused.segments[1].messages.front().text, QStringLiteral("Waypoint is inside a no-fly zone"));
    }

    void missionMapping()
    {
        pb::Mission m = payloadOf<pb::CreateOrUpdateObjectResponse>("018-CreateOrUpdateObjectResponse.bin").object().mission();
        *m.add_routes() = savedRoute();
        const Result<Mission> mission = missionFromHci(m);
        QVERIFY(mission.ok());
        QCOMPARE(mission->name, QStringLiteral("Riga port survey"));
        QCOMPARE(int(mission->routes.size()), 1);
        QCOMPARE(missionToHci(*mission).SerializeAsString(), m.SerializeAsString());
    }

    // Each tool of the facts file, built by code: out to a SegmentDefinition and back unchanged,
    // with the class name, figure type and parameter names the facts give.
    void everySegmentTypeRoundTrips()
    {
        Route r = imported(savedRoute());
        const GeoPoint a{56.95, 24.10}, b{56.95, 24.11}, c{56.955, 24.11}, d{56.955, 24.10};
        for (const AlgorithmDefinition &def : AlgorithmCatalog::builtIn().algorithms()) {
            if (def.kind == AlgorithmKind::Waypoint || def.kind == AlgorithmKind::TakeOff || def.kind == AlgorithmKind::Landing
                || def.kind == AlgorithmKind::AreaScan)
                continue;  // typed segments, below
            AlgorithmSegment seg;
            seg.algorithm = def.className;
            seg.figure = def.figure;
            const std::vector<GeoPoint> corners = def.figure == FigureType::Polygon ? std::vector{a, b, c, d}
                                                : def.figure == FigureType::Polyline ? std::vector{a, c} : std::vector{a};
            for (const GeoPoint &g : corners)
                seg.points.push_back({g, def.figure == FigureType::Circle ? 40.0 : 0.0, AltitudeType::Agl});
            if (def.figure == FigureType::Circle)
                seg.figureParameters = {35.5};
            for (const ParameterDefinition &p : def.parameters)
                if (!p.defaultValue.isEmpty())
                    seg.parameters.push_back({p.name, p.defaultValue});
            r.segments.push_back(seg);
        }
        Waypoint takeoff, landing;
        takeoff.role = WaypointRole::Takeoff;
        takeoff.position = a;
        landing.role = WaypointRole::Land;
        landing.position = d;
        landing.altitude = 0;
        r.segments.push_back(takeoff);
        r.segments.push_back(landing);
        AreaScan scan;  // UgCS's own area scan: a plain side distance, no camera overlap
        scan.polygon = {a, b, c};
        scan.parameters.sideDistanceMeters = 25;
        scan.parameters.toleranceMeters = 6;  // AGL tolerance: the facts' `tolerance`, metres
        syncDerivedFields(scan.parameters);
        r.segments.push_back(scan);

        const pb::Route sent = routeToHci(r);
        QCOMPARE(sent.segments_size(), int(r.segments.size()));
        QSet<QString> kinds;
        for (int i = 3; i < sent.segments_size(); ++i) {
            const pb::SegmentDefinition &s = sent.segments(i);
            const QString className = QString::fromStdString(s.algorithmclassname());
            QVERIFY2(className.startsWith(QLatin1String(kUgcsAlgorithmPackage)), qPrintable(className));
            kinds.insert(className.section(QLatin1Char('.'), -1));
            if (s.figure().type() == pb::FT_POLYGON) {
                QVERIFY(s.figure().points_size() >= 4);
                QCOMPARE(s.figure().points(s.figure().points_size() - 1).longitude(), s.figure().points(0).longitude());
            }
            if (s.figure().type() == pb::FT_CIRCLE) {
                QCOMPARE(s.figure().parameters(0).value(), 35.5);
                QCOMPARE(s.figure().points(0).aglaltitude(), 40.0);
            }
        }
        for (const char *k : {"PhotogrammetryAlgorithm", "CircleAlgorithm", "PerimeterAlgorithm", "CorridorMappingAlgorithm",
                              "TakeOffAlgorithm", "LandingAlgorithm", "AreaScanAlgorithm", "ExpandingSquareAlgorithm",
                              "CreepingLineAlgorithm", "FacadeScannerAlgorithm"})
            QVERIFY2(kinds.contains(QLatin1String(k)), k);
        const pb::SegmentDefinition &areaScan = sent.segments(sent.segments_size() - 1);
        QCOMPARE(findValue(areaScan, "sideDistance")->value(), std::string("25.0"));
        QVERIFY(!findValue(areaScan, "overlapSide"));
        QCOMPARE(findValue(areaScan, "tolerance")->value(), std::string("6.0"));
        const Route back = imported(sent);
        QCOMPARE(back.segments.size(), r.segments.size());
        for (size_t i = 0; i < r.segments.size(); ++i)
            QVERIFY2(back.segments[i] == r.segments[i], qPrintable(segmentLabel(int(i), r.segments[i])));
        // And out again: what came back goes out byte for byte.
        QCOMPARE(routeToHci(back).SerializePartialAsString(), sent.SerializePartialAsString());
    }

    // Segments as UgCS clients write them (NET-RC, NET-DEMO, MAT in the facts file), built by hand
    // field by field, framed, decoded: the values arrive typed, and an unedited route goes back
    // byte for byte.
    void handMadeFramesOfEveryTool()
    {
        pb::Route route = storedRoute();
        auto point = [](pb::Figure *f, double lat, double lon, double agl) {
            pb::FigurePoint *p = f->add_points();
            p->set_latitude(lat * kDeg);
            p->set_longitude(lon * kDeg);
            p->set_aglaltitude(agl);
            p->set_altitudetype(pb::AT_AGL);
        };
        auto param = [](pb::SegmentDefinition *s, const char *name, const char *value) {
            pb::ParameterValue *v = s->add_parametervalues();
            v->set_name(name);
            v->set_value(value);
        };
        auto polygon = [&](pb::SegmentDefinition *s) {
            s->mutable_figure()->set_type(pb::FT_POLYGON);
            for (auto [lat, lon] : {std::pair{56.95, 24.10}, {56.95, 24.11}, {56.955, 24.11}, {56.955, 24.10}, {56.95, 24.10}})
                point(s->mutable_figure(), lat, lon, 0);  // closed, as sent
        };
        const std::string impl = "com.ugcs.ucs.service.routing.impl.";
        pb::SegmentDefinition *areaScan = route.add_segments();
        areaScan->set_uuid("a1");
        areaScan->set_algorithmclassname(impl + "AreaScanAlgorithm");
        polygon(areaScan);
        for (auto [n, v] : {std::pair{"speed", "5"}, {"wpTurnType", "STOP_AND_TURN"}, {"height", "70"}, {"altitudeType", "AGL"},
                            {"sideDistance", "25"}, {"directionAngle", "30"}, {"avoidObstacles", "True"},
                            {"actionExecution", "ACTIONS_EVERY_POINT"}, {"overshoot", ""}, {"overshootSpeed", ""},
                            {"areaScanAllowPartialCalculation", "False"}, {"tolerance", "3"}, {"noActionsAtLastPoint", "True"},
                            {"doubleGrid", "False"}})
            param(areaScan, n, v);
        pb::SegmentDefinition *photo = route.add_segments();
        photo->set_uuid("p1");
        photo->set_algorithmclassname(impl + "PhotogrammetryAlgorithm");
        polygon(photo);
        for (auto [n, v] : {std::pair{"speed", "5.0"}, {"camera", "GoPro Hero3 Black Edition"}, {"groundSampleDistance", "2.5"},
                            {"overlapForward", "60"}, {"overlapSide", "30"}, {"camTopFacingForward", "True"},
                            {"directionAngle", "0"}, {"altitudeType", "AMSL"}})
            param(photo, n, v);
        photo->add_actiondefinitions()->mutable_cameraseriesbytimedefinition()->set_autocalc(true);
        pb::SegmentDefinition *circle = route.add_segments();
        circle->set_uuid("c1");
        circle->set_algorithmclassname(impl + "CircleAlgorithm");
        circle->mutable_figure()->set_type(pb::FT_CIRCLE);
        point(circle->mutable_figure(), 56.952, 24.105, 45);
        circle->mutable_figure()->add_parameters()->set_value(30);
        for (auto [n, v] : {std::pair{"speed", "4"}, {"loops", "2"}, {"flightClockwise", "False"}, {"followTerrain", "True"}})
            param(circle, n, v);
        pb::SegmentDefinition *perimeter = route.add_segments();
        perimeter->set_uuid("m1");
        perimeter->set_algorithmclassname(impl + "PerimeterAlgorithm");
        polygon(perimeter);
        for (auto [n, v] : {std::pair{"height", "40"}, {"heightAgl", "True"}, {"loops", "1"}})
            param(perimeter, n, v);
        pb::SegmentDefinition *landing = route.add_segments();
        landing->set_uuid("l1");
        landing->set_algorithmclassname(impl + "LandingAlgorithm");
        landing->mutable_figure()->set_type(pb::FT_LANDING_POINT);
        point(landing->mutable_figure(), 56.9505, 24.1005, 0);

        // Framed as a server's GetObjectResponse would carry it, then decoded from the bytes.
        pb::GetObjectResponse response;
        *response.mutable_object()->mutable_route() = route;
        pb::GetObjectResponse decoded;
        QVERIFY(decoded.ParsePartialFromString(response.SerializePartialAsString()));
        const Result<HciRouteImport> in = routeFromHci(decoded.object().route());
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        const Route &r = in->route;
        QCOMPARE(int(r.segments.size()), 7);
        const AreaScan &scan = std::get<AreaScan>(r.segments[2]);
        QCOMPARE(scan.polygon.size(), size_t(4));  // the closing point is the wire's, not a corner
        QCOMPARE(scan.parameters.sideDistanceMeters, 25.0);
        QCOMPARE(scan.parameters.altitude, 70.0);
        QCOMPARE(scan.parameters.directionDeg, 30.0);
        QCOMPARE(scan.parameters.turnaroundMeters, AreaScanParameters{}.turnaroundMeters);  // "" is "not set"
        QCOMPARE(planAreaScan(scan).plan->transectSpacing, 25.0);
        const AlgorithmSegment &ph = std::get<AlgorithmSegment>(r.segments[3]);
        QCOMPARE(ph.kind(), AlgorithmKind::Photogrammetry);
        QCOMPARE(parameterValue(r.segments[3], QStringLiteral("groundSampleDistance")).toDouble(), 2.5);
        QCOMPARE(parameterValue(r.segments[3], QStringLiteral("camTopFacingForward")).toBool(), true);
        QCOMPARE(int(ph.actions.size()), 1);
        const std::optional<AreaScan> photoScan = scanOf(r.segments[3]);
        QVERIFY(photoScan);
        QCOMPARE(photoScan->parameters.camera.name, QStringLiteral("GoPro Hero3 Black Edition"));
        QCOMPARE(photoScan->parameters.sideOverlapPercent, 30.0);
        const AlgorithmSegment &ci = std::get<AlgorithmSegment>(r.segments[4]);
        QCOMPARE(ci.figure, FigureType::Circle);
        QCOMPARE(ci.figureParameters, std::vector<double>{30});
        QCOMPARE(altitudeOf(r.segments[4]), 45.0);
        QCOMPARE(parameterValue(r.segments[4], QStringLiteral("flightClockwise")).toBool(), false);
        QCOMPARE(parameterValue(r.segments[4], QStringLiteral("loops")).toDouble(), 2.0);
        QCOMPARE(std::get<AlgorithmSegment>(r.segments[5]).points.size(), size_t(4));
        QCOMPARE(altitudeOf(r.segments[5]), 40.0);
        QCOMPARE(std::get<Waypoint>(r.segments[6]).role, WaypointRole::Land);
        QCOMPARE(routeToHci(r).SerializePartialAsString(), decoded.object().route().SerializePartialAsString());
    }

    // A segment of an algorithm Sortie has never heard of, with fields this schema does not know:
    // shown, editable as raw name/value text, and byte for byte the same after another segment
    // was edited; an edit of one of its values changes that value only.
    void unknownAlgorithmSurvivesEditsByteForByte()
    {
        pb::Route original = storedRoute();
        pb::SegmentDefinition *odd = original.add_segments();
        odd->set_uuid("u1");
        odd->set_algorithmclassname("com.ugcs.ucs.service.routing.impl.SpiralSearchAlgorithm");
        odd->mutable_figure()->set_type(pb::FT_EIGHT_CURVE);
        pb::FigurePoint *p = odd->mutable_figure()->add_points();
        p->set_latitude(56.95 * kDeg);
        p->set_longitude(24.1 * kDeg);
        p->set_wgs84altitude(120);
        p->set_altitudetype(pb::AT_WGS84);
        odd->mutable_figure()->add_parameters()->set_value(12);
        for (auto [n, v] : {std::pair{"turns", "7"}, {"spiralOut", "True"}, {"speed", "6.5"}}) {
            pb::ParameterValue *pv = odd->add_parametervalues();
            pv->set_name(n);
            pv->set_value(v);
        }
        odd->mutable_unknown_fields()->AddVarint(9999, 42);  // a field of a newer schema
        pb::Route withUnknown;
        QVERIFY(withUnknown.ParseFromString(original.SerializeAsString()));
        const std::string oddBytes = withUnknown.segments(2).SerializeAsString();

        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        editor.replaceRoute(imported(withUnknown), QStringLiteral("Load"));
        QCOMPARE(model.index(2).data(RouteModel::KindRole).toString(), QStringLiteral("unknown"));
        QCOMPARE(model.index(2).data(RouteModel::LabelRole).toString(), QStringLiteral("SpiralSearch 3"));
        QCOMPARE(model.index(2).data(RouteModel::ScanParametersRole).toMap().value(QStringLiteral("turns")).toString(), QStringLiteral("7"));
        QCOMPARE(model.index(2).data(RouteModel::SpeedRole).toDouble(), 6.5);
        QVERIFY(editor.moveWaypoints({0}, {QGeoCoordinate(56.97, 24.08)}));
        QVERIFY(editor.setAltitude({0, 1}, 77));
        pb::Route sent = routeToHci(model.route());
        QCOMPARE(sent.segments(2).SerializeAsString(), oddBytes);

        QVERIFY(editor.setParameter({2}, QStringLiteral("turns"), QStringLiteral("9")));
        QVERIFY(!editor.setParameter({2}, QStringLiteral("spin"), 1));  // it has no such parameter
        sent = routeToHci(model.route());
        pb::SegmentDefinition expected = withUnknown.segments(2);
        expected.mutable_parametervalues(0)->set_value("9");
        QCOMPARE(sent.segments(2).SerializeAsString(), expected.SerializeAsString());
    }

    // UgCS payload profiles give the optics in SI metres (GoPro Hero3 Black: focal 0.0028 m).
    void profileCameraIsInMetres()
    {
        pb::Route route = storedRoute();
        pb::PayloadProfile *camera = route.mutable_vehicleprofile()->add_payloadprofiles()->mutable_payloadprofile();
        camera->set_name("GoPro Hero3 Black Edition");
        camera->set_payloadtype(pb::PT_CAMERA);
        for (auto [type, value] : {std::pair{pb::PPT_TRUE_FOCAL_LENGTH, 0.0028}, {pb::PPT_SENSOR_WIDTH, 0.00617},
                                   {pb::PPT_SENSOR_HEIGHT, 0.00455}, {pb::PPT_SENSOR_HORIZONTAL_PIXELS, 4000.0},
                                   {pb::PPT_SENSOR_VERTICAL_PIXELS, 3000.0}}) {
            pb::PayloadParameter *p = camera->add_parameters();
            p->set_type(type);
            p->set_value(value);
        }
        pb::SegmentDefinition *scan = route.add_segments();
        scan->set_algorithmclassname(kAreaScanAlgorithm);
        scan->mutable_figure()->set_type(pb::FT_POLYGON);
        for (auto [lat, lon] : {std::pair{56.95, 24.10}, {56.95, 24.11}, {56.955, 24.11}}) {
            pb::FigurePoint *p = scan->mutable_figure()->add_points();
            p->set_latitude(lat * kDeg);
            p->set_longitude(lon * kDeg);
        }
        pb::ParameterValue *gsd = scan->add_parametervalues();
        gsd->set_name("groundSampleDistance");
        gsd->set_value("2");
        const Route r = imported(route);
        const AreaScanParameters &p = std::get<AreaScan>(r.segments[2]).parameters;
        QCOMPARE(p.camera.focalLengthMm, 2.8);
        QCOMPARE(p.camera.sensorWidthMm, 6.17);
        QCOMPARE(p.camera.imageWidthPx, 4000);
        // 2 cm/px with this camera: H = 0.02 · 2.8 · 4000 / 6.17 = 36.3 m (GSD on the coarser axis).
        QVERIFY(std::abs(scanAltitude(p) - 0.02 * 2.8 / std::max(6.17 / 4000, 4.55 / 3000)) < 1e-6);
        QVERIFY(scanAltitude(p) > 30 && scanAltitude(p) < 40);
    }

    void javaNumberText()
    {
        QCOMPARE(javaDoubleString(5), std::string("5.0"));
        QCOMPARE(javaDoubleString(7.5), std::string("7.5"));
        QCOMPARE(javaDoubleString(0.001), std::string("0.001"));
        QCOMPARE(javaDoubleString(1e-4), std::string("1.0E-4"));
        QCOMPARE(javaDoubleString(12345678.9), std::string("1.23456789E7"));
        QCOMPARE(javaDoubleString(1e7), std::string("1.0E7"));
        QCOMPARE(javaDoubleString(-120.25), std::string("-120.25"));
        QCOMPARE(javaDoubleString(100), std::string("100.0"));
        QCOMPARE(parseHciDouble("1.0E-4").value(), 1e-4);
        QVERIFY(!parseHciDouble("").has_value());
        QVERIFY(!parseHciDouble("5 m/s").has_value());
    }
};

QTEST_GUILESS_MAIN(TestHciMapping)
#include "tst_hcimapping.moc"
