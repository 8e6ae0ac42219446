// What real DJI WPML files hold and Sortie once lost (issue 21, part 3), against files laid out as
// DJI Pilot 2 and FlightHub 2 write them: the start action group, the time-lapse capture of mapping
// missions, the take-off point, WGS-84 ellipsoidal heights (converted with the EGM96 geoid), several
// waylines, the aircraft beyond the first four; and notices that name wayline and waypoint, one per
// thing not kept.
#include "DjiDroneModels.h"
#include "Egm96Geoid.h"
#include "MissionFiles.h"
#include "RouteStatistics.h"
#include "WpmlFormat.h"
#include "WpmlSamples.h"

#include <QDomDocument>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace wpmlsample;

namespace {

const QString kWpml = QStringLiteral("http://www.dji.com/wpmz/1.0.2");

QStringList texts(const QByteArray &xml, const QString &name)
{
    QDomDocument doc;
    if (!doc.setContent(xml, true))
        qFatal("not XML");
    QStringList out;
    const QDomNodeList nodes = doc.elementsByTagNameNS(kWpml, name);
    for (int i = 0; i < nodes.size(); ++i)
        out << nodes.at(i).toElement().text();
    return out;
}

QStringList matching(const QStringList &notices, const QString &part)
{
    QStringList out;
    for (const QString &n : notices)
        if (n.contains(part))
            out << n;
    return out;
}

const Waypoint &waypoint(const Route &r, size_t i) { return std::get<Waypoint>(r.segments.at(i)); }

QString five(const QString &extra0 = {}, const QString &extra1 = {}, const QString &extra3 = {})
{
    return placemark(0, 40, extra0) + placemark(1, 40, extra1) + placemark(2, 40) + placemark(3, 40, extra3) + placemark(4, 40);
}

struct Run
{
    int code;
    QString err;
};

Run sortiePlan(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(SORTIE_PLAN_BIN), args);
    if (!p.waitForFinished(60000))
        qFatal("sortie-plan did not finish");
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardError())};
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

double undulationAt(double lat, double lon)
{
    QString error;
    const auto geoid = sortie::datum::Egm96Geoid::open(sortie::datum::Egm96Geoid::defaultGridPath(), &error);
    if (!geoid)
        qFatal("%s", qPrintable(error));
    return *geoid->undulation(lat, lon);
}

} // namespace

