// The waypoint actions' editor model: what it shows of a selection, and that every change goes
// through the RouteEditor (checked, one undo step) to the right waypoints.
#include "Domain.pb.h"
#include "HciActionMapper.h"
#include "MavlinkMission.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "ServerActions.h"
#include "WaypointActionsModel.h"

#include <QAbstractItemModelTester>
#include <QLocale>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace sortie::mission;
namespace pb = com::ugcs::ucs::proto;

namespace {
struct Fixture
{
    RouteModel model;
    QUndoStack stack;
    RouteEditor editor{&model, &stack};
    WaypointActionsModel actions{&model, &editor};
    QAbstractItemModelTester tester{&actions, QAbstractItemModelTester::FailureReportingMode::QtTest};
    Fixture()
    {
        Route r;
        for (int i = 0; i < 3; ++i) {
            Waypoint w;
            w.position = {56.95 + 0.001 * i, 24.10};
            r.segments.push_back(w);
        }
        model.resetRoute(r);
    }
    const std::vector<WaypointAction> &at(int row) const { return std::get<Waypoint>(model.segment(row)).actions; }
    // The field as the view reads it: through the model's FieldsRole, a list of typed rows.
    ActionFieldRow field(int action, const QString &name) const
    {
        for (const QVariant &f : actions.index(action).data(WaypointActionsModel::FieldsRole).toList())
            if (f.value<ActionFieldRow>().name == name)
                return f.value<ActionFieldRow>();
        return {};
    }
};
} // namespace

