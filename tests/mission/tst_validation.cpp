// Validation rules (each names its segment and severity), the save/upload gate, route statistics
// and the coalescing analyzer.
#include "Geodesy.h"
#include "LocalTangentPlane.h"
#include "RouteAnalyzer.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "RouteStatistics.h"
#include "RouteValidator.h"
#include "ValidationGate.h"

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::mission;

namespace {
Waypoint at(double lat, double lon, double alt = 50, double speed = 5)
{
    Waypoint w;
    w.position = {lat, lon};
    w.altitude = alt;
    w.speed = speed;
    return w;
}

Route twoPoints()
{
    Route r;
    r.settings.safeAltitude = 20;
    r.settings.maxAltitude = 120;
    r.settings.profile.maxHorizontalSpeed = 10;
    r.segments = {at(56.9, 24.1), at(56.91, 24.1)};
    return r;
}

AreaScan squareScan(const GeoPoint &c, double side)
{
    const LocalTangentPlane plane(c);
    const double h = side / 2;
    AreaScan s;
    for (const PlanePoint p : {PlanePoint{-h, -h}, PlanePoint{h, -h}, PlanePoint{h, h}, PlanePoint{-h, h}})
        s.polygon.push_back(plane.unproject(p));
    return s;
}

const ValidationIssue *find(const ValidationReport &r, const QString &rule)
{
    for (const auto &i : r.issues)
        if (i.rule == rule)
            return &i;
    return nullptr;
}
}

class TestValidation : public QObject
{
    Q_OBJECT
private slots:
    void cleanRouteHasNoIssues()
    {
        const ValidationReport r = validateRoute(twoPoints());
        QVERIFY2(r.issues.empty(), r.issues.empty() ? "" : qPrintable(r.issues.front().message));
    }

    void rules_data()
    {
        QTest::addColumn<int>("which");
        QTest::addColumn<QString>("rule");
        QTest::addColumn<bool>("error");
        QTest::addColumn<int>("segment");
        QTest::newRow("too few points") << 0 << "too-few-points" << true << -1;
        QTest::newRow("above max") << 1 << "altitude-above-max" << true << 1;
        QTest::newRow("below safe") << 2 << "altitude-below-safe" << false << 0;
        QTest::newRow("speed above limit") << 3 << "speed-above-limit" << true << 1;
        QTest::newRow("speed zero") << 4 << "speed-not-positive" << true << 0;
        QTest::newRow("duplicate") << 5 << "duplicate-waypoint" << false << 2;
        QTest::newRow("self-intersecting scan") << 6 << "scan-self-intersecting" << true << 2;
        QTest::newRow("scan without transects") << 7 << "scan-no-transects" << true << 2;
        QTest::newRow("amsl unchecked") << 8 << "altitude-unchecked" << false << 1;
        QTest::newRow("amsl above max via home") << 9 << "altitude-above-max" << true << 1;
        QTest::newRow("mixed altitude types") << 10 << "mixed-altitude-types" << false << 1;
        QTest::newRow("invalid position") << 11 << "invalid-position" << true << 0;
        QTest::newRow("scan speed above limit") << 12 << "speed-above-limit" << true << 2;
        QTest::newRow("scan refused") << 13 << "scan-invalid" << true << 2;
    }
    void rules()
    {
        QFETCH(int, which);
        QFETCH(QString, rule);
        QFETCH(bool, error);
        QFETCH(int, segment);
        Route r = twoPoints();
        auto w = [&](int i) -> Waypoint & { return std::get<Waypoint>(r.segments[size_t(i)]); };
        switch (which) {
        case 0: r.segments.pop_back(); break;
        case 1: w(1).altitude = 121; break;
        case 2: w(0).altitude = 19.5; break;
        case 3: w(1).speed = 10.5; break;
        case 4: w(0).speed = 0; break;
        case 5: r.segments.push_back(r.segments[1]); break;
        case 6: {
            AreaScan s = squareScan({56.9, 24.1}, 200);
            std::swap(s.polygon[1], s.polygon[2]);
            r.segments.push_back(s);
            break;
        }
        case 7: r.segments.push_back(squareScan({56.9, 24.1}, 0.5)); break;
        case 8: w(1).altitudeType = AltitudeType::Amsl; break;
        case 9:
            w(1).altitudeType = AltitudeType::Amsl; w(0).altitudeType = AltitudeType::Amsl;
            w(1).altitude = 250; w(0).altitude = 150;
            r.settings.home = HomePosition{{56.9, 24.1}, 120.0};
            break;
        case 10: w(1).altitudeType = AltitudeType::Amsl; r.settings.home = HomePosition{{56.9, 24.1}, 0}; break;
        case 11: w(0).position.latitude = 91; break;
        case 12: { AreaScan s = squareScan({56.9, 24.1}, 200); s.parameters.speed = 11; r.segments.push_back(s); break; }
        case 13: { AreaScan s = squareScan({56.9, 24.1}, 200); s.parameters.frontOverlapPercent = 99; r.segments.push_back(s); break; }
        }
        const ValidationReport report = validateRoute(r);
        const ValidationIssue *issue = find(report, rule);
        QVERIFY2(issue, qPrintable(QStringLiteral("rule %1 not reported").arg(rule)));
        QCOMPARE(issue->severity == Severity::Error, error);
        QCOMPARE(issue->segment, segment);
        if (segment >= 0)
            QVERIFY2(issue->message.contains(QString::number(segment + 1)), qPrintable(issue->message));
        QCOMPARE(report.hasErrors(), error || report.errorCount() > 0);
    }