class TestWpmlImport : public QObject
{
    Q_OBJECT

private slots:
    void startActionsLeadTheFirstWaypointAndGoBack()
    {
        const QString start = el(QStringLiteral("startActionGroup"), gimbalPitch(-45) + action(QStringLiteral("hover"), el(QStringLiteral("hoverTime"), QStringLiteral("2")))
                                                                         + action(QStringLiteral("focus")));
        const QByteArray file = document(drone(77, 0), folder(QStringLiteral("relativeToStartPoint"),
                                                              start + five(group(0, 0, QStringLiteral("reachPoint"), action(QStringLiteral("takePhoto"))))));
        const Result<WpmlImport> in = readWpml(file);
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        const Route &route = in->routes.front();
        const std::vector<WaypointAction> expected = {CameraControlAction{45.0, std::nullopt, std::nullopt, std::nullopt}, WaitAction{2.0, false},
                                                      CameraTriggerAction{TriggerState::SingleShot}};
        QCOMPARE(waypoint(route, 0).actions, expected);
        QCOMPARE(matching(in->notices, QStringLiteral("start actions (gimbalRotate, hover) run at waypoint 1")).size(), 1);
        QCOMPARE(matching(in->notices, QStringLiteral("wayline 1, start actions: the WPML action \"focus\"")).size(), 1);

        // Back out for an aircraft that flies start actions: the leading gimbal tilt is one again.
        WpmlExportOptions o;
        o.drone = QStringLiteral("m3e");
        const Result<WpmlExport> out = writeWpml(route, o);
        QVERIFY2(out.ok(), out.ok() ? "" : qPrintable(out.error().toString()));
        QVERIFY(out->waylinesWpml.contains("<wpml:startActionGroup>"));
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("actionActuatorFunc")), (QStringList{"gimbalRotate", "hover", "takePhoto"}));
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("gimbalPitchRotateAngle")), QStringList{"-45"});
        const Result<WpmlImport> again = readWpml(out->kmz);
        QVERIFY(again.ok());
        QCOMPARE(waypoint(again->routes.front(), 0).actions, expected);
        // The M350 flies none: the tilt is done on reaching waypoint 1.
        o.drone = QStringLiteral("m350");
        const Result<WpmlExport> m350 = writeWpml(route, o);
        QVERIFY(m350.ok());
        QVERIFY(!m350->waylinesWpml.contains("startActionGroup"));
        QCOMPARE(texts(m350->waylinesWpml, QStringLiteral("actionGroupStartIndex")).value(0), QStringLiteral("0"));
    }

    void timeLapseIsATimedPhotoSeries()
    {
        // A mapping mission's capture: startTimeLapse at the first point, stopTimeLapse at the fourth.
        const QString startLapse = group(0, 0, QStringLiteral("reachPoint"),
                                         action(QStringLiteral("startTimeLapse"), el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"))
                                                                                      + el(QStringLiteral("minShootInterval"), QStringLiteral("2"))));
        const QString stopLapse = group(3, 3, QStringLiteral("reachPoint"), action(QStringLiteral("stopTimeLapse")));
        const Result<WpmlImport> in = readWpml(document(drone(77, 2), folder(QStringLiteral("relativeToStartPoint"), five(startLapse, {}, stopLapse))));
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        QCOMPARE(in->droneName, QStringLiteral("DJI Mavic 3 Multispectral"));
        const Route &route = in->routes.front();
        QCOMPARE(waypoint(route, 0).actions, (std::vector<WaypointAction>{CameraSeriesByTimeAction{2.0, 0, 0.0}}));
        QCOMPARE(waypoint(route, 3).actions, (std::vector<WaypointAction>{CameraSeriesByDistanceAction{0.0, 0, 0.0}}));
        QVERIFY2(matching(in->notices, QStringLiteral("TimeLapse")).isEmpty(), qPrintable(in->notices.join('\n')));
        // The photos show: three legs of about 55.7 m at 5 m/s, a photo every 2 s.
        const RouteStatistics stats = computeStatistics(route, nullptr);
        QVERIFY2(stats.photoCount >= 9 && stats.photoCount <= 30, qPrintable(QString::number(stats.photoCount)));
        // Written back as an equal-time capture over the same waypoints, and read back the same.
        const Result<WpmlExport> out = writeWpml(route);
        QVERIFY(out.ok());
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("actionTriggerType")), QStringList{"multipleTiming"});
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("actionTriggerParam")), QStringList{"2"});
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("actionGroupEndIndex")), QStringList{"3"});
        const Result<WpmlImport> again = readWpml(out->kmz);
        QVERIFY(again.ok());
        QCOMPARE(computeStatistics(again->routes.front(), nullptr).photoCount, stats.photoCount);
    }

    void oneNoticePerThingNotKeptNamingWaylineAndWaypoint()
    {
        const QString evenly = group(1, 2, QStringLiteral("betweenAdjacentPoints"),
                                     action(QStringLiteral("gimbalEvenlyRotate"), el(QStringLiteral("gimbalPitchRotateAngle"), QStringLiteral("-60"))));
        const QString repeatedVideo = group(3, 4, QStringLiteral("multipleTiming"), action(QStringLiteral("startRecord")), QStringLiteral("3"));
        const QString risky = el(QStringLiteral("isRisky"), QStringLiteral("1"));
        const QString first = folder(QStringLiteral("relativeToStartPoint"), five({}, evenly + risky, repeatedVideo + risky));
        const QString second = folder(QStringLiteral("relativeToStartPoint"),
                                      five({}, group(1, 1, QStringLiteral("reachPoint"), action(QStringLiteral("customDirName")))));
        const QString config = drone(120, 0) + el(QStringLiteral("exitOnRCLost"), QStringLiteral("goContinue")) + el(QStringLiteral("globalRTHHeight"), QStringLiteral("80"));
        const Result<WpmlImport> in = readWpml(document(config, first + second));
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        QCOMPARE(int(in->routes.size()), 2);
        const QStringList n = in->notices;
        // gimbalEvenlyRotate: one notice, not also "done on reaching the point".
        QCOMPARE(matching(n, QStringLiteral("gimbalEvenlyRotate")), QStringList{"wayline 1, waypoint 2: the gimbal pitched evenly (gimbalEvenlyRotate) over the leg that follows is not kept"});
        QVERIFY(matching(n, QStringLiteral("done on reaching")).isEmpty());
        QCOMPARE(matching(n, QStringLiteral("startRecord")), QStringList{"wayline 1, waypoint 4: a \"startRecord\" repeated by multipleTiming is not kept"});
        QCOMPARE(matching(n, QStringLiteral("customDirName")), QStringList{"wayline 2, waypoint 2: the WPML action \"customDirName\" has no Sortie equivalent and is not kept"});
        QCOMPARE(matching(n, QStringLiteral("isRisky")), QStringList{"wayline 1, waypoints 2, 4: wpml:isRisky is not kept"});
        QCOMPARE(matching(n, QStringLiteral("droneEnumValue 120/0 is not an aircraft Sortie knows")).size(), 1);
        QCOMPARE(matching(n, QStringLiteral("wpml:globalRTHHeight")).size(), 1);
        QCOMPARE(matching(n, QStringLiteral("wpml:exitOnRCLost \"goContinue\" (written as \"executeLostAction\")")).size(), 1);
        QVERIFY(in->droneName.isEmpty());
        // One finish action: it ends the last wayline only.
        QCOMPARE(in->routes[0].settings.endAction, EndAction::None);
        QCOMPARE(in->routes[1].settings.endAction, EndAction::ReturnHome);
    }

    void aFileSortieWroteComesBackWithoutNotices()
    {
        Route r;
        for (int i = 0; i < 3; ++i) {
            Waypoint w;
            w.position = {56.976 + i * 0.001, 24.07};
            w.altitude = 50;
            w.altitudeType = AltitudeType::Amsl;
            w.speed = 6;
            r.segments.push_back(w);
        }
        r.settings.home = HomePosition{{56.9755, 24.07}, 12.0};
        WpmlExportOptions o;
        o.drone = QStringLiteral("m3e");
        const Result<WpmlExport> out = writeWpml(r, o);
        QVERIFY(out.ok());
        const Result<WpmlImport> in = readWpml(out->kmz);
        QVERIFY(in.ok());
        QVERIFY2(in->notices.isEmpty(), qPrintable(in->notices.join('\n')));
    }

    void takeOffPointIsKeptAndWrittenBack()
    {
        // FlightHub 2 writes the take-off point in the template; its height is ellipsoidal.
        const QString takeoff = el(QStringLiteral("takeOffRefPoint"), QStringLiteral("56.9755,24.07,140.5"));
        const QString templFolder = QStringLiteral("<Folder>") + el(QStringLiteral("templateType"), QStringLiteral("waypoint"))
                                    + el(QStringLiteral("waylineCoordinateSysParam"), el(QStringLiteral("coordinateMode"), QStringLiteral("WGS84"))
                                                                                            + el(QStringLiteral("heightMode"), QStringLiteral("relativeToStartPoint")))
                                    + placemark(0, 40, {}, QStringLiteral("height")) + placemark(1, 55, {}, QStringLiteral("height")) + QStringLiteral("</Folder>");
        const QByteArray waylines = document(drone(91, 0), folder(QStringLiteral("relativeToStartPoint"), placemark(0, 40) + placemark(1, 55)));
        const Result<WpmlImport> in = readWpml(kmz(waylines, document(drone(91, 0) + takeoff, templFolder)));
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        QCOMPARE(in->droneName, QStringLiteral("DJI Matrice 3D"));
        const Route &route = in->routes.front();
        QVERIFY(route.settings.home);
        // 140.5 m above the ellipsoid where the geoid is 20.50 m above it (tst_egm96geoid's table).
        const double takeoffAmsl = route.settings.home->altitudeAmsl;
        QVERIFY2(std::abs(takeoffAmsl - (140.5 - 20.50)) < 0.05, qPrintable(QString::number(takeoffAmsl)));
        QCOMPARE(route.settings.home->position, (GeoPoint{56.9755, 24.07}));
        // Heights above take-off with its AMSL altitude known are AMSL, exactly; no level-ground notice.
        QCOMPARE(waypoint(route, 1).altitudeType, AltitudeType::Amsl);
        QVERIFY(std::abs(waypoint(route, 1).altitude - (takeoffAmsl + 55)) < 1e-9);
        QVERIFY2(matching(in->notices, QStringLiteral("level ground")).isEmpty(), qPrintable(in->notices.join('\n')));

        // AMSL again without being told the take-off altitude: the file held it.
        QTemporaryDir dir;
        Mission m;
        m.routes.push_back(route);
        SaveOptions options;
        options.wpml.heightMode = WpmlHeightMode::Egm96;
        const QString path = dir.filePath(QStringLiteral("again.kmz"));
        const Result<QStringList> saved = saveMission(m, path, options);
        QVERIFY2(saved.ok(), saved.ok() ? "" : qPrintable(saved.error().toString()));
        const Result<WpmlImport> back = readWpml([&] { QFile f(path); f.open(QIODevice::ReadOnly); return f.readAll(); }());
        QVERIFY(back.ok());
        QCOMPARE(back->routes.front().settings.home->position, route.settings.home->position);
        QVERIFY(std::abs(back->routes.front().settings.home->altitudeAmsl - takeoffAmsl) < 0.002);
        QVERIFY(std::abs(waypoint(back->routes.front(), 1).altitude - waypoint(route, 1).altitude) < 0.002);
    }

    void wgs84HeightsAreConvertedWithTheGeoid()
    {
        // 120.5 m above the ellipsoid at waypoint 0 (56.976, 24.07), where N is 20.50 m.
        const QByteArray file = document(drone(67, 1, 53), folder(QStringLiteral("WGS84"), placemark(0, 120.5) + placemark(1, 130.5)));
        const Result<WpmlImport> in = readWpml(file);
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        QCOMPARE(in->droneName, QStringLiteral("DJI Matrice 30T"));
        const Waypoint &w = waypoint(in->routes.front(), 0);
        QCOMPARE(w.altitudeType, AltitudeType::Amsl);
        const double n = undulationAt(56.976, 24.07);
        QVERIFY(std::abs(n - 20.50) < 0.02);
        QVERIFY(std::abs(w.altitude - (120.5 - n)) < 1e-6);
        QVERIFY(matching(in->notices, QStringLiteral("WGS-84")).isEmpty());

        // Without the grid: an error naming it, never the numbers passed through as AMSL.
        QTemporaryDir dir;
        WpmlReadOptions noGrid;
        noGrid.geoid.gridPath = dir.filePath(QStringLiteral("egm96_15.gtx"));
        const Result<WpmlImport> refused = readWpml(file, noGrid);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(noGrid.geoid.gridPath) && refused.error().message.contains(QStringLiteral("wayline 1, waypoint 1")),
                 qPrintable(refused.error().message));

        // Written back in WGS-84: ellipsoidal in the waylines, EGM96 in the template, and read back.
        WpmlExportOptions o;
        o.heightMode = WpmlHeightMode::Wgs84;
        const Result<WpmlExport> out = writeWpml(in->routes.front(), o);
        QVERIFY2(out.ok(), out.ok() ? "" : qPrintable(out.error().toString()));
        QCOMPARE(texts(out->waylinesWpml, QStringLiteral("executeHeightMode")), QStringList{"WGS84"});
        QVERIFY(std::abs(texts(out->waylinesWpml, QStringLiteral("executeHeight")).value(0).toDouble() - 120.5) < 1e-6);
        QCOMPARE(texts(out->templateKml, QStringLiteral("heightMode")), QStringList{"EGM96"});
        const Result<WpmlImport> back = readWpml(out->kmz);
        QVERIFY(back.ok());
        QVERIFY(std::abs(waypoint(back->routes.front(), 0).altitude - w.altitude) < 1e-6);
        o.geoid.gridPath = noGrid.geoid.gridPath;
        const Result<WpmlExport> noGeoid = writeWpml(in->routes.front(), o);
        QVERIFY(!noGeoid.ok());
        QVERIFY(noGeoid.error().message.contains(QStringLiteral("proj-data")));
    }

    void aMappingFileOverRisingGroundConvertsWithTheAircraftsLimit()
    {
        // As DJI Pilot 2 writes a mapping mission over rising ground: WGS-84 heights, the take-off
        // point in the file, waypoints 135.6 m above it (not above the ground under them). A WPML
        // file states no altitude limit, so the route keeps its aircraft's, and the conversion
        // writes the file rather than refusing it on Sortie's default of 120 m.
        const double takeoffEllipsoid = 568.55;
        const QString takeoff = el(QStringLiteral("takeOffRefPoint"), QStringLiteral("56.9755,24.07,%1").arg(takeoffEllipsoid));
        const QByteArray file = document(drone(77, 0) + takeoff, folder(QStringLiteral("WGS84"), placemark(0, takeoffEllipsoid + 100.0)
                                                                                                     + placemark(1, takeoffEllipsoid + 135.6)
                                                                                                     + placemark(2, takeoffEllipsoid + 120.0)));
        const Result<WpmlImport> in = readWpml(file);
        QVERIFY2(in.ok(), in.ok() ? "" : qPrintable(in.error().toString()));
        const DjiDroneModel *m3e = findDjiDroneModel(QStringLiteral("m3e"));
        QVERIFY(m3e);
        QCOMPARE(in->routes.front().settings.maxAltitude, m3e->maxAltitudeLimit);

        QTemporaryDir dir;
        const QString kmzPath = dir.filePath(QStringLiteral("mapping.kmz"));
        QVERIFY(writeFile(kmzPath, kmz(file)));
        const Run converted = sortiePlan({QStringLiteral("convert"), kmzPath, dir.filePath(QStringLiteral("mapping.sortie"))});
        QVERIFY2(converted.code == 0, qPrintable(converted.err));
        QVERIFY2(!converted.err.contains(QStringLiteral("altitude-above-max")), qPrintable(converted.err));
        const Result<LoadedMission> loaded = loadMission(dir.filePath(QStringLiteral("mapping.sortie")));
        QVERIFY(loaded.ok());
        QCOMPARE(loaded->mission.routes.front().settings.maxAltitude, m3e->maxAltitudeLimit);

        // Held to a limit of 120 m above the take-off point, the conversion still writes the file
        // and names what was compared; --strict refuses it and writes nothing.
        Mission held = loaded->mission;
        held.routes.front().settings.maxAltitude = 120.0;
        QVERIFY(saveMission(held, dir.filePath(QStringLiteral("held.sortie")), {std::nullopt, ValidationOverride::AcceptErrors, {}}).ok());
        const Run written = sortiePlan({QStringLiteral("convert"), dir.filePath(QStringLiteral("held.sortie")), dir.filePath(QStringLiteral("held.kmz"))});
        QVERIFY2(written.code == 0, qPrintable(written.err));
        QVERIFY2(written.err.contains(QStringLiteral("Waypoint 2: 135.6 m above the take-off point")) && written.err.contains(QStringLiteral("the route's limit is 120 m above it")),
                 qPrintable(written.err));
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("held.kmz"))));
        const Run strict = sortiePlan({QStringLiteral("convert"), dir.filePath(QStringLiteral("held.sortie")), dir.filePath(QStringLiteral("strict.kmz")), QStringLiteral("--strict")});
        QCOMPARE(strict.code, 2);
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("strict.kmz"))));
    }

    void severalWaylinesAllWrittenOrRefusedWithTheReason()
    {
        const QByteArray two = document(drone(89, 0), folder(QStringLiteral("relativeToStartPoint"), five()) + folder(QStringLiteral("relativeToStartPoint"), placemark(0, 60) + placemark(1, 70)));
        const Result<WpmlImport> in = readWpml(two);
        QVERIFY(in.ok());
        QCOMPARE(int(in->routes.size()), 2);
        Mission m;
        m.routes = in->routes;
        QTemporaryDir dir;
        // .kmz: both waylines, in order, one finish action after the last.
        const QString kmzPath = dir.filePath(QStringLiteral("both.kmz"));
        const Result<QStringList> saved = saveMission(m, kmzPath);
        QVERIFY2(saved.ok(), saved.ok() ? "" : qPrintable(saved.error().toString()));
        const Result<LoadedMission> loaded = loadMission(kmzPath);
        QVERIFY(loaded.ok());
        QCOMPARE(int(loaded->mission.routes.size()), 2);
        QCOMPARE(loaded->mission.routes[1].segments.size(), size_t(2));
        QCOMPARE(loaded->mission.routes[1].settings.endAction, EndAction::ReturnHome);
        // A one-route format: refused with the reason unless a route is chosen.
        const QString planPath = dir.filePath(QStringLiteral("one.plan"));
        const Result<QStringList> refused = saveMission(m, planPath);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QStringLiteral("has 2 routes")) && refused.error().message.contains(QStringLiteral("--route")),
                 qPrintable(refused.error().message));
        QVERIFY(!QFile::exists(planPath));
        SaveOptions second;
        second.routeIndex = 1;
        QVERIFY(saveMission(m, planPath, second).ok());
        QCOMPARE(loadMission(planPath)->mission.routes.front().segments.size(), size_t(2));
        // An earlier wayline cannot return home: the file has one finish action.
        m.routes[0].settings.endAction = EndAction::ReturnHome;
        const Result<QStringList> early = saveMission(m, dir.filePath(QStringLiteral("early.kmz")));
        QVERIFY(!early.ok());
        QVERIFY2(early.error().message.contains(QStringLiteral("route 1 (\"Wayline 1\") ends by returning home")), qPrintable(early.error().message));
    }

    void sortiePlanConvertKeepsWhatTheFileHeld()
    {
        QTemporaryDir dir;
        // Two waylines to a one-route format: refused with the reason; --route chooses.
        const QString two = dir.filePath(QStringLiteral("two.kmz"));
        QVERIFY(writeFile(two, kmz(document(drone(89, 0), folder(QStringLiteral("relativeToStartPoint"), five())
                                                              + folder(QStringLiteral("relativeToStartPoint"), placemark(0, 60) + placemark(1, 70))))));
        const Run refused = sortiePlan({QStringLiteral("convert"), two, dir.filePath(QStringLiteral("two.plan"))});
        QVERIFY(refused.code != 0);
        QVERIFY2(refused.err.contains(QStringLiteral("the mission has 2 routes")), qPrintable(refused.err));
        QCOMPARE(sortiePlan({QStringLiteral("convert"), two, dir.filePath(QStringLiteral("two.plan")), QStringLiteral("--route"), QStringLiteral("2")}).code, 0);
        QCOMPARE(sortiePlan({QStringLiteral("convert"), two, dir.filePath(QStringLiteral("both.kmz"))}).code, 0);
        QCOMPARE(int(loadMission(dir.filePath(QStringLiteral("both.kmz")))->mission.routes.size()), 2);
        // AMSL heights without --takeoff-amsl: the file's take-off point gives the altitude.
        const QString withTakeoff = dir.filePath(QStringLiteral("takeoff.kmz"));
        const QString takeoff = el(QStringLiteral("takeOffRefPoint"), QStringLiteral("56.9755,24.07,140.5"));
        QVERIFY(writeFile(withTakeoff, kmz(document(drone(89, 0) + takeoff, folder(QStringLiteral("relativeToStartPoint"), five())))));
        const Run amsl = sortiePlan({QStringLiteral("convert"), withTakeoff, dir.filePath(QStringLiteral("amsl.kmz")), QStringLiteral("--height"), QStringLiteral("amsl")});
        QVERIFY2(amsl.code == 0, qPrintable(amsl.err));
        QFile out(dir.filePath(QStringLiteral("amsl.kmz")));
        QVERIFY(out.open(QIODevice::ReadOnly));
        const Result<std::vector<ZipEntry>> entries = readZip(out.readAll());
        QVERIFY(entries.ok());
        QCOMPARE(texts(entries->at(1).data, QStringLiteral("executeHeight")).value(0).toDouble(), 40.0);
        QVERIFY(texts(entries->at(0).data, QStringLiteral("takeOffRefPoint")).value(0).startsWith(QStringLiteral("56.9755,24.07,140.5")));
    }

    void everyKnownAircraftIsOfferedAndRecognised()
    {
        Route r;
        for (int i = 0; i < 2; ++i) {
            Waypoint w;
            w.position = {56.976 + i * 0.001, 24.07};
            w.altitude = 50;
            w.speed = 6;
            r.segments.push_back(w);
        }
        QVERIFY(djiDroneKeys().contains(QStringLiteral("m30t")) && djiDroneKeys().contains(QStringLiteral("m3td")));
        for (const DjiDroneModel &model : djiDroneModels()) {
            WpmlExportOptions o;
            o.drone = model.key;
            const Result<WpmlExport> out = writeWpml(r, o);
            QVERIFY2(out.ok(), qPrintable(model.key));
            QCOMPARE(texts(out->waylinesWpml, QStringLiteral("droneEnumValue")), QStringList{QString::number(model.droneEnumValue)});
            QCOMPARE(texts(out->waylinesWpml, QStringLiteral("droneSubEnumValue")), QStringList{QString::number(model.droneSubEnumValue)});
            QCOMPARE(texts(out->waylinesWpml, QStringLiteral("payloadEnumValue")), QStringList{QString::number(model.payloads.front().enumValue)});
            const Result<WpmlImport> in = readWpml(out->kmz);
            QVERIFY(in.ok());
            QCOMPARE(in->droneName, model.name);
        }
        // DJI's documented values (Cloud API, "Enumeration Values of Aircraft" and "of Camera").
        const auto enums = [](const char *key) {
            const DjiDroneModel *m = findDjiDroneModel(QString::fromLatin1(key));
            return m ? QStringLiteral("%1/%2 %3").arg(m->droneEnumValue).arg(m->droneSubEnumValue).arg(m->payloads.front().enumValue) : QString();
        };
        QCOMPARE(enums("m30"), QStringLiteral("67/0 52"));
        QCOMPARE(enums("m30t"), QStringLiteral("67/1 53"));
        QCOMPARE(enums("m3m"), QStringLiteral("77/2 68"));
        QCOMPARE(enums("m3d"), QStringLiteral("91/0 80"));
        QCOMPARE(enums("m3td"), QStringLiteral("91/1 81"));
        QCOMPARE(enums("m4e"), QStringLiteral("99/0 88"));
        QCOMPARE(enums("m4t"), QStringLiteral("99/1 89"));
        QCOMPARE(enums("m4d"), QStringLiteral("100/0 98"));
        QCOMPARE(enums("m4td"), QStringLiteral("100/1 99"));
        // A payload the route cannot keep is told.
        const Result<WpmlImport> h20t = readWpml(document(drone(89, 0, 43), folder(QStringLiteral("relativeToStartPoint"), placemark(0, 40) + placemark(1, 40))));
        QVERIFY(h20t.ok());
        QCOMPARE(matching(h20t->notices, QStringLiteral("--payload h20t")).size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestWpmlImport)
#include "tst_wpmlimport.moc"
