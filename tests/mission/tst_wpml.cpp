// DJI WPML export and import: the KMZ is a real ZIP holding wpmz/template.kml and wpmz/waylines.wpml,
// both well-formed XML with the elements DJI Pilot 2 requires; a route comes back from Sortie's
// importer as it went out; area scans fly their passes with the camera down and a photo per
// forward-overlap distance; and a route WPML cannot carry is refused with its reason.
#include "DjiDroneModels.h"
#include "MissionFiles.h"
#include "WpmlFormat.h"
#include "ZipArchive.h"

#include <QDomDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::mission;
using namespace sortie::mission::formats;

Q_DECLARE_METATYPE(sortie::mission::Route)

namespace {

const QString kWpml = QStringLiteral("http://www.dji.com/wpmz/1.0.2");

Waypoint wp(double lat, double lon, double alt, double speed, TurnType turn = TurnType::StopAndTurn)
{
    Waypoint w;
    w.position = {lat, lon};
    w.altitude = alt;
    w.altitudeType = AltitudeType::Agl;
    w.speed = speed;
    w.turnType = turn;
    return w;
}

Route sampleRoute()
{
    Route r;
    r.settings.name = QStringLiteral("Quay");
    r.settings.endAction = EndAction::ReturnHome;
    Waypoint a = wp(56.97650, 24.07350, 40, 5);
    a.actions.push_back(CameraTriggerAction{TriggerState::SingleShot});
    a.actions.push_back(WaitAction{3.5, false});
    Waypoint b = wp(56.97800, 24.07600, 50, 6, TurnType::Straight);
    b.actions.push_back(HeadingAction{90.0, false});
    b.actions.push_back(CameraTriggerAction{TriggerState::StartRecording});
    b.actions.push_back(CameraControlAction{45, std::nullopt, std::nullopt, std::nullopt});
    Waypoint c = wp(56.97700, 24.07950, 55, 7, TurnType::Spline);
    c.actions.push_back(CameraTriggerAction{TriggerState::StopRecording});
    c.actions.push_back(CameraSeriesByDistanceAction{12.5, 0, 0.0});
    Waypoint d = wp(56.97580, 24.07500, 45, 8, TurnType::BankTurn);
    d.actions.push_back(CameraSeriesByDistanceAction{0.0, 0, 0.0});  // stops the series
    Waypoint e = wp(56.97560, 24.07300, 30, 4);
    r.segments = {a, b, c, d, e};
    return r;
}

QDomDocument parse(const QByteArray &xml, const char *what)
{
    QDomDocument doc;
    QString error;
    int line = 0;
    if (!doc.setContent(xml, true, &error, &line))
        qFatal("%s is not XML: %s at line %d", what, qPrintable(error), line);
    return doc;
}

QStringList texts(QDomDocument doc, const QString &name)
{
    QStringList out;
    const QDomNodeList nodes = doc.elementsByTagNameNS(kWpml, name);
    for (int i = 0; i < nodes.size(); ++i)
        out << nodes.at(i).toElement().text();
    return out;
}

} // namespace

class TestWpml : public QObject
{
    Q_OBJECT

private slots:
    void kmzHoldsTheTwoDocuments()
    {
        const Result<WpmlExport> out = writeWpml(sampleRoute());
        QVERIFY2(out.ok(), out.ok() ? "" : qPrintable(out.error().toString()));
        const Result<std::vector<ZipEntry>> entries = readZip(out->kmz);
        QVERIFY(entries.ok());
        QCOMPARE(int(entries->size()), 2);
        QCOMPARE(entries->at(0).path, QStringLiteral("wpmz/template.kml"));
        QCOMPARE(entries->at(1).path, QStringLiteral("wpmz/waylines.wpml"));
        QCOMPARE(entries->at(0).data, out->templateKml);
        QCOMPARE(entries->at(1).data, out->waylinesWpml);
    }

