// The rules between a route and a vehicle, without a peer: the upload review (errors refuse naming
// the culprit, warnings and unsaved edits asked once), the save gate, the command policy, a route as
// the waypoints a VCI vehicle flies, the read-back comparison, the VCI mission codec with actions,
// and the command log.
#include "AlgorithmCatalog.h"
#include "AlgorithmSegment.h"
#include "AreaScan.h"
#include "Geodesy.h"
#include "CommandLog.h"
#include "CommandPolicy.h"
#include "MissionDifference.h"
#include "VciMissionPlanner.h"
#include "Route.h"
#include "RouteValidator.h"
#include "SegmentPlanning.h"
#include "UploadReview.h"
#include "VciProfile.h"

#include <QSettings>
#include <QMetaEnum>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <numbers>

using namespace sortie;
using namespace sortie::client;
using vehicle::MissionAction;
using vehicle::MissionItem;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

mission::Waypoint waypoint(double lat, double lon, double altitude, double speed = 6)
{
    mission::Waypoint w;
    w.position = {lat, lon};
    w.altitude = altitude;
    w.speed = speed;
    return w;
}

mission::Route route(std::vector<mission::Segment> segments)
{
    mission::Route r;
    r.settings.name = QStringLiteral("rules");
    r.segments = std::move(segments);
    return r;
}

} // namespace

