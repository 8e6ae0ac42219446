// RouteModel and its undo commands: every command undoes back to the start and redoes to the end,
// drags of one point merge, bulk edits touch only the selection, the model stays consistent
// (QAbstractItemModelTester) and persistent indexes follow reordering.
#include "RouteEditor.h"
#include "RouteModel.h"

#include <QAbstractItemModelTester>
#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::mission;

namespace {
Route sampleRoute(int n)
{
    Route r;
    r.settings.name = QStringLiteral("sample");
    for (int i = 0; i < n; ++i) {
        Waypoint w;
        w.position = {56.9 + i * 0.001, 24.1 + i * 0.001};
        w.altitude = 40 + i;
        w.speed = 5;
        r.segments.push_back(w);
    }
    return r;
}

const Waypoint &wp(const RouteModel &m, int row) { return std::get<Waypoint>(m.segment(row)); }

struct Fixture
{
    RouteModel model;
    QUndoStack stack;
    RouteEditor editor{&model, &stack};
    QAbstractItemModelTester tester{&model, QAbstractItemModelTester::FailureReportingMode::QtTest};
    explicit Fixture(int n = 5) { model.resetRoute(sampleRoute(n)); }
};
}

class TestRouteModel : public QObject
{
    Q_OBJECT
private slots:
    void roles()
    {
        Fixture f(3);
        const QModelIndex i = f.model.index(1);
        QCOMPARE(f.model.rowCount(), 3);
        QCOMPARE(i.data(RouteModel::KindRole).toString(), QStringLiteral("waypoint"));
        QCOMPARE(i.data(RouteModel::SequenceRole).toInt(), 2);
        QCOMPARE(i.data(RouteModel::LatitudeRole).toDouble(), 56.901);
        QCOMPARE(i.data(RouteModel::AltitudeRole).toDouble(), 41.0);
        QCOMPARE(i.data(RouteModel::AltitudeTypeRole).toString(), QStringLiteral("AGL"));
        QCOMPARE(i.data(RouteModel::TurnTypeRole).toString(), QStringLiteral("StopAndTurn"));
        QVERIFY(f.model.roleNames().values().contains("actionsSummary"));
    }

    void everyCommandUndoesToTheStartAndRedoesToTheEnd()
    {
        Fixture f(6);
        const Route start = f.model.route();
        f.editor.addWaypoint(57.0, 24.2);
        f.editor.insertWaypoint(0, 56.8, 24.0);
        f.editor.moveWaypoint(2, 56.95, 24.15);
        f.editor.removeRows({1, 3, 4});
        f.editor.moveRows({0, 2}, 4);
        f.editor.reverse();
        f.editor.setAltitude({0, 1}, 80);
        f.editor.setAltitudeType({1, 2}, QStringLiteral("AMSL"));
        f.editor.setSpeed({2}, 7.5);
        f.editor.setTurnType({0}, QStringLiteral("Spline"));
        f.editor.setAcceptanceRadius({0, 1, 2}, 3);
        QVERIFY(f.editor.addAction({0, 2}, {{"kind", "wait"}, {"seconds", 5}}));
        QVERIFY(f.editor.addAction({2}, {{"kind", "cameraSeriesByDistance"}, {"intervalMeters", 20}}));
        f.editor.removeAction({0}, 0);
        f.editor.clearActions({2});
        QVERIFY(f.editor.addAreaScan({QVariantMap{{"latitude", 56.9}, {"longitude", 24.1}},
                                      QVariantMap{{"latitude", 56.91}, {"longitude", 24.1}},
                                      QVariantMap{{"latitude", 56.91}, {"longitude", 24.12}}}) >= 0);
        QVERIFY(f.editor.setRouteProperty(QStringLiteral("maxAltitude"), 90));
        Route replacement = sampleRoute(2);
        f.editor.replaceRoute(replacement, QStringLiteral("Import"));
        f.editor.addWaypoint(10, 10);
        const Route end = f.model.route();
        QCOMPARE(f.stack.count(), 19);

        f.stack.setIndex(0);
        QVERIFY(f.model.route() == start);
        f.stack.setIndex(f.stack.count());
        QVERIFY(f.model.route() == end);
        // And step by step, each undo then redo restores exactly.
        for (int i = f.stack.count(); i > 0; --i) {
            const Route before = f.model.route();
            f.stack.undo();
            f.stack.redo();
            QVERIFY2(f.model.route() == before, qPrintable(f.stack.text(i - 1)));
            f.stack.undo();
        }
        QVERIFY(f.model.route() == start);
    }