    void waylinesCarryTheRequiredElements()
    {
        WpmlExportOptions o;
        o.drone = QStringLiteral("m350");
        o.payload = QStringLiteral("h20t");
        const Result<WpmlExport> out = writeWpml(sampleRoute(), o);
        QVERIFY(out.ok());
        QDomDocument w = parse(out->waylinesWpml, "waylines.wpml");
        QCOMPARE(w.documentElement().localName(), QStringLiteral("kml"));
        QVERIFY(out->waylinesWpml.contains("<kml xmlns=\"http://www.opengis.net/kml/2.2\""));  // unprefixed KML, as DJI writes it
        QVERIFY(out->waylinesWpml.contains("<Placemark>"));
        QCOMPARE(texts(w, QStringLiteral("droneEnumValue")), QStringList{"89"});
        QCOMPARE(texts(w, QStringLiteral("payloadEnumValue")), QStringList{"43"});
        QCOMPARE(texts(w, QStringLiteral("finishAction")), QStringList{"goHome"});
        QCOMPARE(texts(w, QStringLiteral("executeHeightMode")), QStringList{"relativeToStartPoint"});
        QCOMPARE(texts(w, QStringLiteral("index")), (QStringList{"0", "1", "2", "3", "4"}));
        QCOMPARE(texts(w, QStringLiteral("executeHeight")), (QStringList{"40", "50", "55", "45", "30"}));
        // DJI's speed leaves a waypoint: the speed Sortie gives the next one.
        QCOMPARE(texts(w, QStringLiteral("waypointSpeed")), (QStringList{"6", "7", "8", "4", "4"}));
        QCOMPARE(texts(w, QStringLiteral("globalTransitionalSpeed")), QStringList{"5"});
        QCOMPARE(texts(w, QStringLiteral("waypointTurnMode")),
                 (QStringList{"toPointAndStopWithDiscontinuityCurvature", "toPointAndPassWithContinuityCurvature",
                              "toPointAndPassWithContinuityCurvature", "coordinateTurn", "toPointAndStopWithDiscontinuityCurvature"}));
        QCOMPARE(texts(w, QStringLiteral("actionActuatorFunc")),
                 (QStringList{"takePhoto", "hover", "rotateYaw", "startRecord", "gimbalRotate", "stopRecord", "takePhoto"}));
        QCOMPARE(texts(w, QStringLiteral("actionTriggerType")),
                 (QStringList{"reachPoint", "reachPoint", "reachPoint", "multipleDistance"}));
        QCOMPARE(texts(w, QStringLiteral("actionTriggerParam")), QStringList{"12.5"});
        QCOMPARE(texts(w, QStringLiteral("hoverTime")), QStringList{"3.5"});
        QCOMPARE(texts(w, QStringLiteral("aircraftHeading")), QStringList{"90"});
        // The series runs from waypoint 3 to waypoint 4, where it was stopped.
        const QDomNodeList groups = w.elementsByTagNameNS(kWpml, QStringLiteral("actionGroup"));
        const QDomElement series = groups.at(groups.size() - 1).toElement();
        QCOMPARE(series.elementsByTagNameNS(kWpml, QStringLiteral("actionGroupStartIndex")).at(0).toElement().text(), QStringLiteral("2"));
        QCOMPARE(series.elementsByTagNameNS(kWpml, QStringLiteral("actionGroupEndIndex")).at(0).toElement().text(), QStringLiteral("3"));
        // Coordinates are longitude,latitude.
        const QDomNodeList coords = w.elementsByTagName(QStringLiteral("coordinates"));
        QCOMPARE(coords.size(), 5);
        QCOMPARE(coords.at(0).toElement().text(), QStringLiteral("24.0735,56.9765"));

        QDomDocument t = parse(out->templateKml, "template.kml");
        QCOMPARE(texts(t, QStringLiteral("templateType")), QStringList{"waypoint"});
        QCOMPARE(texts(t, QStringLiteral("heightMode")), QStringList{"relativeToStartPoint"});
        QCOMPARE(texts(t, QStringLiteral("coordinateMode")), QStringList{"WGS84"});
        QCOMPARE(texts(t, QStringLiteral("height")), (QStringList{"40", "50", "55", "45", "30"}));
        QVERIFY(out->notices.join('\n').contains(QStringLiteral("level ground")));
    }