class TestWaypointActions : public QObject
{
    Q_OBJECT
private slots:
    void addToTheSelectionAndEditTheFields()
    {
        Fixture f;
        f.actions.setRows({0, 2});
        QVERIFY(f.actions.isValid());
        QCOMPARE(f.actions.title(), QStringLiteral("Actions at 2 waypoints"));
        QCOMPARE(f.actions.rowCount(), 0);
        QVERIFY(f.actions.add(QStringLiteral("cameraSeriesByDistance")));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(f.at(0).size(), size_t(1));
        QCOMPARE(f.at(2).size(), size_t(1));
        QVERIFY(f.at(1).empty());
        QCOMPARE(f.actions.rowCount(), 1);
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).value.toDouble(), 10.0);
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).unit, QStringLiteral("m"));

        // A field typed as text, as an editor sends it: both waypoints, one more undo step.
        QVERIFY(f.actions.setField(0, QStringLiteral("intervalMeters"), QStringLiteral("25")));
        QCOMPARE(f.stack.count(), 2);
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(0)[0]).intervalMeters, 25.0);
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(2)[0]).intervalMeters, 25.0);
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::SummaryRole).toString(), QStringLiteral("Photo every 25 m"));

        // Typed in German: "12,5" is twelve and a half (a dot is read too).
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        const bool german = f.actions.setField(0, QStringLiteral("intervalMeters"), QStringLiteral("12,5"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        QVERIFY2(german, qPrintable(f.actions.problem()));
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(0)[0]).intervalMeters, 12.5);
        f.stack.undo();

        f.stack.undo();
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(2)[0]).intervalMeters, 10.0);
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).value.toDouble(), 10.0);
    }

    void badValuesAreRefusedWithAReason()
    {
        Fixture f;
        f.actions.setRows({1});
        QVERIFY(f.actions.add(QStringLiteral("wait")));
        QSignalSpy problem(&f.actions, &WaypointActionsModel::problemChanged);
        for (const QVariant &bad : {QVariant(QStringLiteral("-3")), QVariant(QStringLiteral("soon")), QVariant(QString())}) {
            QVERIFY(!f.actions.setField(0, QStringLiteral("seconds"), bad));
            QVERIFY2(!f.actions.problem().isEmpty(), qPrintable(bad.toString()));
        }
        QVERIFY(!problem.isEmpty());
        QCOMPARE(f.stack.count(), 1);  // only the add
        QCOMPARE(std::get<WaitAction>(f.at(1)[0]).seconds, 0.0);
        QVERIFY(!f.actions.setField(0, QStringLiteral("nonsense"), 1));
        QVERIFY(!f.actions.add(QStringLiteral("teleport")));
        QVERIFY(f.actions.problem().contains(QStringLiteral("teleport")));
        // A good value clears the problem.
        QVERIFY(f.actions.setField(0, QStringLiteral("waitForOperator"), true));
        QVERIFY(f.actions.problem().isEmpty());
        QVERIFY(std::get<WaitAction>(f.at(1)[0]).waitForOperator);
        QVERIFY(!f.actions.setField(0, QStringLiteral("seconds"), QStringLiteral("1e9")));
    }

    void aMixedSelectionIsNeverOverwritten()
    {
        Fixture f;
        f.actions.setRows({0});
        QVERIFY(f.actions.add(QStringLiteral("wait")));
        f.actions.setRows({1});
        QVERIFY(f.actions.add(QStringLiteral("heading")));
        // Both selected, waypoint 1 first: its wait is shown; waypoint 2's heading is kept.
        f.actions.setRows({0, 1});
        QVERIFY(f.actions.isMixed());
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::KindRole).toString(), QStringLiteral("wait"));
        QVERIFY(f.actions.setField(0, QStringLiteral("seconds"), 4));
        QCOMPARE(std::get<WaitAction>(f.at(0)[0]).seconds, 4.0);
        QVERIFY(std::holds_alternative<HeadingAction>(f.at(1)[0]));
        f.actions.remove(0);
        QVERIFY(f.at(0).empty());
        QCOMPARE(f.at(1).size(), size_t(1));
        // Added goes to all; clear clears all.
        QVERIFY(f.actions.add(QStringLiteral("panorama")));
        QCOMPARE(f.at(0).size(), size_t(1));
        QCOMPARE(f.at(1).size(), size_t(2));
        f.actions.clear();
        QVERIFY(f.at(0).empty() && f.at(1).empty());
    }

    void aGimbalValueMayBeLeftUnset()
    {
        Fixture f;
        f.actions.setRows({0});
        QVERIFY(f.actions.add(QStringLiteral("cameraControl")));
        QVERIFY(f.field(0, QStringLiteral("tiltDeg")).optional);
        QVERIFY(!f.field(0, QStringLiteral("tiltDeg")).hasValue());  // shown empty, not 0
        QCOMPARE(f.field(0, QStringLiteral("tiltDeg")).text, QString());
        QVERIFY(f.actions.setField(0, QStringLiteral("tiltDeg"), QStringLiteral("90")));
        QCOMPARE(std::get<CameraControlAction>(f.at(0)[0]).tiltDeg, std::optional<double>(90));
        QVERIFY(!std::get<CameraControlAction>(f.at(0)[0]).yawDeg);
        QVERIFY(!f.actions.setField(0, QStringLiteral("tiltDeg"), QStringLiteral("200")));
        QVERIFY(f.actions.setField(0, QStringLiteral("tiltDeg"), QString()));
        QVERIFY(!std::get<CameraControlAction>(f.at(0)[0]).tiltDeg);
    }

    void choicesAndTogglesAndWhatIsNotAWaypoint()
    {
        Fixture f;
        f.actions.setRows({2});
        QVERIFY(f.actions.add(QStringLiteral("cameraTrigger")));
        const ActionFieldRow state = f.field(0, QStringLiteral("state"));
        QVERIFY(state.isChoice() && !state.isNumber() && !state.isToggle());
        QCOMPARE(state.value.toString(), QStringLiteral("singleShot"));
        // The choice shown is the value's, worded for the operator; its value is what setField takes.
        QVERIFY(state.choiceIndex >= 0);
        QCOMPARE(state.choiceValues.value(state.choiceIndex), QStringLiteral("singleShot"));
        QCOMPARE(state.choiceTexts.size(), state.choiceValues.size());
        QVERIFY(f.actions.setField(0, QStringLiteral("state"), QStringLiteral("startRecording")));
        QCOMPARE(std::get<CameraTriggerAction>(f.at(2)[0]).state, TriggerState::StartRecording);
        QVERIFY(!f.actions.setField(0, QStringLiteral("state"), QStringLiteral("explode")));
        // The model follows the route: undoing the add empties it.
        f.stack.undo();
        f.stack.undo();
        QCOMPARE(f.actions.rowCount(), 0);
        // Rows that are not waypoints (out of range here) give no editor.
        f.actions.setRows({7});
        QVERIFY(!f.actions.isValid());
        QVERIFY(!f.actions.add(QStringLiteral("wait")));
    }

    void theServersActionsHaveEditorsFromTheSchema()
    {
        // Every action in the facts Sortie has no type for is offered, with its fields as the schema types them.
        Fixture f;
        QStringList offered;
        for (const ActionKindChoice &k : f.actions.kindChoices())
            offered << k.kind;
        QCOMPARE(f.actions.kindLabels().size(), f.actions.kindChoices().size());
        for (const char *kind : {"setServo", "repeatServo", "transitionFixed", "transitionVtol", "lidarRecordingControl",
                                 "lidarCalibration", "hopAction", "drop"})
            QVERIFY2(offered.contains(QLatin1String(kind)), kind);
        QVERIFY(!offered.contains(QStringLiteral("segment")));
        const ActionKindDescription *servo = actionKindDescription(QStringLiteral("repeatServo"));
        QVERIFY(servo);
        QStringList names;
        for (const ActionField &field : servo->fields)
            names << field.name;
        QCOMPARE(names, (QStringList{"servoId", "pwm", "delay", "count"}));  // not id, version or tag
        QCOMPARE(servo->fields[1].type, ActionField::Type::Integer);
        QCOMPARE(servo->fields[1].unit, QStringLiteral("µs"));
        QCOMPARE(servo->fields[2].type, ActionField::Type::Number);
        const ActionKindDescription *lidar = actionKindDescription(QStringLiteral("lidarRecordingControl"));
        QVERIFY(lidar);
        QCOMPARE(lidar->fields.size(), size_t(1));
        QCOMPARE(lidar->fields[0].type, ActionField::Type::Choice);
        QCOMPARE(lidar->fields[0].choices, (std::vector<std::pair<QString, QString>>{{"RS_OFF", "Off"}, {"RS_ON", "On"}}));
        QVERIFY(actionKindDescription(QStringLiteral("drop"))->fields.empty());
    }

    void aServersServoIsEditedInItsOwnTerms()
    {
        Fixture f;
        pb::ActionDefinition sent;
        sent.set_id(77);
        sent.mutable_repeatservodefinition()->set_servoid(3);
        sent.mutable_repeatservodefinition()->set_pwm(1900);
        sent.mutable_repeatservodefinition()->set_tag("winch");
        sent.mutable_repeatservodefinition()->mutable_unknown_fields()->AddVarint(99, 5);
        Route r = f.model.route();
        std::get<Waypoint>(r.segments[1]).actions.push_back(actionFromHci(sent));
        f.model.resetRoute(r);
        f.actions.setRows({1});
        QCOMPARE(f.actions.rowCount(), 1);
        QVERIFY(f.actions.index(0).data(WaypointActionsModel::EditableRole).toBool());
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::KindRole).toString(), QStringLiteral("repeatServo"));
        QCOMPARE(f.field(0, QStringLiteral("pwm")).value.toInt(), 1900);
        // Not sent: shown as missing, never as 0.
        QVERIFY(!f.field(0, QStringLiteral("count")).hasValue());

        QVERIFY(f.actions.setField(0, QStringLiteral("pwm"), QStringLiteral("1100")));
        QVERIFY(f.actions.setField(0, QStringLiteral("count"), QStringLiteral("4")));
        QCOMPARE(f.stack.count(), 2);
        const auto definitionAt = [&f] {
            const QByteArray &bytes = std::get<ServerAction>(f.at(1)[0]).definition;
            pb::ActionDefinition d;
            d.ParseFromArray(bytes.constData(), int(bytes.size()));
            return d;
        };
        QCOMPARE(definitionAt().repeatservodefinition().pwm(), 1100);
        QCOMPARE(definitionAt().repeatservodefinition().count(), 4);
        // What the editor does not touch goes back as it came: the id, the tag, the unknown field.
        QCOMPARE(definitionAt().id(), 77);
        QCOMPARE(definitionAt().repeatservodefinition().tag(), std::string("winch"));
        QCOMPARE(definitionAt().repeatservodefinition().unknown_fields().field_count(), 1);
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::SummaryRole).toString(),
                 QStringLiteral("Repeat servo: servo 3, PWM 1100 µs, repeats 4"));

        // Out of range or not whole: refused with a reason, nothing changes.
        QVERIFY(!f.actions.setField(0, QStringLiteral("pwm"), QStringLiteral("1500.5")));
        QVERIFY(f.actions.problem().contains(QStringLiteral("whole number")));
        QVERIFY(!f.actions.setField(0, QStringLiteral("servoId"), QStringLiteral("-1")));
        QCOMPARE(f.stack.count(), 2);
        // An emptied field is unset again: the server's default applies.
        QVERIFY(f.actions.setField(0, QStringLiteral("count"), QString()));
        QVERIFY(!definitionAt().repeatservodefinition().has_count());

        // Undo gives back the server's bytes exactly.
        f.stack.undo();
        f.stack.undo();
        f.stack.undo();
        QCOMPARE(definitionAt().SerializeAsString(), sent.SerializeAsString());
        pb::ActionDefinition back = sent;
        actionToHci(f.at(1)[0], back);
        QCOMPARE(back.SerializeAsString(), sent.SerializeAsString());
    }

    void anyServerActionCanBeAddedAndGoesToTheServer()
    {
        Fixture f;
        f.actions.setRows({0, 2});
        QVERIFY(f.actions.add(QStringLiteral("lidarRecordingControl")));
        QVERIFY(f.actions.add(QStringLiteral("drop")));
        QCOMPARE(f.at(2).size(), size_t(2));
        QVERIFY(!f.field(0, QStringLiteral("targetState")).hasValue());
        QVERIFY(f.actions.setField(0, QStringLiteral("targetState"), QStringLiteral("RS_ON")));
        QVERIFY(!f.actions.setField(0, QStringLiteral("targetState"), QStringLiteral("RS_MAYBE")));
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::SummaryRole).toString(), QStringLiteral("Lidar recording: recording on"));
        QCOMPARE(f.actions.index(1).data(WaypointActionsModel::SummaryRole).toString(), QStringLiteral("Drop payload"));
        for (int row : {0, 2}) {
            pb::ActionDefinition lidar, drop;
            actionToHci(f.at(row)[0], lidar);
            actionToHci(f.at(row)[1], drop);
            QCOMPARE(lidar.lidarrecordingcontroldefinition().targetstate(), pb::RS_ON);
            QVERIFY(drop.has_dropdefinition());  // present, though it has nothing to set
            QCOMPARE(actionKindName(actionFromHci(drop)), QStringLiteral("drop"));
        }
    }

    void servosAndTransitionsAreMavlinkCommands()
    {
        Route r;
        Waypoint w;
        w.position = {56.95, 24.10};
        w.actions.push_back(*makeServerAction(QStringLiteral("setServo"), {{"servoId", 9}, {"pwm", 1750}}));
        w.actions.push_back(*makeServerAction(QStringLiteral("repeatServo"), {{"servoId", 10}, {"pwm", 1200}, {"count", 3}, {"delay", 2.5}}));
        w.actions.push_back(*makeServerAction(QStringLiteral("transitionFixed"), {}));
        w.actions.push_back(*makeServerAction(QStringLiteral("hopAction"), {{"descentAltitude", 5}}));
        r.segments.push_back(w);
        const formats::MavlinkExport out = formats::routeToMavlink(r, 5.0);
        std::vector<int> commands;
        for (const formats::MavlinkItem &i : out.items)
            commands.push_back(i.command);
        QCOMPARE(commands, (std::vector<int>{formats::mav::NavWaypoint, 183, 184, 3000}));
        QCOMPARE(out.items[1].param[0], 9.0);
        QCOMPARE(out.items[1].param[1], 1750.0);
        QCOMPARE(out.items[2].param[3], 2.5);
        QCOMPARE(out.items[3].param[0], 4.0);  // MAV_VTOL_STATE_FW
        QVERIFY(out.notices.join(u' ').contains(QStringLiteral("Hop")));  // no MAVLink form: said, not silently dropped

        const auto back = formats::routeFromMavlink(out.items, std::nullopt, 5.0);
        QVERIFY(back.ok());
        const auto &actions = std::get<Waypoint>(back.value().route.segments[0]).actions;
        QCOMPARE(actions.size(), size_t(3));
        QCOMPARE(actions[0], w.actions[0]);
        QCOMPARE(actions[1], w.actions[1]);
        QCOMPARE(actions[2], w.actions[2]);
    }
};

QTEST_GUILESS_MAIN(TestWaypointActions)
#include "tst_waypointactions.moc"