    void dragStepsMergeIntoOneUndo()
    {
        Fixture f;
        const GeoPoint origin = wp(f.model, 2).position;
        for (int i = 1; i <= 30; ++i)
            f.editor.moveWaypoint(2, 56.9 + i * 1e-4, 24.1);
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(wp(f.model, 2).position.latitude, 56.9 + 30 * 1e-4);
        f.editor.moveWaypoint(3, 56.0, 24.0);  // another point: a new step
        QCOMPARE(f.stack.count(), 2);
        f.editor.endMove();
        f.editor.moveWaypoint(3, 56.1, 24.0);  // the same point, a new drag: a new step
        f.editor.moveWaypoint(3, 56.2, 24.0);
        QCOMPARE(f.stack.count(), 3);
        f.stack.undo();
        QCOMPARE(wp(f.model, 3).position.latitude, 56.0);
        f.stack.undo();
        f.stack.undo();
        QVERIFY(wp(f.model, 2).position == origin);
        // Typed coordinates never merge.
        QVERIFY(f.model.setData(f.model.index(1), 57.0, RouteModel::LatitudeRole));
        QVERIFY(f.model.setData(f.model.index(1), 57.1, RouteModel::LatitudeRole));
        QCOMPARE(f.stack.count(), 2);
    }

    void areaScanToolEditsThroughMaps()
    {
        Fixture f(2);
        const int row = f.editor.addAreaScan({QVariantMap{{"latitude", 56.90}, {"longitude", 24.10}},
                                              QVariantMap{{"latitude", 56.90}, {"longitude", 24.11}},
                                              QVariantMap{{"latitude", 56.905}, {"longitude", 24.11}}});
        QCOMPARE(row, 2);
        const QModelIndex i = f.model.index(row);
        QCOMPARE(i.data(RouteModel::KindRole).toString(), QStringLiteral("areaScan"));
        QCOMPARE(i.data(RouteModel::PolygonRole).toList().size(), 3);
        QVariantMap plan = i.data(RouteModel::ScanPlanRole).toMap();
        QVERIFY(plan.value("ok").toBool());
        const int photosBefore = plan.value("photoCount").toInt();
        QVERIFY(photosBefore > 0);
        QCOMPARE(plan.value("path").toList().size(), 4 * plan.value("transects").toInt());

        QVERIFY(f.editor.setScanProperties(row, {{"byGroundSampleDistance", true}, {"groundSampleDistanceCm", 1.0},
                                                 {"frontOverlapPercent", 80}}));
        const QVariantMap params = i.data(RouteModel::ScanParametersRole).toMap();
        QCOMPARE(params.value("groundSampleDistanceCm").toDouble(), 1.0);
        QVERIFY(params.value("altitude").toDouble() < 40);  // 1 cm/px needs to fly lower than 60 m
        plan = i.data(RouteModel::ScanPlanRole).toMap();
        QVERIFY(plan.value("photoCount").toInt() > photosBefore);
        QVERIFY(!f.editor.setScanProperties(row, {{"sideOverlapPercent", "lots"}}));
        QVERIFY(!f.editor.setScanProperties(0, {{"sideOverlapPercent", 50}}));  // a waypoint
        QVERIFY(f.editor.setScanProperties(row, {{"sideOverlapPercent", 99}}));
        plan = i.data(RouteModel::ScanPlanRole).toMap();
        QVERIFY(!plan.value("ok").toBool());
        QVERIFY(plan.value("message").toString().contains(QStringLiteral("Overlap")));
        f.stack.undo();
        f.stack.undo();
        QCOMPARE(i.data(RouteModel::ScanPlanRole).toMap().value("photoCount").toInt(), photosBefore);
    }

    void editAnActionOfASelection()
    {
        Fixture f(4);
        QVERIFY(f.editor.addAction({0, 1, 2}, {{"kind", "wait"}, {"seconds", 3}}));
        QVERIFY(f.editor.setAction({1, 2, 3}, 0, {{"kind", "cameraSeriesByTime"}, {"intervalSeconds", 2}}));
        QVERIFY(std::holds_alternative<WaitAction>(wp(f.model, 0).actions[0]));
        QCOMPARE(std::get<CameraSeriesByTimeAction>(wp(f.model, 2).actions[0]).intervalSeconds, 2.0);
        QVERIFY(wp(f.model, 3).actions.empty());  // had no action 0
        QVERIFY(!f.editor.setAction({1}, 0, {{"kind", "teleport"}}));
        QCOMPARE(f.model.index(2).data(RouteModel::ActionsSummaryRole).toString(), QStringLiteral("Photo every 2 s"));
    }