    void roundTripsThroughTheImporter()
    {
        const Route route = sampleRoute();
        const Result<WpmlExport> out = writeWpml(route);
        QVERIFY(out.ok());
        const Result<WpmlImport> in = readWpml(out->kmz);
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        QCOMPARE(in->droneName, QStringLiteral("DJI Matrice 350 RTK"));
        QCOMPARE(int(in->routes.size()), 1);
        const Route &back = in->routes.front();
        QCOMPARE(back.settings.endAction, EndAction::ReturnHome);
        QCOMPARE(back.segments.size(), route.segments.size());
        for (size_t i = 0; i < route.segments.size(); ++i) {
            const Waypoint &a = std::get<Waypoint>(route.segments[i]);
            const Waypoint &b = std::get<Waypoint>(back.segments[i]);
            QCOMPARE(b.position, a.position);
            QCOMPARE(b.altitude, a.altitude);
            QCOMPARE(b.altitudeType, a.altitudeType);
            QCOMPARE(b.speed, a.speed);
            QCOMPARE(b.turnType, i == 0 || i + 1 == route.segments.size() ? TurnType::StopAndTurn : a.turnType);
            QCOMPARE(b.actions, a.actions);
        }
        QVERIFY(in->notices.join('\n').contains(QStringLiteral("relative to take-off read as AGL")));
    }

    void amslRoundTripsThroughTheEgm96Template()
    {
        Route route = sampleRoute();
        for (Segment &s : route.segments) {
            std::get<Waypoint>(s).altitudeType = AltitudeType::Amsl;
            std::get<Waypoint>(s).altitude += 100.0;
        }
        WpmlExportOptions o;
        o.heightMode = WpmlHeightMode::Egm96;
        QVERIFY(!writeWpml(route, o).ok());  // no take-off altitude: refused
        QVERIFY(writeWpml(route, o).error().message.contains(QStringLiteral("take-off's AMSL altitude")));
        route.settings.home = HomePosition{{56.9764, 24.0734}, 120.0};
        const Result<WpmlExport> out = writeWpml(route, o);
        QVERIFY(out.ok());
        QDomDocument w = parse(out->waylinesWpml, "waylines.wpml");
        QCOMPARE(texts(w, QStringLiteral("executeHeight")), (QStringList{"20", "30", "35", "25", "10"}));  // above take-off
        QCOMPARE(texts(parse(out->templateKml, "template.kml"), QStringLiteral("heightMode")), QStringList{"EGM96"});
        const Result<WpmlImport> in = readWpml(out->kmz);
        QVERIFY(in.ok());
        const Waypoint &first = std::get<Waypoint>(in->routes.front().segments.front());
        QCOMPARE(first.altitudeType, AltitudeType::Amsl);
        QCOMPARE(first.altitude, 140.0);
    }

    void areaScansFlyTheirPassesWithTheCameraDown()
    {
        Route route;
        route.segments.push_back(wp(56.9760, 24.0700, 60, 8));
        AreaScan scan;
        scan.polygon = {{56.9770, 24.0710}, {56.9770, 24.0740}, {56.9785, 24.0740}, {56.9785, 24.0710}};
        scan.parameters.altitude = 60;
        scan.parameters.speed = 9;
        route.segments.push_back(scan);
        route.segments.push_back(wp(56.9760, 24.0700, 60, 8));
        const Result<WpmlExport> out = writeWpml(route);
        QVERIFY2(out.ok(), out.ok() ? "" : qPrintable(out.error().toString()));
        QVERIFY(out->waypointCount > 6);
        QDomDocument w = parse(out->waylinesWpml, "waylines.wpml");
        QCOMPARE(texts(w, QStringLiteral("actionActuatorFunc")), (QStringList{"gimbalRotate", "takePhoto"}));
        QCOMPARE(texts(w, QStringLiteral("gimbalPitchRotateAngle")), QStringList{"-90"});
        QCOMPARE(texts(w, QStringLiteral("actionTriggerType")), (QStringList{"reachPoint", "multipleDistance"}));
        const double spacing = texts(w, QStringLiteral("actionTriggerParam")).value(0).toDouble();
        QCOMPARE(spacing, footprintAlongMeters(scan.parameters) * 0.25);
        QCOMPARE(texts(w, QStringLiteral("actionGroupStartIndex")), (QStringList{"1", "1"}));
        QCOMPARE(texts(w, QStringLiteral("actionGroupEndIndex")).value(1), QString::number(out->waypointCount - 2));
    }

