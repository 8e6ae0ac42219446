// RouteModel and RouteEditor, the one entry point for edits: every edit undoes back to the start
// and redoes to the end, the steps of a gesture (EditStep::Continuing ... Done) merge into one
// undo step and nothing else merges, bulk edits touch only the selection, parameters go by wire
// name through the one reader, the model stays consistent (QAbstractItemModelTester) and
// persistent indexes follow reordering.
#include "RouteEditor.h"
#include "RouteModel.h"
#include "Geodesy.h"
#include "SegmentParameters.h"

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
        f.editor.addWaypoint(QGeoCoordinate(57.0, 24.2));
        f.editor.insertWaypoint(0, QGeoCoordinate(56.8, 24.0));
        f.editor.moveWaypoints({2}, {QGeoCoordinate(56.95, 24.15)});
        f.editor.removeRows({1, 3, 4});
        f.editor.moveRows({0, 2}, 4);
        f.editor.reverse();
        f.editor.setAltitude({0, 1}, 80);
        f.editor.setAltitudeType({1, 2}, AltitudeType::Amsl);
        f.editor.setSpeed({2}, 7.5);
        f.editor.setTurnType({0}, TurnType::Spline);
        f.editor.setAcceptanceRadius({0, 1, 2}, 3);
        QVERIFY(f.editor.addAction({0, 2}, {{"kind", "wait"}, {"seconds", 5}}));
        QVERIFY(f.editor.addAction({2}, {{"kind", "cameraSeriesByDistance"}, {"intervalMeters", 20}}));
        f.editor.removeAction({0}, 0);
        f.editor.clearActions({2});
        const int scan = f.editor.addAreaScan({QGeoCoordinate(56.9, 24.1), QGeoCoordinate(56.91, 24.1), QGeoCoordinate(56.91, 24.12)});
        QVERIFY(scan >= 0);
        QVERIFY(f.editor.setParameter({scan}, QStringLiteral("overlapSide"), 70.0));
        QVERIFY(f.editor.moveVertex(scan, 1, QGeoCoordinate(56.912, 24.1)));
        QVERIFY(f.editor.insertVertex(scan, 3, QGeoCoordinate(56.905, 24.125)));
        QVERIFY(f.editor.removeVertex(scan, 0));
        QVERIFY(f.editor.setRouteProperty(QStringLiteral("maxAltitude"), 90));
        Route replacement = sampleRoute(2);
        f.editor.replaceRoute(replacement, QStringLiteral("Import"));
        f.editor.addWaypoint(QGeoCoordinate(10, 10));
        const Route end = f.model.route();
        QCOMPARE(f.stack.count(), 23);

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

    void gestureStepsMergeIntoOneUndo()
    {
        Fixture f;
        const GeoPoint origin = wp(f.model, 2).position;
        for (int i = 1; i < 30; ++i)
            QVERIFY(f.editor.moveWaypoints({2}, {QGeoCoordinate(56.9 + i * 1e-4, 24.1)}, EditStep::Continuing));
        QVERIFY(f.editor.moveWaypoints({2}, {QGeoCoordinate(56.9 + 30 * 1e-4, 24.1)}, EditStep::Done));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(wp(f.model, 2).position.latitude, 56.9 + 30 * 1e-4);
        // The same point again, a new gesture: a new step.
        f.editor.moveWaypoints({2}, {QGeoCoordinate(56.0, 24.0)}, EditStep::Continuing);
        f.editor.moveWaypoints({2}, {QGeoCoordinate(56.1, 24.0)});
        QCOMPARE(f.stack.count(), 2);
        // One-shot edits (a typed coordinate) never merge, even of the same point.
        f.editor.setLatitude(1, 57.0);
        f.editor.setLatitude(1, 57.1);
        QCOMPARE(f.stack.count(), 4);
        // Within a gesture only the same edit of the same rows merges.
        f.editor.setAltitude({3}, 60, EditStep::Continuing);
        f.editor.setAltitude({4}, 61, EditStep::Continuing);
        f.editor.setAltitude({4}, 62, EditStep::Done);
        QCOMPARE(f.stack.count(), 6);
        QCOMPARE(wp(f.model, 4).altitude, 62.0);
        f.stack.undo();
        QCOMPARE(wp(f.model, 4).altitude, 44.0);
        f.stack.setIndex(1);
        QCOMPARE(wp(f.model, 2).position.latitude, 56.9 + 30 * 1e-4);
        f.stack.undo();
        QVERIFY(wp(f.model, 2).position == origin);
    }

    void areaScanCornersFollowAGesture()
    {
        Fixture f(1);
        const int row = f.editor.addAreaScan({QGeoCoordinate(56.90, 24.10), QGeoCoordinate(56.90, 24.11),
                                              QGeoCoordinate(56.905, 24.11), QGeoCoordinate(56.905, 24.10)});
        QCOMPARE(row, 1);
        QCOMPARE(f.stack.count(), 1);
        const auto planBefore = f.model.scanPlan(row);
        QVERIFY(planBefore && planBefore->ok());
        for (int i = 1; i <= 10; ++i)  // the corner is dragged outwards; the plan follows every step
            QVERIFY(f.editor.moveVertex(row, 2, QGeoCoordinate(56.905 + i * 2e-4, 24.11 + i * 2e-4),
                                        i < 10 ? EditStep::Continuing : EditStep::Done));
        QCOMPARE(f.stack.count(), 2);
        const auto &scan = std::get<AreaScan>(f.model.segment(row));
        QCOMPARE(scan.polygon[2].latitude, 56.905 + 10 * 2e-4);
        const auto planAfter = f.model.scanPlan(row);
        QVERIFY(planAfter && planAfter->ok());
        QVERIFY(planAfter->plan->areaSquareMeters > planBefore->plan->areaSquareMeters);
        QVERIFY(f.editor.insertVertex(row, 2, QGeoCoordinate(56.902, 24.113)));
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).polygon.size(), size_t(5));
        QVERIFY(f.editor.removeVertex(row, 0));
        QVERIFY(f.editor.removeVertex(row, 0));
        QSignalSpy refused(&f.editor, &RouteEditor::refused);
        QVERIFY(!f.editor.removeVertex(row, 0));  // three corners stay
        QCOMPARE(refused.count(), 1);
        QVERIFY(!f.editor.moveVertex(row, 7, QGeoCoordinate(56.9, 24.1)));
        QVERIFY(!f.editor.moveVertex(0, 0, QGeoCoordinate(56.9, 24.1)));  // a waypoint has no corners
        QCOMPARE(refused.count(), 3);
        f.stack.setIndex(1);
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).polygon[2].latitude, 56.905);
    }

    void aFigureDraggedByItsMarkerMovesWhole()
    {
        // The map drags a segment's route marker through moveWaypoints: the figure moves with it,
        // its shape and size kept, in one undo step per gesture.
        Fixture f(1);
        const int row = f.editor.addAreaScan({QGeoCoordinate(56.90, 24.10), QGeoCoordinate(56.90, 24.11),
                                              QGeoCoordinate(56.905, 24.11), QGeoCoordinate(56.905, 24.10)});
        const std::vector<GeoPoint> before = std::get<AreaScan>(f.model.segment(row)).polygon;
        const int steps = f.stack.count();
        QVERIFY(f.editor.moveWaypoints({row}, {QGeoCoordinate(56.91, 24.12)}, EditStep::Continuing));
        QVERIFY(f.editor.moveWaypoints({row}, {QGeoCoordinate(56.95, 24.30)}, EditStep::Done));
        QCOMPARE(f.stack.count(), steps + 1);
        const std::vector<GeoPoint> after = std::get<AreaScan>(f.model.segment(row)).polygon;
        QCOMPARE(after.size(), before.size());
        QVERIFY(geodesicDistance(after[0], {56.95, 24.30}) < 1e-3);
        for (size_t i = 0; i < before.size(); ++i)
            for (size_t j = i + 1; j < before.size(); ++j)
                QVERIFY2(std::abs(geodesicDistance(after[i], after[j]) - geodesicDistance(before[i], before[j])) < 0.05,
                         qPrintable(QStringLiteral("corners %1-%2").arg(i).arg(j)));
        f.stack.undo();
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).polygon, before);
        QSignalSpy refused(&f.editor, &RouteEditor::refused);
        QVERIFY(!f.editor.moveWaypoints({9}, {QGeoCoordinate(56.9, 24.1)}));
        QCOMPARE(refused.count(), 1);
    }

    void areaScanParametersByWireName()
    {
        Fixture f(2);
        QSignalSpy added(&f.editor, &RouteEditor::rowsAdded);
        const int row = f.editor.addAreaScan({QGeoCoordinate(56.90, 24.10), QGeoCoordinate(56.90, 24.11), QGeoCoordinate(56.905, 24.11)});
        QCOMPARE(row, 2);
        QCOMPARE(added.count(), 1);
        QCOMPARE(added.at(0).at(0).toInt(), 2);
        const QModelIndex i = f.model.index(row);
        QCOMPARE(i.data(RouteModel::KindRole).toString(), QStringLiteral("areaScan"));
        QCOMPARE(i.data(RouteModel::PolygonRole).toList().size(), 3);
        auto plan = f.model.scanPlan(row);
        QVERIFY(plan && plan->ok());
        const int photosBefore = plan->plan->photoCount;
        QVERIFY(photosBefore > 0);
        QCOMPARE(plan->plan->path.size(), 4 * plan->plan->transects.size());
        QVERIFY(!f.model.scanPlan(0));  // a waypoint has no plan

        QVERIFY(f.editor.setParameter({row}, QStringLiteral("groundSampleDistance"), 1.0));
        QVERIFY(f.editor.setParameter({row}, QStringLiteral("overlapForward"), 80));
        const QVariantMap params = i.data(RouteModel::ScanParametersRole).toMap();
        QCOMPARE(params.value("groundSampleDistance").toDouble(), 1.0);
        QVERIFY(params.value("height").toDouble() < 40);  // 1 cm/px needs to fly lower than 60 m
        plan = f.model.scanPlan(row);
        QVERIFY(plan->plan->photoCount > photosBefore);
        QSignalSpy refused(&f.editor, &RouteEditor::refused);
        QVERIFY(!f.editor.setParameter({row}, QStringLiteral("overlapSide"), QStringLiteral("lots")));
        QVERIFY(!f.editor.setParameter({row}, QStringLiteral("overlapSide"), 100));
        QVERIFY(!f.editor.setParameter({row}, QStringLiteral("teleport"), 1));
        QCOMPARE(refused.count(), 3);
        QVERIFY(refused.at(1).at(0).toString().contains(QStringLiteral("overlapSide")));
        QCOMPARE(f.stack.count(), 3);
        // A selection of a waypoint and the scan: the speed goes to both, the overlap to the scan.
        QVERIFY(f.editor.setParameter({0, row}, QStringLiteral("speed"), 6.5));
        QCOMPARE(wp(f.model, 0).speed, 6.5);
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).parameters.speed, 6.5);
        // sideDistance sets the spacing directly.
        QVERIFY(f.editor.setParameter({row}, QStringLiteral("sideDistance"), 25.0));
        QCOMPARE(f.model.scanPlan(row)->plan->transectSpacing, 25.0);
        f.stack.undo();
        f.stack.undo();
        f.stack.undo();
        f.stack.undo();
        QCOMPARE(f.model.scanPlan(row)->plan->photoCount, photosBefore);
    }

    void parameterReaderTakesTypedAndWireValues()
    {
        Segment scan = AreaScan{};
        QString error;
        QVERIFY(setParameterValue(scan, QStringLiteral("overlapSide"), QStringLiteral("70.0"), &error));
        QVERIFY(setParameterValue(scan, QStringLiteral("altitudeType"), QStringLiteral("WGS84"), &error));
        QCOMPARE(std::get<AreaScan>(scan).parameters.altitudeType, AltitudeType::Amsl);
        QVERIFY(setParameterValue(scan, QStringLiteral("altitudeType"), QVariant::fromValue(AltitudeType::Agl), &error));
        QVERIFY(setParameterValue(scan, QStringLiteral("directionAngle"), -90, &error));
        QCOMPARE(std::get<AreaScan>(scan).parameters.directionDeg, 270.0);
        QVERIFY(!setParameterValue(scan, QStringLiteral("overlapForward"), true, &error));  // a bool is no number
        QVERIFY(!setParameterValue(scan, QStringLiteral("height"), QStringLiteral("high"), &error));
        QVERIFY(error.contains(QStringLiteral("height")));
        QCOMPARE(parameterValue(scan, QStringLiteral("overlapSide")).toDouble(), 70.0);
        QVERIFY(!parameterValue(scan, QStringLiteral("wpTurnType")).isValid());

        Segment w = Waypoint{};
        QVERIFY(setParameterValue(w, QStringLiteral("wpTurnType"), QStringLiteral("BANK_TURN"), &error));
        QCOMPARE(std::get<Waypoint>(w).turnType, TurnType::BankTurn);
        QVERIFY(setParameterValue(w, QStringLiteral("wpTurnType"), 2, &error));  // QML hands enums over as numbers
        QCOMPARE(std::get<Waypoint>(w).turnType, TurnType::Spline);
        QVERIFY(!setParameterValue(w, QStringLiteral("wpTurnType"), QStringLiteral("SIDEWAYS"), &error));
        QCOMPARE(parameterValue(w, QStringLiteral("wpTurnType")).toString(), QStringLiteral("SPLINE"));
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

    void tableCellsAreEditorCalls()
    {
        Fixture f;
        QVERIFY(!(f.model.flags(f.model.index(1)) & Qt::ItemIsEditable));  // read-only: edits go through the editor
        QVERIFY(!f.model.setData(f.model.index(1), 99.0, RouteModel::AltitudeRole));
        QVERIFY(f.editor.setAltitude({1}, 99.0));
        QVERIFY(f.editor.setAltitudeType({1}, AltitudeType::Amsl));
        QVERIFY(f.editor.setLatitude(1, 57.5));
        QVERIFY(!f.editor.setLatitude(1, 91.0));
        QVERIFY(!f.editor.setLatitude(17, 50.0));
        QCOMPARE(f.stack.count(), 3);
        QCOMPARE(wp(f.model, 1).altitude, 99.0);
        QCOMPARE(wp(f.model, 1).altitudeType, AltitudeType::Amsl);
        QCOMPARE(f.model.index(1).data(RouteModel::AltitudeTypeRole).toString(), QStringLiteral("AMSL"));
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
        const int row = f.editor.addWaypoint(QGeoCoordinate(56.95, 24.2));
        QCOMPARE(row, 2);
        QCOMPARE(wp(f.model, 2).altitude, 77.0);
        QCOMPARE(wp(f.model, 2).speed, 6.0);
        QCOMPARE(f.editor.addWaypoint(QGeoCoordinate(95, 0)), -1);
        QCOMPARE(f.editor.addWaypoint(QGeoCoordinate()), -1);
    }
};

QTEST_GUILESS_MAIN(TestRouteModel)
#include "tst_routemodel.moc"