class TestUploadRules : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        // The policy keeps its setting in QSettings: a scratch place, not the user's.
        QCoreApplication::setOrganizationName(QStringLiteral("sortie-tests"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_uploadrules"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    }

    void anErrorBlocksNamingTheCulprit()
    {
        mission::Route r = route({waypoint(56.95, 24.10, 30), waypoint(56.951, 24.10, 30, 0), waypoint(56.952, 24.10, 500)});
        const UploadReview review = reviewUpload(mission::validateRoute(r), true);
        QVERIFY(review.isBlocked());
        QVERIFY(!review.needsConfirmation()); // nothing to ask: it does not go
        QCOMPARE(review.culprit, 1);
        QVERIFY2(review.blocked.startsWith(QLatin1String("Waypoint 2: the speed must be positive.")), qPrintable(review.blocked));
        QVERIFY2(review.blocked.contains(QLatin1String("and 1 more error")), qPrintable(review.blocked));
        QVERIFY2(review.blocked.endsWith(QLatin1String("Fix them before uploading.")), qPrintable(review.blocked));
        QVERIFY(saveRefusal(mission::validateRoute(r)).endsWith(QLatin1String("Fix them before saving.")));
        QVERIFY(saveRefusal(mission::validateRoute(route({waypoint(56.95, 24.10, 30), waypoint(56.951, 24.10, 30)}))).isEmpty());
    }

    void warningsAndUnsavedEditsAreOneQuestion()
    {
        mission::Route r = route({waypoint(56.95, 24.10, 30), waypoint(56.951, 24.10, 10), waypoint(56.952, 24.10, 12)});
        UploadReview review = reviewUpload(mission::validateRoute(r), false);
        QVERIFY(!review.isBlocked());
        QVERIFY(review.needsConfirmation());
        QCOMPARE(review.warnings.size(), 2);
        QVERIFY(review.warnings[0].startsWith(QLatin1String("Waypoint 2: altitude")));
        QString q = review.question(QStringLiteral("EMU-101"));
        QVERIFY2(q.contains(QLatin1String("2 warning(s)")), qPrintable(q));
        QVERIFY(q.contains(QStringLiteral("• Waypoint 3: altitude")));
        QVERIFY(!q.contains(QLatin1String("not saved")));
        QVERIFY(q.endsWith(QLatin1String("Upload to EMU-101?")));

        review = reviewUpload(mission::validateRoute(route({waypoint(56.95, 24.10, 30), waypoint(56.951, 24.10, 30)})), true);
        QVERIFY(review.needsConfirmation());
        QVERIFY(review.warnings.isEmpty());
        q = review.question(QStringLiteral("Sim VCI 1"));
        QVERIFY2(q.startsWith(QLatin1String("The route has edits that are not saved")), qPrintable(q));

        review = reviewUpload(mission::validateRoute(route({waypoint(56.95, 24.10, 30), waypoint(56.951, 24.10, 30)})), false);
        QVERIFY(!review.needsConfirmation() && !review.isBlocked());
    }

    void commandPolicy()
    {
        CommandPolicy policy;
        QCOMPARE(policy.defaultTakeoffAltitude(), 20.0);
        QCOMPARE(policy.takeoffAltitude(nullptr), 20.0);
        QSignalSpy changed(&policy, &CommandPolicy::defaultTakeoffAltitudeChanged);
        policy.setDefaultTakeoffAltitude(1); // below the floor: refused
        policy.setDefaultTakeoffAltitude(std::nan(""));
        QCOMPARE(changed.count(), 0);
        policy.setDefaultTakeoffAltitude(35);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(CommandPolicy().defaultTakeoffAltitude(), 35.0); // kept in the settings
        policy.setDefaultTakeoffAltitude(20);

        // Vehicle without telemetry: on the ground is not known, so disarming asks.
        vehicle::Vehicle unknown(nullptr);
        using Command = CommandPolicy::Command;
        const QMetaEnum commandNames = QMetaEnum::fromType<Command>();
        for (Command asks : {Command::Arm, Command::TakeOff, Command::Auto, Command::Disarm})
            QVERIFY2(policy.needsConfirmation(asks, &unknown), commandNames.valueToKey(int(asks)));
        for (Command immediate : {Command::Land, Command::Hold, Command::ReturnHome, Command::Guided, Command::Manual})
            QVERIFY2(!policy.needsConfirmation(immediate, &unknown), commandNames.valueToKey(int(immediate)));
        QVERIFY(policy.confirmation(Command::Land, &unknown).isEmpty());
        QCOMPARE(policy.confirmation(Command::TakeOff, &unknown), QStringLiteral("Take off with the vehicle to 20 m above home?").replace(QLatin1String("the vehicle"), unknown.name()));
        QVERIFY(policy.confirmation(Command::Auto, &unknown).contains(QLatin1String("has not seen its mission")));
        unknown.setMission({MissionItem{}, MissionItem{}});
        QVERIFY(policy.confirmation(Command::Auto, &unknown).contains(QLatin1String("2 waypoint(s)")));
        // Resting on the ground with fresh telemetry: disarming needs no question.
        vehicle::TelemetryBatch onGround{{vehicle::TelemetryField::AltitudeAgl, 0.1, 0}};
        unknown.ingest(onGround);
        QVERIFY(!policy.needsConfirmation(Command::Disarm, &unknown));
        unknown.ingest({{vehicle::TelemetryField::AltitudeAgl, 12.0, 0}});
        QVERIFY(policy.needsConfirmation(Command::Disarm, &unknown));

        QCOMPARE(policy.modeLabel(QStringLiteral("return_home")), QStringLiteral("Return home"));
        QCOMPARE(policy.modeLabel(QStringLiteral("auto")), QStringLiteral("Auto (fly the mission)"));
        QCOMPARE(policy.modeLabel(QStringLiteral("loiter")), QStringLiteral("Hold"));
        QCOMPARE(policy.modeLabel(QString()), QStringLiteral("Unknown"));
        QVERIFY(!policy.send(Command(99), &unknown)); // not a command
        QVERIFY(!policy.send(Command::Arm, nullptr));
    }

    void routeAsVciWaypoints()
    {
        mission::Waypoint a = waypoint(56.95, 24.10, 30, 5), b = waypoint(56.951, 24.101, 40, 0);
        b.acceptanceRadius = 4;
        b.actions = {mission::WaitAction{3, false}, mission::HeadingAction{90, false},
                     mission::CameraSeriesByDistanceAction{15, 0, 0}, mission::PanoramaAction{}};
        mission::Waypoint land = waypoint(56.952, 24.10, 20);
        land.role = mission::WaypointRole::Land;
        auto mission = vehicle::vciMissionFor(route({a, b, land}));
        QVERIFY2(mission, qPrintable(mission ? QString() : mission.error().message));
        // Without the home's altitude and the ground, AGL heights fly above home, and the operator is told.
        QCOMPARE(mission->notices.size(), 1);
        QVERIFY2(mission->notices.front().startsWith(QLatin1String("3 point(s) fly their height above the ground as a height above home")),
                 qPrintable(mission->notices.front()));
        QVERIFY(mission->notices.front().contains(QLatin1String("the vehicle has not reported its home")));
        QVERIFY(mission->waitingFor.isEmpty());
        const std::vector<MissionItem> *items = &mission->items;
        QCOMPARE(items->size(), size_t(3));
        QCOMPARE((*items)[0].latitude, 56.95); // degrees; the link sends radians
        QCOMPARE((*items)[1].acceptanceRadius, 4.0);
        QCOMPARE((*items)[1].actions.size(), size_t(4));
        QCOMPARE((*items)[1].actions[0], (MissionAction{QStringLiteral("wait"), {{QStringLiteral("seconds"), 3.0}}}));
        QCOMPARE((*items)[1].actions[1].parameters.value(QStringLiteral("heading")).toDouble(), 90 * kRad);
        QCOMPARE((*items)[1].actions[2].type, QStringLiteral("camera_by_distance"));
        QCOMPARE((*items)[1].actions[3].parameters.value(QStringLiteral("direction")).toString(), QStringLiteral("cw"));
        QCOMPARE((*items)[2].actions, (std::vector<MissionAction>{{QStringLiteral("land"), {}}}));
        // A gimbal action sends what is set, in radians, and leaves the rest out.
        mission::Waypoint gimbal = a;
        mission::CameraControlAction tiltOnly;
        tiltOnly.tiltDeg = 90;
        gimbal.actions = {tiltOnly};
        mission = vehicle::vciMissionFor(route({gimbal}));
        QVERIFY(mission);
        items = &mission->items;
        QCOMPARE((*items)[0].actions.front(), (MissionAction{QStringLiteral("gimbal"), {{QStringLiteral("tilt"), 90 * kRad}}}));

        // What has no VCI form is refused, naming the waypoint.
        mission::Waypoint amsl = b;
        amsl.altitudeType = mission::AltitudeType::Amsl;
        auto refused = vehicle::vciMissionFor(route({a, amsl}));
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.startsWith(QLatin1String("Waypoint 2: an AMSL altitude needs the vehicle's home altitude")),
                 qPrintable(refused.error().message));
        // With the home's altitude, AMSL is flown above it; AGL still needs the ground.
        auto withHome = vehicle::vciMissionFor(route({a, amsl}), {nullptr, 15.0});
        QVERIFY(withHome);
        QCOMPARE(withHome->items[1].altitude, 40.0 - 15.0);
        QCOMPARE(withHome->items[0].altitude, 30.0);
        QVERIFY(withHome->notices.front().startsWith(QLatin1String("1 point(s)")));
        QVERIFY(withHome->notices.front().contains(QLatin1String("no terrain source is set")));
        mission::Waypoint operatorWait = a;
        operatorWait.actions = {mission::WaitAction{0, true}};
        refused = vehicle::vciMissionFor(route({operatorWait}));
        QVERIFY(!refused);
        QVERIFY(refused.error().message.startsWith(QLatin1String("Waypoint 1: a wait for the operator")));
        QVERIFY(!vehicle::vciMissionFor(route({})));

        // An area scan becomes its passes, the camera on from the first point to the last.
        mission::AreaScan scan;
        scan.polygon = {{56.950, 24.100}, {56.950, 24.104}, {56.952, 24.104}, {56.952, 24.100}};
        scan.parameters.altitude = 60;
        mission = vehicle::vciMissionFor(route({a, scan}));
        QVERIFY2(mission, qPrintable(mission ? QString() : mission.error().message));
        items = &mission->items;
        QVERIFY(items->size() > 5);
        QCOMPARE((*items)[1].actions.front().type, QStringLiteral("camera_by_distance"));
        QVERIFY((*items)[1].actions.front().parameters.value(QStringLiteral("interval")).toDouble() > 0);
        QCOMPARE(items->back().actions.front().parameters.value(QStringLiteral("interval")).toDouble(), 0.0);
        QCOMPARE(items->back().altitude, 60.0);
    }

    // Every UgCS tool becomes the points sortie-sim's processing plans for it (a VCI vehicle has no
    // server): an orbit on its radius, the photo tools' camera series, a landing's "land". Before,
    // anything but a waypoint or Sortie's area scan threw out of the upload.
    void everySegmentKindAsVciWaypoints()
    {
        using namespace sortie::mission;
        const GeoPoint a{56.95, 24.10}, b{56.95, 24.104}, c{56.952, 24.104}, d{56.952, 24.10};
        int planned = 0;
        for (const AlgorithmDefinition &def : AlgorithmCatalog::builtIn().algorithms()) {
            if (def.kind == AlgorithmKind::Waypoint || def.kind == AlgorithmKind::AreaScan)
                continue;  // typed segments, above
            AlgorithmSegment seg;
            seg.algorithm = def.className;
            seg.figure = def.figure;
            const std::vector<GeoPoint> corners = def.figure == FigureType::Polygon ? std::vector{a, b, c, d}
                                                : def.figure == FigureType::Polyline ? std::vector{a, c} : std::vector{a};
            for (const GeoPoint &g : corners)
                seg.points.push_back({g, 40.0, AltitudeType::Agl});
            if (def.figure == FigureType::Circle)
                seg.figureParameters = {35.5};
            for (const ParameterDefinition &p : def.parameters)
                if (!p.defaultValue.isEmpty())
                    seg.parameters.push_back({p.name, p.defaultValue});
            if (def.parameter(u"camera"))
                seg.setValue(QStringLiteral("camera"), QStringLiteral("Sony RX1R II"));
            seg.actions = {WaitAction{2, false}};
            const Route r = route({waypoint(56.949, 24.10, 30), seg});
            const auto mission = vehicle::vciMissionFor(r);
            QVERIFY2(mission, qPrintable(def.displayName + QStringLiteral(": ") + (mission ? QString() : mission.error().message)));
            const std::vector<MissionItem> &items = mission->items;
            QVERIFY2(items.size() >= 2, qPrintable(def.displayName));
            const SegmentPlanOutcome expected = planAlgorithmSegment(seg, AlgorithmCatalog::builtIn(), [&] {
                PlanContext context = planContextOf(r.settings);
                context.previousPosition = GeoPoint{56.949, 24.10};
                return context;
            }());
            QVERIFY(expected.ok());
            QCOMPARE(items.size(), 1 + expected.plan->points.size());
            int waits = 0;
            for (size_t i = 1; i < items.size(); ++i) {
                const PlannedPoint &p = expected.plan->points[i - 1];
                QCOMPARE(items[i].latitude, p.position.latitude);
                // A landing is flown at the height its leg left at, then landed on straight down (FlownLegs.h).
                QCOMPARE(items[i].altitude, p.kind == PlannedPoint::Kind::Landing ? items[i - 1].altitude : p.height);
                for (const MissionAction &action : items[i].actions)
                    waits += action.type == QLatin1String("wait");
                if (p.kind == PlannedPoint::Kind::Landing)
                    QCOMPARE(items[i].actions.back().type, QStringLiteral("land"));
            }
            QVERIFY2(waits >= 1, qPrintable(def.displayName));  // the segment's own action, where the plan runs it
            if (def.kind == AlgorithmKind::Circle) {
                for (size_t i = 1; i < items.size(); ++i) {
                    const GeoPoint at{items[i].latitude, items[i].longitude};
                    QVERIFY(std::abs(geodesicDistance(a, at) - 35.5) < 1.0);
                }
            }
            if (def.kind == AlgorithmKind::Photogrammetry) {
                QCOMPARE(items[1].actions.front(), (MissionAction{QStringLiteral("gimbal"), {{QStringLiteral("tilt"), 90 * kRad},
                                                                                             {QStringLiteral("roll"), 0.0},
                                                                                             {QStringLiteral("yaw"), 0.0}}}));
                bool series = false;
                for (const MissionItem &item : items)
                    for (const MissionAction &action : item.actions)
                        series |= action.type == QLatin1String("camera_by_distance")
                                  && action.parameters.value(QStringLiteral("interval")).toDouble() > 0;
                QVERIFY(series);
            }
            ++planned;
        }
        QVERIFY(planned >= 9);
        // A tool Sortie does not know cannot be planned here: refused, naming it.
        AlgorithmSegment unknown;
        unknown.algorithm = QStringLiteral("com.example.SpiralAlgorithm");
        unknown.points = {{a, 30, AltitudeType::Agl}};
        const auto refused = vehicle::vciMissionFor(route({waypoint(56.949, 24.10, 30), unknown}));
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.startsWith(QLatin1String("Spiral 2: only a UgCS server that knows com.example.SpiralAlgorithm can plan it")), qPrintable(refused.error().message));
    }

    void readBackComparison()
    {
        std::vector<MissionItem> sent = {{0.99, 0.42, 30, 5, 0, {}}, {0.9901, 0.4201, 40, 0, 3, {{QStringLiteral("wait"), {{QStringLiteral("seconds"), 2.0}}}}}};
        std::vector<MissionItem> back = sent;
        back[1].speed = 8; // the vehicle's default filled in where none was given
        QVERIFY(vehicle::missionDifference(sent, back).isEmpty());
        back[1].altitude = 45;
        QCOMPARE(vehicle::missionDifference(sent, back), QStringLiteral("waypoint 2: altitude 45 m, sent 40 m"));
        back = sent;
        back[0].speed = 6;
        QVERIFY(vehicle::missionDifference(sent, back).startsWith(QLatin1String("waypoint 1: speed")));
        back = sent;
        back[1].actions[0].parameters[QStringLiteral("seconds")] = 3.0;
        QCOMPARE(vehicle::missionDifference(sent, back), QStringLiteral("waypoint 2: action 1 (wait) differs"));
        back = sent;
        back.pop_back();
        QCOMPARE(vehicle::missionDifference(sent, back), QStringLiteral("the vehicle holds 1 waypoint(s), 2 were sent"));
        back = sent;
        back[0].latitude += 1e-6;
        QVERIFY(vehicle::missionDifference(sent, back).contains(QLatin1String("another position")));
    }

    void vciMissionCodecWithActions()
    {
        namespace profile = vci::profile;
        profile::Waypoint w{0.99, 0.42, 30, 5, 2.5, {}};
        w.actions.push_back({"wait", {{"seconds", 4}}});
        w.actions.push_back({"camera", {{"state", "start_recording"}}});
        w.actions.push_back({"land", nlohmann::json::object()});
        const nlohmann::json body = profile::encodeMission({w, profile::Waypoint{0.991, 0.421, 20, 0, 0, {}}});
        QCOMPARE(body["waypoints"][0]["acceptanceRadius"].get<double>(), 2.5);
        QCOMPARE(body["waypoints"][0]["actions"][1]["type"].get<std::string>(), std::string("camera"));
        QVERIFY(!body["waypoints"][1].contains("actions")); // nothing to say, nothing sent
        std::string error;
        const auto back = profile::decodeMission(body, &error);
        QVERIFY2(back, error.c_str());
        QCOMPARE((*back)[0].actions.size(), size_t(3));
        QCOMPARE((*back)[0].actions[0].fields["seconds"].get<double>(), 4.0);
        QCOMPARE((*back)[0].acceptanceRadius, 2.5);

        auto refused = [](const char *text) {
            std::string why;
            return profile::decodeMission(nlohmann::json::parse(text), &why) ? std::string() : why;
        };
        const char *base = R"({"waypoints":[{"latitude":0.9,"longitude":0.4,"altitude":10,"actions":[%1]}]})";
        auto with = [base](const char *action) { return QString::fromLatin1(base).arg(QLatin1String(action)).toStdString(); };
        QCOMPARE(refused(with(R"({"type":"dance"})").c_str()), std::string("waypoints[0].actions[0].type: \"dance\" is not an action of this profile"));
        QCOMPARE(refused(with(R"({"type":"wait"})").c_str()), std::string("waypoints[0].actions[0].seconds: missing"));
        QCOMPARE(refused(with(R"({"type":"wait","seconds":-1})").c_str()), std::string("waypoints[0].actions[0].seconds: must be a number, 0 or more"));
        QCOMPARE(refused(with(R"({"type":"camera","state":"burst"})").c_str()), std::string("waypoints[0].actions[0].state: not one of the names the profile lists"));
        QCOMPARE(refused(with(R"({"type":"gimbal","tilt":1.57})").c_str()), std::string());
        QCOMPARE(refused(with(R"({"type":"gimbal","zoom":-1})").c_str()), std::string("waypoints[0].actions[0].zoom: must be a number, 0 or more"));
        QCOMPARE(refused(with(R"(5)").c_str()), std::string("waypoints[0].actions[0]: must be an object"));
        QCOMPARE(refused(R"({"waypoints":[{"latitude":0.9,"longitude":0.4,"altitude":10,"acceptanceRadius":-2}]})"),
                 std::string("waypoints[0].acceptanceRadius: must be a number of metres, 0 or more"));
    }

    void commandLogRecordsAndAges()
    {
        vehicle::CommandLog log(nullptr, 3);
        QSignalSpy recorded(&log, &vehicle::CommandLog::recorded);
        QSignalSpy finished(&log, &vehicle::CommandLog::finished);
        const int arm = log.begin(QStringLiteral("EMU-101"), QStringLiteral("arm"));
        QCOMPARE(log.count(), 1);
        QCOMPARE(recorded.count(), 1);
        QCOMPARE(log.index(0).data(vehicle::CommandLog::StatusTextRole).toString(), QStringLiteral("sent"));
        log.finish(arm, vehicle::CommandResult::failure(QStringLiteral("arm: no GPS fix")));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(log.at(0).status, vehicle::CommandLog::Status::Failed);
        QCOMPARE(log.at(0).result, QStringLiteral("arm: no GPS fix"));
        QVERIFY(log.index(0).data(vehicle::CommandLog::TextRole).toString().endsWith(QLatin1String("EMU-101: arm failed: arm: no GPS fix")));
        log.finish(arm, vehicle::CommandResult::success()); // answered once only
        QCOMPARE(finished.count(), 1);
        auto done = log.track(QStringLiteral("EMU-102"), QStringLiteral("land"));
        done(vehicle::CommandResult::success());
        QCOMPARE(log.at(1).status, vehicle::CommandLog::Status::Done);
        log.track(QStringLiteral("EMU-102"), QStringLiteral("upload"))(vehicle::CommandResult::cancel());
        QCOMPARE(log.at(2).status, vehicle::CommandLog::Status::Cancelled);
        log.begin(QStringLiteral("EMU-103"), QStringLiteral("arm"));
        QCOMPARE(log.count(), 3); // the oldest aged out
        QCOMPARE(log.at(0).vehicle, QStringLiteral("EMU-102"));
        QVERIFY(!log.find(arm));
        log.finish(arm, vehicle::CommandResult::success()); // aged out: nothing happens
        QCOMPARE(finished.count(), 3);
    }

private:
    QTemporaryDir m_settings;
};

QTEST_MAIN(TestUploadRules)
#include "tst_uploadrules.moc"