    void refusesWhatPassesADocumentedLimit_data()
    {
        QTest::addColumn<Route>("route");
        QTest::addColumn<QString>("drone");
        QTest::addColumn<QString>("reason");
        Route many;
        many.segments.reserve(size_t(kWpmlMaxWaypoints) + 1);
        for (int i = 0; i <= kWpmlMaxWaypoints; ++i)
            many.segments.push_back(wp(56.0 + i * 1e-5, 24.0, 50, 5));
        QTest::newRow("too many waypoints") << many << "m350" << "a wayline holds 2 to 65535 waypoints; this route flies 65536";
        Route one;
        one.segments.push_back(wp(56.0, 24.0, 50, 5));
        QTest::newRow("one waypoint") << one << "m350" << "this route flies 1";
        Route close = sampleRoute();
        std::get<Waypoint>(close.segments[2]).position = std::get<Waypoint>(close.segments[1]).position;
        std::get<Waypoint>(close.segments[2]).altitude = 50.2;
        QTest::newRow("too close") << close << "m350" << "at least 0.5 m between adjacent waypoints";
        Route fast = sampleRoute();
        std::get<Waypoint>(fast.segments[3]).speed = 16;
        QTest::newRow("too fast") << fast << "m350" << "row 4: speed 16 m/s is outside the DJI Matrice 350 RTK's waypoint speed range";
        Route high = sampleRoute();
        std::get<Waypoint>(high.segments[1]).altitude = 600;
        QTest::newRow("above the altitude limit") << high << "m3e" << "above the DJI Mavic 3 Enterprise's 500 m altitude limit";
        Route toggle = sampleRoute();
        std::get<Waypoint>(toggle.segments[1]).actions = {CameraTriggerAction{TriggerState::ToggleRecording}};
        QTest::newRow("toggle recording") << toggle << "m350" << "row 2: \"toggle recording\" has no WPML action";
        Route yaw = sampleRoute();
        std::get<Waypoint>(yaw.segments[1]).actions = {CameraControlAction{45, std::nullopt, 10, std::nullopt}};
        QTest::newRow("gimbal yaw") << yaw << "m350" << "row 2: only the gimbal's tilt has a WPML action here";
        Route amsl = sampleRoute();
        std::get<Waypoint>(amsl.segments[0]).altitudeType = AltitudeType::Amsl;
        QTest::newRow("AMSL without a take-off altitude") << amsl << "m350" << "row 1 is AMSL";
        QTest::newRow("unknown drone") << sampleRoute() << "phantom" << "unknown DJI aircraft \"phantom\"";
    }

    void refusesWhatPassesADocumentedLimit()
    {
        QFETCH(Route, route);
        QFETCH(QString, drone);
        QFETCH(QString, reason);
        WpmlExportOptions o;
        o.drone = drone;
        const Result<WpmlExport> out = writeWpml(route, o);
        QVERIFY(!out.ok());
        QVERIFY2(out.error().message.startsWith(QStringLiteral("DJI WPML: ")), qPrintable(out.error().message));
        QVERIFY2(out.error().message.contains(reason), qPrintable(out.error().message));
    }