    void selectionModelGivesTheRows()
    {
        Fixture f(6);
        QItemSelectionModel selection(&f.model);
        selection.select(f.model.index(4), QItemSelectionModel::Select);
        selection.select(f.model.index(1), QItemSelectionModel::Select);
        const QList<int> rows = f.editor.rowsOf(&selection);
        QCOMPARE(rows, (QList<int>{1, 4}));
        f.editor.setSpeed(rows, 9);
        QCOMPARE(wp(f.model, 4).speed, 9.0);
        QCOMPARE(wp(f.model, 2).speed, 5.0);
        QItemSelectionModel other;
        QVERIFY(f.editor.rowsOf(&other).isEmpty());
    }

    void setDataGoesThroughTheUndoStack()
    {
        Fixture f;
        QVERIFY(f.model.setData(f.model.index(1), 99.0, RouteModel::AltitudeRole));
        QVERIFY(f.model.setData(f.model.index(1), QStringLiteral("AMSL"), RouteModel::AltitudeTypeRole));
        QVERIFY(f.model.setData(f.model.index(1), 57.5, RouteModel::LatitudeRole));
        QVERIFY(!f.model.setData(f.model.index(1), QStringLiteral("sideways"), RouteModel::TurnTypeRole));
        QVERIFY(!f.model.setData(f.model.index(1), 91.0, RouteModel::LatitudeRole));
        QCOMPARE(f.stack.count(), 3);
        QCOMPARE(wp(f.model, 1).altitude, 99.0);
        QCOMPARE(wp(f.model, 1).altitudeType, AltitudeType::Amsl);
        f.stack.setIndex(0);
        QCOMPARE(wp(f.model, 1).altitude, 41.0);
        QCOMPARE(wp(f.model, 1).position.latitude, 56.901);
    }

    void bulkEditTouchesOnlyTheSelection()
    {
        Fixture f(10);
        QSignalSpy changed(&f.model, &QAbstractItemModel::dataChanged);
        f.editor.setAltitude({2, 3, 7}, 70);
        for (int r = 0; r < 10; ++r)
            QCOMPARE(wp(f.model, r).altitude, (r == 2 || r == 3 || r == 7) ? 70.0 : 40.0 + r);
        QCOMPARE(changed.count(), 2);  // two contiguous runs: 2-3 and 7
        QCOMPARE(f.stack.count(), 1);
        f.editor.setAltitude({2, 3, 7}, 70);  // no change: no undo step
        QCOMPARE(f.stack.count(), 1);
        f.editor.setSpeed({}, 3);
        f.editor.setSpeed({-1, 99}, 3);
        QCOMPARE(f.stack.count(), 1);
    }

    void reorderKeepsPersistentIndexes()
    {
        Fixture f(6);
        const QPersistentModelIndex tracked(f.model.index(4));
        const GeoPoint p = wp(f.model, 4).position;
        f.editor.moveRows({4}, 0);
        QCOMPARE(tracked.row(), 0);
        QVERIFY(wp(f.model, 0).position == p);
        f.editor.reverse();
        QCOMPARE(tracked.row(), 5);
        f.stack.setIndex(0);
        QCOMPARE(tracked.row(), 4);
    }

    void moveSelectionToTheEnd()
    {
        Fixture f(5);
        f.editor.moveRows({0, 2}, 5);
        const std::vector<double> expected{41, 43, 44, 40, 42};
        for (int r = 0; r < 5; ++r)
            QCOMPARE(wp(f.model, r).altitude, expected[size_t(r)]);
    }

    void largeScatteredDeleteUndoes()
    {
        Fixture f(2000);
        const Route start = f.model.route();
        QList<int> every3rd;
        for (int r = 0; r < 2000; r += 3)
            every3rd << r;
        f.editor.removeRows(every3rd);
        QCOMPARE(f.model.count(), 2000 - int(every3rd.size()));
        QCOMPARE(wp(f.model, 0).altitude, 41.0);
        f.stack.undo();
        QVERIFY(f.model.route() == start);
    }

    void newWaypointInheritsFromThePreviousOne()
    {
        Fixture f(2);
        f.editor.setAltitude({1}, 77);
        f.editor.setSpeed({1}, 6);
        const int row = f.editor.addWaypoint(56.95, 24.2);
        QCOMPARE(row, 2);
        QCOMPARE(wp(f.model, 2).altitude, 77.0);
        QCOMPARE(wp(f.model, 2).speed, 6.0);
        QCOMPARE(f.editor.addWaypoint(95, 0), -1);
    }
};

QTEST_GUILESS_MAIN(TestRouteModel)
#include "tst_routemodel.moc"
