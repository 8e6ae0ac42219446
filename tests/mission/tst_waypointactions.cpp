// The waypoint actions' editor model: what it shows of a selection, and that every change goes
// through the RouteEditor (checked, one undo step) to the right waypoints.
#include "RouteEditor.h"
#include "RouteModel.h"
#include "WaypointActionsModel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace sortie::mission;

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
    QVariantMap field(int action, const QString &name) const
    {
        for (const QVariant &f : actions.index(action).data(WaypointActionsModel::FieldsRole).toList())
            if (f.toMap().value(QStringLiteral("name")) == name)
                return f.toMap();
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
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).value(QStringLiteral("value")).toDouble(), 10.0);
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).value(QStringLiteral("unit")).toString(), QStringLiteral("m"));

        // A field typed as text, as an editor sends it: both waypoints, one more undo step.
        QVERIFY(f.actions.setField(0, QStringLiteral("intervalMeters"), QStringLiteral("25")));
        QCOMPARE(f.stack.count(), 2);
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(0)[0]).intervalMeters, 25.0);
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(2)[0]).intervalMeters, 25.0);
        QCOMPARE(f.actions.index(0).data(WaypointActionsModel::SummaryRole).toString(), QStringLiteral("Photo every 25 m"));

        f.stack.undo();
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(f.at(2)[0]).intervalMeters, 10.0);
        QCOMPARE(f.field(0, QStringLiteral("intervalMeters")).value(QStringLiteral("value")).toDouble(), 10.0);
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
        QVERIFY(f.field(0, QStringLiteral("tiltDeg")).value(QStringLiteral("optional")).toBool());
        QVERIFY(!f.field(0, QStringLiteral("tiltDeg")).value(QStringLiteral("value")).isValid());  // shown empty, not 0
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
        const QVariantMap state = f.field(0, QStringLiteral("state"));
        QCOMPARE(state.value(QStringLiteral("type")).toString(), QStringLiteral("choice"));
        QCOMPARE(state.value(QStringLiteral("value")).toString(), QStringLiteral("singleShot"));
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
};

QTEST_GUILESS_MAIN(TestWaypointActions)
#include "tst_waypointactions.moc"
