// RouteDiff on real routes (a QGroundControl WPL sample, the MAVLink feature route) and hand-built
// ones: identical routes, moves in metres, additions and removals by position, altitude, speed,
// actions, area scans and route settings, and the one-line summary.
#include "Geodesy.h"
#include "HciRouteMapper.h"
#include "MissionFiles.h"
#include "MissionSamples.h"
#include "Messages.pb.h"
#include "RouteDiff.h"

#include <QTest>

using namespace sortie::mission;
using Kind = RouteChange::Kind;

class TestRouteDiff : public QObject
{
    Q_OBJECT

    static Route sample()
    {
        auto loaded = formats::loadMission(test::samplePath(QStringLiteral("100Waypoints.waypoints.txt")));
        if (!loaded)
            qFatal("%s", qPrintable(loaded.error().toString()));
        return loaded->mission.routes.front();
    }
    static Waypoint &wp(Route &r, int row) { return std::get<Waypoint>(r.segments[size_t(row)]); }

private slots:
    void identicalRoutesHaveNoChanges()
    {
        const Route route = sample();
        QVERIFY(route.segments.size() >= 50);
        const RouteDiff diff = RouteDiff::compare(route, route);
        QVERIFY(diff.isEmpty());
        QCOMPARE(diff.summary(), QStringLiteral("No changes"));

        // The same content from the server (with its provenance) is no change either.
        Route local = test::mavlinkRoute();
        local.settings.home.reset(); // HCI routes carry no home
        auto fromServer = routeFromHci(routeToHci(local));
        QVERIFY(fromServer && fromServer->route.origin);
        QVERIFY2(RouteDiff::compare(local, fromServer->route).isEmpty(), qPrintable(RouteDiff::compare(local, fromServer->route).summary()));
    }

    void movedAddedAndAltitudeInOneSummary()
    {
        Route before = sample();
        wp(before, 2).altitude = 80;
        Route after = before;
        // WP 2 moves 41 m north-east; WP 3 climbs; a new WP 5.
        wp(after, 1).position = geodesicDirect(wp(before, 1).position, 45, 41).point;
        wp(after, 2).altitude = 100;
        Waypoint added = wp(before, 3);
        added.position = geodesicDirect(added.position, 90, 15).point;
        after.segments.insert(after.segments.begin() + 4, added);

        const RouteDiff diff = RouteDiff::compare(before, after);
        QCOMPARE(diff.texts(), (QStringList{QStringLiteral("WP 2 moved 41 m"), QStringLiteral("altitude of WP 3 80 → 100 m"),
                                            QStringLiteral("WP 5 added")}));
        QCOMPARE(diff.summary(), QStringLiteral("3 changes: WP 2 moved 41 m, altitude of WP 3 80 → 100 m, WP 5 added"));
        QCOMPARE(diff.changes()[0].kind, Kind::Moved);
        QVERIFY(std::abs(diff.changes()[0].meters - 41.0) < 0.01);
        QCOMPARE(diff.changes()[2].kind, Kind::Added);
        QCOMPARE(diff.changes()[2].row, 4);
    }

    void removalIsOneChangeNotAShiftOfEveryLaterWaypoint()
    {
        const Route before = sample();
        Route after = before;
        after.segments.erase(after.segments.begin() + 9);
        const RouteDiff diff = RouteDiff::compare(before, after);
        QCOMPARE(diff.texts(), QStringList{QStringLiteral("WP 10 removed")});
        QCOMPARE(diff.changes().front().kind, Kind::Removed);
        // And back again: an addition at the same place.
        QCOMPARE(RouteDiff::compare(after, before).texts(), QStringList{QStringLiteral("WP 10 added")});
    }

    void removalBesideAnEditPairsTheRightWaypoints()
    {
        const Route before = sample();
        Route after = before;
        after.segments.erase(after.segments.begin() + 5);
        wp(after, 5).speed = 9; // was WP 7
        const RouteDiff diff = RouteDiff::compare(before, after);
        QCOMPARE(diff.count(), 2);
        QCOMPARE(diff.texts().at(0), QStringLiteral("WP 6 removed"));
        QVERIFY2(diff.texts().at(1).startsWith(QStringLiteral("speed of WP 6 ")), qPrintable(diff.texts().at(1)));
        QVERIFY(diff.texts().at(1).endsWith(QStringLiteral(" → 9 m/s")));
    }

    void waypointFieldsAndActions()
    {
        const Route before = test::mavlinkRoute();
        Route after = before;
        wp(after, 1).actions.push_back(WaitAction{5, false});
        wp(after, 2).altitudeType = AltitudeType::Agl;
        wp(after, 3).turnType = TurnType::Spline;
        wp(after, 4).speed = 3;
        const QStringList texts = RouteDiff::compare(before, after).texts();
        QCOMPARE(texts.size(), 4);
        QVERIFY2(texts[0].startsWith(QStringLiteral("actions of WP 2: Wait 4.5 s")) && texts[0].endsWith(QStringLiteral("Wait 5 s")),
                 qPrintable(texts[0]));
        QCOMPARE(texts[1], QStringLiteral("altitude of WP 3 80 m AMSL → 80 m AGL"));
        QCOMPARE(texts[2], QStringLiteral("turn at WP 4 Straight → Spline"));
        QCOMPARE(texts[3], QStringLiteral("speed of WP 5 4 → 3 m/s"));
    }

    void areaScansAndSettings()
    {
        Route before = test::mavlinkRoute();
        before.segments.push_back(test::squareScan({56.96, 24.11}, 200, 60));
        Route after = before;
        after.settings.name = QStringLiteral("Riga quay, evening");
        after.settings.safeAltitude = 45;
        after.settings.endAction = EndAction::ReturnHome;
        AreaScan &scan = std::get<AreaScan>(after.segments.back());
        scan.parameters.sideOverlapPercent = 80;
        scan.polygon.push_back({56.9595, 24.1115});
        const QStringList texts = RouteDiff::compare(before, after).texts();
        QCOMPARE(texts, (QStringList{QStringLiteral("name \"Riga quay\" → \"Riga quay, evening\""),
                                     QStringLiteral("safe altitude 20 → 45 m"),
                                     QStringLiteral("end action none → return home"),
                                     QStringLiteral("area of Scan 6 reshaped (4 → 5 corners)"),
                                     QStringLiteral("side overlap of Scan 6 65 → 80 %")}));
        const RouteDiff diff = RouteDiff::compare(before, after);
        QCOMPARE(diff.summary(2), QStringLiteral("5 changes: name \"Riga quay\" → \"Riga quay, evening\", safe altitude 20 → 45 m and 3 more"));
    }

    void aWaypointReplacedByAScanIsARemovalAndAnAddition()
    {
        const Route before = test::mavlinkRoute();
        Route after = before;
        after.segments[2] = test::squareScan({56.953, 24.105}, 100);
        QCOMPARE(RouteDiff::compare(before, after).texts(),
                 (QStringList{QStringLiteral("WP 3 removed"), QStringLiteral("Scan 3 added")}));
    }
};

QTEST_GUILESS_MAIN(TestRouteDiff)
#include "tst_routediff.moc"