    void aboveTheLimitSaysWhatWasCompared()
    {
        // 250 m AMSL with the take-off at 120 m AMSL: 130 m above the take-off point, not above the
        // ground under the waypoint, and the message says so.
        Route r = twoPoints();
        for (int i : {0, 1})
            std::get<Waypoint>(r.segments[size_t(i)]).altitudeType = AltitudeType::Amsl;
        std::get<Waypoint>(r.segments[0]).altitude = 150;
        std::get<Waypoint>(r.segments[1]).altitude = 250;
        r.settings.home = HomePosition{{56.9, 24.1}, 120.0};
        const ValidationReport report = validateRoute(r); // held: find() points into it
        const ValidationIssue *issue = find(report, QStringLiteral("altitude-above-max"));
        QVERIFY(issue);
        QCOMPARE(issue->message, QStringLiteral("Waypoint 2: 130.0 m above the take-off point (altitude 250 m AMSL); the route's limit is 120 m above it."));
    }

    void gateBlocksErrorsUnlessOverridden()
    {
        Route r = twoPoints();
        std::get<Waypoint>(r.segments[1]).altitude = 500;
        const ValidationReport report = validateRoute(r);
        const Result<void> refused = permitRelease(report, ValidationOverride::None, QStringLiteral("Upload"));
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().message.contains(QStringLiteral("Waypoint 2")));
        QVERIFY(permitRelease(report, ValidationOverride::AcceptErrors, QStringLiteral("Upload")).ok());
        std::get<Waypoint>(r.segments[1]).altitude = 10;  // only a warning now
        QVERIFY(permitRelease(validateRoute(r), ValidationOverride::None, QStringLiteral("Save")).ok());
    }

    void statistics()
    {
        Route r;
        r.settings.profile.climbRate = 3;
        r.settings.profile.descentRate = 2;
        const GeoPoint a{56.9, 24.1};
        const GeoPoint b = geodesicDirect(a, 90, 1000).point;
        const GeoPoint c = geodesicDirect(b, 0, 10).point;
        Waypoint w1 = at(a.latitude, a.longitude, 40, 5);
        w1.role = WaypointRole::Takeoff;                 // climbs 40 m at 3 m/s: 13.33 s
        Waypoint w2 = at(b.latitude, b.longitude, 100, 5);  // 1000 m at 5 m/s: 200 s (the 60 m climb takes 20 s)
        w2.actions.push_back(WaitAction{5, false});     // + 5 s
        Waypoint w3 = at(c.latitude, c.longitude, 40, 5);   // 10 m takes 2 s, the 60 m descent 30 s
        r.segments = {w1, w2, w3};
        const RouteStatistics st = computeStatistics(r);
        QCOMPARE(st.waypointCount, 3);
        QVERIFY2(std::abs(st.lengthMeters - 1010.0) < 1e-4, qPrintable(QString::number(st.lengthMeters, 'f', 9)));
        QVERIFY(std::abs(st.flightTimeSeconds - (40.0 / 3 + 200 + 5 + 30)) < 1e-6);
        QVERIFY(std::abs(st.climbMeters - 100) < 1e-9);
        QVERIFY(std::abs(st.descentMeters - 60) < 1e-9);
        QVERIFY(!st.boundingBox.empty);
        QCOMPARE(st.boundingBox.south, std::min({a.latitude, b.latitude, c.latitude}));  // an eastward geodesic bends south
        QVERIFY(std::abs(st.boundingBox.north - c.latitude) < 1e-12);

        AreaScan scan = squareScan({56.95, 24.1}, 1000);
        scan.parameters.altitude = 40;
        r.segments.push_back(scan);
        const RouteStatistics withScan = computeStatistics(r);
        QCOMPARE(withScan.areaScanCount, 1);
        QCOMPARE(withScan.photoCount, planAreaScan(scan).plan->photoCount);
        QVERIFY(withScan.photoCount > 1000);
        QVERIFY(withScan.lengthMeters > st.lengthMeters + 20000);
    }

    void cameraActionsCountPhotos()
    {
        // Four waypoints 100 m apart along a line at 5 m/s.
        Route r;
        GeoPoint p{56.9, 24.1};
        for (int i = 0; i < 4; ++i) {
            r.segments.push_back(at(p.latitude, p.longitude, 40, 5));
            p = geodesicDirect(p, 90, 100).point;
        }
        auto actions = [&r](int row) -> std::vector<WaypointAction> & { return std::get<Waypoint>(r.segments[size_t(row)]).actions; };
        QCOMPARE(computeStatistics(r).photoCount, 0);
        // One photo where it is set, then one every 30 m over the 300 m that follow: 1 + 10.
        actions(0).push_back(CameraSeriesByDistanceAction{30, 0, 0});
        QCOMPARE(computeStatistics(r).photoCount, 11);
        // Stopped at the third waypoint (interval 0) after 200 m: 1 + 6; a single shot at the last.
        actions(2).push_back(CameraSeriesByDistanceAction{0, 0, 0});
        actions(3).push_back(CameraTriggerAction{TriggerState::SingleShot});
        QCOMPARE(computeStatistics(r).photoCount, 7 + 1);
        // Three shots only.
        actions(0).front() = CameraSeriesByDistanceAction{30, 3, 0};
        QCOMPARE(computeStatistics(r).photoCount, 3 + 1);
        // By time: every 4 s over 40 s of legs (two 100 m legs at 5 m/s) from the first: 1 + 10.
        actions(0).front() = CameraSeriesByTimeAction{4, 0, 0};
        QCOMPARE(computeStatistics(r).photoCount, 11 + 1);
    }

    void analyzerCoalescesEdits()
    {
        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        model.resetRoute(twoPoints());
        RouteAnalyzer analyzer(&model);
        analyzer.setDelay(20);
        const int before = analyzer.recomputeCount();
        QCOMPARE(analyzer.errorCount(), 0);
        QSignalSpy recomputed(&analyzer, &RouteAnalyzer::recomputed);
        QSignalSpy validation(&analyzer, &RouteAnalyzer::validationChanged);
        for (int i = 0; i < 200; ++i)
            editor.moveWaypoints({1}, {QGeoCoordinate(56.91 + i * 1e-5, 24.1)}, EditStep::Continuing);
        editor.setAltitude({1}, 500);
        QVERIFY(analyzer.isPending());
        QVERIFY(recomputed.wait(2000));
        QCOMPARE(analyzer.recomputeCount(), before + 1);  // 201 edits, one recomputation
        QCOMPARE(validation.count(), 1);
        QCOMPARE(analyzer.errorCount(), 1);
        QCOMPARE(analyzer.issues()->rowCount(), 1);
        QCOMPARE(analyzer.issues()->index(0).data(ValidationIssueModel::RuleRole).toString(), QStringLiteral("altitude-above-max"));
        QCOMPARE(analyzer.issues()->index(0).data(ValidationIssueModel::SegmentRole).toInt(), 1);
        QVERIFY(analyzer.lengthMeters() > 1000);
        stack.setIndex(0);
        QVERIFY(recomputed.wait(2000));
        QCOMPARE(analyzer.errorCount(), 0);
    }
};

QTEST_GUILESS_MAIN(TestValidation)
#include "tst_validation.moc"