    void terrainFollowingOnlyWhereTheAircraftHasIt()
    {
        WpmlExportOptions o;
        o.heightMode = WpmlHeightMode::AboveGroundLevel;
        o.drone = QStringLiteral("m300");
        const Result<WpmlExport> refused = writeWpml(sampleRoute(), o);
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().message.contains(QStringLiteral("cannot follow the terrain")));
        o.drone = QStringLiteral("m3e");
        const Result<WpmlExport> out = writeWpml(sampleRoute(), o);
        QVERIFY(out.ok());
        QDomDocument w = parse(out->waylinesWpml, "waylines.wpml");
        QCOMPARE(texts(w, QStringLiteral("executeHeightMode")), QStringList{"realTimeFollowSurface"});
        QCOMPARE(texts(w, QStringLiteral("droneEnumValue")), QStringList{"77"});
        QCOMPARE(texts(w, QStringLiteral("payloadEnumValue")), QStringList{"66"});
        QVERIFY(out->notices.isEmpty());  // AGL written as AGL: nothing approximated
        const Result<WpmlImport> in = readWpml(out->kmz);
        QVERIFY(in.ok());
        QVERIFY(!in->notices.join('\n').contains(QStringLiteral("level ground")));
    }

    void damagedArchivesFailWithTheirReason()
    {
        const QByteArray kmz = writeWpml(sampleRoute())->kmz;
        QByteArray corrupt = kmz;
        corrupt[60] = char(corrupt[60] ^ 0x55);  // inside the first entry's deflated data
        const Result<WpmlImport> a = readWpml(corrupt);
        QVERIFY(!a.ok());
        QVERIFY2(a.error().message.contains(QStringLiteral("template.kml")), qPrintable(a.error().message));
        const Result<WpmlImport> b = readWpml(kmz.left(kmz.size() / 2));
        QVERIFY(!b.ok());
        QVERIFY(b.error().message.contains(QStringLiteral("ZIP")));
        const Result<WpmlImport> c = readWpml(QByteArray("<kml><Document><Folder><Placemark><index>x</index></Placemark></Folder></Document></kml>"));
        QVERIFY(!c.ok());
        QCOMPARE(c.error().line, 1);
    }

    void missionFilesReadAndWriteKmz()
    {
        QTemporaryDir dir;
        Mission m;
        m.name = QStringLiteral("Quay");
        m.routes.push_back(sampleRoute());
        const QString path = dir.filePath(QStringLiteral("quay.kmz"));
        SaveOptions options;
        options.wpml.drone = QStringLiteral("m300");
        const Result<QStringList> saved = saveMission(m, path, options);
        QVERIFY2(saved.ok(), saved.ok() ? "" : qPrintable(saved.error().toString()));
        QCOMPARE(formatForPath(path), std::optional<FileFormat>(FileFormat::Wpml));
        const Result<LoadedMission> loaded = loadMission(path);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded->mission.routes.size(), size_t(1));
        QCOMPARE(loaded->mission.routes.front().settings.profile.name, QStringLiteral("DJI Matrice 300 RTK"));
        QCOMPARE(loaded->mission.routes.front().segments.size(), size_t(5));
        // Written again without naming an aircraft: the route's DJI profile decides.
        const Result<WpmlExport> again = writeWpml(loaded->mission.routes.front());
        QVERIFY(again.ok());
        QVERIFY(again->waylinesWpml.contains("<wpml:droneEnumValue>60</wpml:droneEnumValue>"));
        QVERIFY(!again->notices.join('\n').contains(QStringLiteral("not a DJI aircraft")));
        // A route planned for another vehicle is written for the M350, and says so.
        const Result<WpmlExport> other = writeWpml(sampleRoute());
        QVERIFY(other->waylinesWpml.contains("<wpml:droneEnumValue>89</wpml:droneEnumValue>"));
        QVERIFY(other->notices.join('\n').contains(QStringLiteral("names no DJI aircraft")));
    }
};

QTEST_GUILESS_MAIN(TestWpml)
#include "tst_wpml.moc"
