// QGC WPL 110 and QGroundControl .plan: every sample from QGroundControl's test data imports,
// round trips come back identical, and malformed files fail with the line or JSON path.
#include "AlgorithmCatalog.h"
#include "AreaScanPlanner.h"
#include "MissionFiles.h"
#include "MissionSamples.h"
#include "QgcPlanFormat.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "WplFormat.h"

#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace sortie::mission::test;

namespace {
int countRole(const Route &r, WaypointRole role)
{
    int n = 0;
    for (const auto &s : r.segments)
        if (const Waypoint *w = asWaypoint(s); w && w->role == role)
            ++n;
    return n;
}

QString describe(const MissionError &e) { return e.toString(); }

// WPL carries no route settings except home and the return: compare what it carries.
Route wplView(Route r)
{
    RouteSettings s;
    s.home = r.settings.home;
    s.endAction = r.settings.endAction;
    s.initialSpeed = kWplDefaultSpeed;
    r.settings = s;
    return r;
}

Route planView(Route r)
{
    RouteSettings s;
    s.home = r.settings.home;
    s.endAction = r.settings.endAction;
    s.initialSpeed = r.settings.initialSpeed;
    r.settings = s;
    return r;
}
}

class TestQgcFormats : public QObject
{
    Q_OBJECT
private slots:
    void samplesImport_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("segments");
        QTest::addColumn<int>("takeoffs");
        QTest::addColumn<int>("landings");
        QTest::addColumn<bool>("returnsHome");
        QTest::addColumn<int>("notices");
        QTest::newRow("Mission Planner") << "MissionPlanner.waypoints" << 5 << 0 << 0 << false << 1;
        QTest::newRow("Mission Planner, many commands") << "MissionPlanner.waypoints.txt" << 11 << 1 << 1 << false << 4;
        QTest::newRow("100 waypoints") << "100Waypoints.waypoints.txt" << 98 << 1 << 0 << false << 1;
        QTest::newRow("800 waypoints") << "800Waypoints.waypoints.txt" << 825 << 1 << 0 << true << 1;
        QTest::newRow("plan") << "SectionTest.plan" << 4 << 1 << 0 << false << 1;
    }
    void samplesImport()
    {
        QFETCH(QString, file);
        QFETCH(int, segments);
        QFETCH(int, takeoffs);
        QFETCH(int, landings);
        QFETCH(bool, returnsHome);
        QFETCH(int, notices);
        const Result<LoadedMission> m = loadMission(samplePath(file));
        QVERIFY2(m.ok(), m.ok() ? "" : qPrintable(describe(m.error())));
        const Route &r = m->mission.routes.at(0);
        QCOMPARE(int(r.segments.size()), segments);
        QCOMPARE(countRole(r, WaypointRole::Takeoff), takeoffs);
        QCOMPARE(countRole(r, WaypointRole::Land), landings);
        QCOMPARE(r.settings.endAction == EndAction::ReturnHome, returnsHome);
        QVERIFY(r.settings.home.has_value());
        QCOMPARE(m->notices.size(), notices);
        QCOMPARE(r.settings.name, QFileInfo(file).completeBaseName());
        // Import -> export -> import gives the same route.
        const bool plan = file.endsWith(QStringLiteral(".plan"));
        const QByteArray again = plan ? writeQgcPlan(r) : writeWpl(r);
        const Result<ImportedRoute> back = plan ? readQgcPlan(again) : readWpl(again);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(describe(back.error())));
        QVERIFY(plan ? planView(back->route) == planView(r) : wplView(back->route) == wplView(r));
    }

    void missionPlannerDetails()
    {
        const Result<ImportedRoute> r = readWpl(readSample(QStringLiteral("MissionPlanner.waypoints.txt")));
        QVERIFY(r.ok());
        const Route &route = r->route;
        QCOMPARE(route.settings.home->altitudeAmsl, 1543.079956);
        const auto &takeoff = std::get<Waypoint>(route.segments[0]);
        QCOMPARE(takeoff.role, WaypointRole::Takeoff);
        QVERIFY(takeoff.position == route.settings.home->position);  // 0,0 means here
        QCOMPARE(takeoff.altitude, 30.0);
        // DO_CHANGE_SPEED 15 m/s (line 12) applies to the waypoints after it.
        QCOMPARE(std::get<Waypoint>(route.segments[7]).speed, 5.0);
        QCOMPARE(std::get<Waypoint>(route.segments[8]).speed, 15.0);
        QVERIFY(r->notices.join(' ').contains(QStringLiteral("line 9: DO_JUMP is not supported")));
        QVERIFY(r->notices.join(' ').contains(QStringLiteral("line 13: DO_LAND_START")));
        QVERIFY(r->notices.join(' ').contains(QStringLiteral("NAV_LOITER_TURNS was imported as a plain waypoint")));
    }

    void planDetails()
    {
        const Result<ImportedRoute> r = readQgcPlan(readSample(QStringLiteral("SectionTest.plan")));
        QVERIFY(r.ok());
        QCOMPARE(r->route.settings.initialSpeed, 5.0);  // hoverSpeed of a multirotor
        QCOMPARE(r->route.settings.home->position.latitude, 47.633389756176875);
        const auto &w = std::get<Waypoint>(r->route.segments[1]);
        QCOMPARE(w.position.latitude, 47.63369112);
        QCOMPARE(w.altitude, 20.0);
        QCOMPARE(w.altitudeType, AltitudeType::Agl);
        // Item 3 is QGroundControl's gimbal control (DO_MOUNT_CONTROL, all angles 0) after waypoint 3: the camera ahead.
        QCOMPARE(std::get<Waypoint>(r->route.segments[2]).actions, (std::vector<WaypointAction>{CameraControlAction{0, 0, 0, std::nullopt}}));
        QVERIFY(!r->notices.join(' ').contains(QStringLiteral("205")));
    }

    void wplRoundTripIsIdentical()
    {
        const Route r = mavlinkRoute();
        QStringList notices;
        const QByteArray text = writeWpl(r, &notices);
        const Result<ImportedRoute> back = readWpl(text);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(describe(back.error())));
        QVERIFY(wplView(back->route) == wplView(r));
        QCOMPARE(writeWpl(back->route), text);
        QVERIFY(text.startsWith("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t56.9512345678901\t24.1023456789012\t12.5\t1\n"));
    }

    void gimbalIsAMountControl()
    {
        // Tilt only: MAVLink has no "unchanged", so roll and yaw go out as 0 and the notice says so.
        Route r = mavlinkRoute();
        CameraControlAction down;
        down.tiltDeg = 90;
        down.zoomLevel = 2;
        std::get<Waypoint>(r.segments[1]).actions = {down};
        QStringList notices;
        const QByteArray text = writeWpl(r, &notices);
        QVERIFY2(notices.join('\n').contains(QStringLiteral("Waypoint 2: the gimbal's roll, yaw was not set and is written as 0°")),
                 qPrintable(notices.join('\n')));
        QVERIFY(notices.join('\n').contains(QStringLiteral("Waypoint 2: a zoom level has no MAVLink equivalent")));
        QVERIFY(text.contains("\t205\t-90\t0\t0\t0\t0\t0\t2\t1\n"));
        const Result<ImportedRoute> back = readWpl(text);
        QVERIFY(back.ok());
        QCOMPARE(std::get<Waypoint>(back->route.segments[1]).actions,
                 (std::vector<WaypointAction>{CameraControlAction{90, 0, 0, std::nullopt}}));
    }

    void planRoundTripIsIdentical()
    {
        Route r = mavlinkRoute();
        r.segments.insert(r.segments.begin() + 3, squareScan({56.953, 24.11}, 400, 55));
        AreaScan gsd = squareScan({56.956, 24.12}, 300);
        gsd.parameters.heightMode = ScanHeightMode::GroundSampleDistance;
        gsd.parameters.groundSampleDistanceCm = 1.5;
        gsd.parameters.directionDeg = 33;
        gsd.parameters.altitudeType = AltitudeType::Amsl;
        gsd.parameters.speed = 5;
        syncDerivedFields(gsd.parameters);
        r.segments.push_back(gsd);
        r.settings.endAction = EndAction::ReturnHome;
        QStringList notices;
        const QByteArray text = writeQgcPlan(r, &notices);
        const Result<ImportedRoute> back = readQgcPlan(text);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(describe(back.error())));
        QVERIFY(planView(back->route) == planView(r));
        QCOMPARE(writeQgcPlan(back->route), text);
    }

    // A corridor goes out as QGroundControl's CorridorScan and comes back as the same corridor; a
    // structure scan comes in as a perimeter; a circle goes out as the waypoints Sortie plans.
    void corridorStructureAndCircle()
    {
        Route r = mavlinkRoute();
        AlgorithmSegment corridor;
        corridor.algorithm = algorithmClassName(AlgorithmKind::Corridor);
        corridor.figure = FigureType::Polyline;
        corridor.points = {{{56.950, 24.100}, 0, AltitudeType::Agl}, {{56.953, 24.104}, 0, AltitudeType::Agl},
                           {{56.955, 24.112}, 0, AltitudeType::Agl}};
        corridor.parameters = {{QStringLiteral("width"), QStringLiteral("40")}, {QStringLiteral("camera"), QStringLiteral("GoPro Hero3 Black Edition")},
                               {QStringLiteral("groundSampleDistance"), QStringLiteral("2.5")}, {QStringLiteral("overlapForward"), QStringLiteral("70")},
                               {QStringLiteral("overlapSide"), QStringLiteral("40")}, {QStringLiteral("altitudeType"), QStringLiteral("AGL")}};
        r.segments.push_back(corridor);
        AlgorithmSegment circle;
        circle.algorithm = algorithmClassName(AlgorithmKind::Circle);
        circle.figure = FigureType::Circle;
        circle.points = {{{56.951, 24.105}, 40, AltitudeType::Agl}};
        circle.figureParameters = {30};
        r.segments.push_back(circle);
        QStringList notices;
        const QByteArray text = writeQgcPlan(r, &notices);
        QVERIFY(text.contains("\"complexItemType\": \"CorridorScan\""));
        QVERIFY(notices.join(' ').contains(QStringLiteral("waypoints Sortie plans")));
        const Result<ImportedRoute> back = readQgcPlan(text);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(describe(back.error())));
        const auto it = std::find_if(back->route.segments.begin(), back->route.segments.end(),
                                     [](const Segment &s) { return isAlgorithmSegment(s); });
        QVERIFY(it != back->route.segments.end());
        const AlgorithmSegment &c = std::get<AlgorithmSegment>(*it);
        QCOMPARE(c.kind(), AlgorithmKind::Corridor);
        QVERIFY(c.points == corridor.points);
        for (const char *name : {"width", "camera", "overlapForward", "overlapSide", "altitudeType"})
            QCOMPARE(*c.value(QString::fromLatin1(name)), *corridor.value(QString::fromLatin1(name)));
        QVERIFY(std::abs(parseParameterNumber(*c.value(u"groundSampleDistance")).value() - 2.5) < 1e-9);
        // The circle's orbit came back as waypoints on its radius.
        const int waypointsBefore = countRole(r, WaypointRole::Pass);
        QVERIFY(countRole(back->route, WaypointRole::Pass) >= waypointsBefore + 8);

        const QByteArray structure = R"({"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
            "geoFence": {"circles": [], "polygons": [], "version": 2}, "rallyPoints": {"points": [], "version": 2},
            "mission": {"version": 2, "firmwareType": 12, "vehicleType": 2, "cruiseSpeed": 15, "hoverSpeed": 5,
              "plannedHomePosition": [47.39, 8.54, 488], "items": [{"type": "ComplexItem", "complexItemType": "StructureScan",
              "version": 3, "Altitude": 30, "Layers": 3, "StructureHeight": 25,
              "CameraCalc": {"DistanceToSurface": 10, "DistanceToSurfaceRelative": true, "version": 1},
              "polygon": [[47.3900, 8.5400], [47.3900, 8.5410], [47.3906, 8.5410], [47.3906, 8.5400]]}]}})";
        const Result<ImportedRoute> s = readQgcPlan(structure);
        QVERIFY2(s.ok(), s.ok() ? "" : qPrintable(describe(s.error())));
        QCOMPARE(int(s->route.segments.size()), 1);
        const AlgorithmSegment &perimeter = std::get<AlgorithmSegment>(s->route.segments[0]);
        QCOMPARE(perimeter.kind(), AlgorithmKind::Perimeter);
        QCOMPARE(perimeter.points.size(), size_t(4));
        QCOMPARE(*perimeter.value(u"height"), QStringLiteral("30"));
        QCOMPARE(*perimeter.value(u"loops"), QStringLiteral("3"));
        QVERIFY(s->notices.join(' ').contains(QStringLiteral("3 layers as 3 loops")));
    }

    void wplExpandsScans()
    {
        Route r = mavlinkRoute();
        r.segments.insert(r.segments.begin() + 2, squareScan({56.953, 24.11}, 300, 55));
        QStringList notices;
        const Result<ImportedRoute> back = readWpl(writeWpl(r, &notices));
        QVERIFY(back.ok());
        const AreaScanOutcome o = planAreaScan(std::get<AreaScan>(r.segments[2]));
        QCOMPARE(int(back->route.segments.size()), int(r.segments.size()) - 1 + int(o.plan->path.size()));
        QVERIFY(notices.join(' ').contains(QStringLiteral("Area scan 3 was written as")));
    }

    void brokenWplNamesTheLine_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("words");
        const QByteArray home = "0\t1\t0\t16\t0\t0\t0\t0\t47.1\t8.5\t400\t1\n";
        QTest::newRow("header") << QByteArray("QGC WPL 100\n") << 1 << "unsupported";
        QTest::newRow("not wpl") << QByteArray("hello\n") << 1 << "not a waypoint file";
        QTest::newRow("fields") << QByteArray("QGC WPL 110\n" + home + "1\t0\t3\t16\t0\t0\t0\n") << 3 << "12 tab-separated";
        QTest::newRow("number") << QByteArray("QGC WPL 110\n" + home + "1\t0\t3\t16\t0\t0\t0\t0\t47.2\tabc\t50\t1\n") << 3 << "longitude";
        QTest::newRow("sequence") << QByteArray("QGC WPL 110\n" + home + "2\t0\t3\t16\t0\t0\t0\t0\t47.2\t8.6\t50\t1\n") << 3 << "item 2 where item 1";
        QTest::newRow("frame") << QByteArray("QGC WPL 110\n" + home + "1\t0\t7\t16\t0\t0\t0\t0\t47.2\t8.6\t50\t1\n") << 3 << "frame 7";
        QTest::newRow("no position") << QByteArray("QGC WPL 110\n" + home + "1\t0\t3\t16\t0\t0\t0\t0\t0\t0\t50\t1\n") << 3 << "no position";
        QTest::newRow("after rtl") << QByteArray("QGC WPL 110\n" + home + "1\t0\t3\t20\t0\t0\t0\t0\t0\t0\t0\t1\n2\t0\t3\t16\t0\t0\t0\t0\t47.2\t8.6\t50\t1\n") << 4 << "after RETURN_TO_LAUNCH";
        QTest::newRow("range") << QByteArray("QGC WPL 110\r\n" + home + "1\t0\t3\t16\t0\t0\t0\t0\t147.2\t8.6\t50\t1\r\n") << 3 << "not a position";
    }
    void brokenWplNamesTheLine()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, words);
        const Result<ImportedRoute> r = readWpl(text);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().line, line);
        QVERIFY2(r.error().message.contains(words), qPrintable(r.error().message));
    }

    void brokenPlanNamesThePath_data()
    {
        QTest::addColumn<QByteArray>("from");
        QTest::addColumn<QByteArray>("to");
        QTest::addColumn<QString>("path");
        QTest::newRow("file type") << QByteArray("\"fileType\": \"Plan\"") << QByteArray("\"fileType\": \"Fence\"") << "/fileType";
        QTest::newRow("params") << QByteArray("\"params\": [\n                    0,\n                    0,\n                    0,\n                    null\n                ],\n                \"type\": \"SimpleItem\"\n            },\n            {\n                \"autoContinue\": true,\n                \"command\": 16")
                                << QByteArray("\"params\": [0, 0],\n                \"type\": \"SimpleItem\"\n            },\n            {\n                \"autoContinue\": true,\n                \"command\": 16") << "/mission/items/0/params";
        QTest::newRow("complex") << QByteArray("\"type\": \"SimpleItem\"\n            }\n        ],") << QByteArray("\"type\": \"SimpleItem\"\n            },\n {\"type\": \"ComplexItem\", \"complexItemType\": \"Orbit\"}        ],") << "/mission/items/5/complexItemType";
        QTest::newRow("corridor") << QByteArray("\"type\": \"SimpleItem\"\n            }\n        ],") << QByteArray("\"type\": \"SimpleItem\"\n            },\n {\"type\": \"ComplexItem\", \"complexItemType\": \"CorridorScan\"}        ],") << "/mission/items/5";  // no "polyline" in it
        QTest::newRow("command type") << QByteArray("\"command\": 22") << QByteArray("\"command\": \"takeoff\"") << "/mission/items/0/command";
        QTest::newRow("mission version") << QByteArray("\"version\": 2") << QByteArray("\"version\": 3") << "/mission/version";
    }
    void brokenPlanNamesThePath()
    {
        QFETCH(QByteArray, from);
        QFETCH(QByteArray, to);
        QFETCH(QString, path);
        QByteArray text = readSample(QStringLiteral("SectionTest.plan"));
        QVERIFY2(text.contains(from), "test edit does not apply");
        text.replace(text.indexOf(from), from.size(), to);
        const Result<ImportedRoute> r = readQgcPlan(text);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().jsonPath, path);
    }

    void planSyntaxErrorNamesTheLine()
    {
        QByteArray text = readSample(QStringLiteral("SectionTest.plan"));
        text.replace(text.indexOf("\"groundStation\""), 1, "");
        const Result<ImportedRoute> r = readQgcPlan(text);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().line == 8 && r.error().column == 5, qPrintable(r.error().toString()));
        QVERIFY(!r.error().message.contains(QStringLiteral("last read")));
    }

    void failedImportLosesNothingInThePlan()
    {
        // The editing flow: load a file, and only on success replace the route as one undo step.
        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        editor.replaceRoute(mavlinkRoute(), QStringLiteral("Open"));
        editor.setAltitude({1, 2}, 70);
        const Route before = model.route();
        for (const char *bad : {"PolygonBadXml.kml", "PolygonMissingNode.kml"}) {
            const Result<LoadedMission> m = loadMission(samplePath(QLatin1String(bad)));
            QVERIFY(!m.ok());
            QCOMPARE(m.error().file, samplePath(QLatin1String(bad)));
        }
        QByteArray broken = readSample(QStringLiteral("MissionPlanner.waypoints.txt"));
        broken.replace("40.120796", "40.12x796");  // line 10 of 16
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("broken.waypoints")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(broken);
        f.close();
        const Result<LoadedMission> m = loadMission(f.fileName());
        QVERIFY(!m.ok());
        QCOMPARE(m.error().line, 11);
        QVERIFY(model.route() == before);
        QCOMPARE(stack.count(), 2);
        const Result<LoadedMission> good = loadMission(samplePath(QStringLiteral("MissionPlanner.waypoints")));
        QVERIFY(good.ok());
        editor.replaceRoute(good->mission.routes[0], QStringLiteral("Open"));
        QCOMPARE(model.count(), 5);
        stack.undo();
        QVERIFY(model.route() == before);
    }

    // A whole outside file is read at most to its limit: a file over it is refused, and so is a
    // device without end that reports no size (/dev/zero), after limit + 1 bytes, not read on.
    void wholeFilesAreReadToALimit()
    {
        QTemporaryDir dir;
        const QString small = dir.filePath(QStringLiteral("small.json"));
        QFile f(small);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(1000, 'x'));
        f.close();
        QCOMPARE(formats::readFileAtMost(small, 1000).value().size(), 1000);
        const auto over = formats::readFileAtMost(small, 999);
        QVERIFY(!over.ok());
        QVERIFY2(over.error().message.contains(QStringLiteral("larger than")), qPrintable(over.error().message));

        // A device with no end and no size: refused after 1 MiB + 1 bytes.
        const auto endless = formats::readFileAtMost(QStringLiteral("/dev/zero"), 1024 * 1024);
        QVERIFY(!endless.ok());
        QVERIFY2(endless.error().message.contains(QStringLiteral("larger than 1 MiB")), qPrintable(endless.error().message));
    }

    void importFailureLeavesTheFileAlone()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("route.waypoints"));
        Mission m;
        m.routes.push_back(mavlinkRoute());
        QVERIFY(saveMission(m, path).ok());
        const Result<LoadedMission> loaded = loadMission(path);
        QVERIFY(loaded.ok());
        QVERIFY(wplView(loaded->mission.routes[0]) == wplView(m.routes[0]));
        QVERIFY(!saveMission(m, path, {3, ValidationOverride::None}).ok());
    }
};

QTEST_GUILESS_MAIN(TestQgcFormats)
#include "tst_qgcformats.moc"
