// Route <-> HCI, on frames the UgCS SDK produced (tests/data/hci-vectors): an unchanged route goes
// back byte for byte; a route edited in one waypoint sends every other field back exactly,
// unknown fields included; a new route encodes the way the SDK's sample builds one; the processed
// route becomes the plan the vehicle will fly.
#include "Domain.pb.h"
#include "HciRouteMapper.h"
#include "HciText.h"
#include "Messages.pb.h"
#include "ProcessedPlanModel.h"
#include "RouteEditor.h"
#include "RouteModel.h"

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
    QFile f(QStringLiteral(SORTIE_TEST_DATA "/hci-vectors/") + QLatin1String(file));
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

    void unchangedRouteGoesBackByteForByte()
    {
        // Also a profile with a parameter given twice, the second NaN (found by fuzz_hci_route).
        pb::Route odd = savedRoute();
        auto *twice = odd.mutable_vehicleprofile()->add_parameters();
        twice->set_type(pb::VPT_MAX_CLIMB_RATE);
        twice->set_value(std::numeric_limits<double>::quiet_NaN());
        odd.mutable_segments(0)->mutable_figure()->mutable_points(0)->set_aglaltitude(std::numeric_limits<double>::quiet_NaN());
        for (const pb::Route &original : {storedRoute(), savedRoute(), odd}) {
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
        QCOMPARE(std::get<OpaqueAction>(w.actions[1]).description, QStringLiteral("SetServo"));
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
        QCOMPARE(s.figure().points_size(), 4);
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

        ProcessedPlanModel model;
        model.setPlan(plan);
        QCOMPARE(model.rowCount(), 3);
        const QModelIndex i = model.index(0);
        QVERIFY(std::abs(i.data(ProcessedPlanModel::HeightAboveGroundRole).toDouble() - 100.0) < 1e-9);
        QCOMPARE(i.data(ProcessedPlanModel::RouteRowRole).toInt(), 0);
        QCOMPARE(i.data(ProcessedPlanModel::StatusRole).toString(), QStringLiteral("processed"));
        QVERIFY(model.errors().isEmpty());
        pb::ProcessedRoute invalid = processed;
        invalid.mutable_segments(1)->set_status(pb::RPS_INVALID);
        auto *msg = invalid.mutable_segments(1)->mutable_messageset()->add_messages();
        msg->set_severity(pb::MS_ERROR);
        msg->set_defaulttext("Waypoint is inside a no-fly zone");
        model.setPlan(processedPlanFromHci(invalid, &route));
        QVERIFY(!model.flyable());
        QCOMPARE(model.errors(), QStringList{QStringLiteral("Segment 2: Waypoint is inside a no-fly zone")});
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

    void unsupportedSegmentIsAnError()
    {
        pb::Route r = storedRoute();
        r.mutable_segments(1)->set_algorithmclassname("com.ugcs.ucs.service.routing.impl.CircleAlgorithm");
        const Result<HciRouteImport> i = routeFromHci(r);
        QVERIFY(!i.ok());
        QVERIFY(i.error().message.contains(QStringLiteral("segment 2")));
        QVERIFY(i.error().message.contains(QStringLiteral("CircleAlgorithm")));
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
