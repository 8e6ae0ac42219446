// sortie-plan airspace (and stats --zones), run as a process over route and zone files the test
// writes: the JSON keys the issue names, legs numbered as `profile` numbers them, the exit codes.
#include "Geodesy.h"
#include "TestData.h"
#include "HgtWriter.h"
#include "JsonCursor.h"
#include "MissionFiles.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTimeZone>
#include "PlanRun.h"

#include <QtTest>

using namespace sortie::mission;
using Json = sortie::mission::formats::Json;

namespace {
using Run = sortie::test::PlanRun;
Run run(const QStringList &args) { return sortie::test::runPlan(args); }

const GeoPoint kOrigin{56.95, 24.1};

GeoPoint east(double metres) { return geodesicDirect(kOrigin, 90, metres).point; }

// Three waypoints 1000 m apart going east, 30 m above the ground.
Mission lineMission()
{
    Route r;
    r.settings.name = QStringLiteral("line");
    r.settings.home = HomePosition{kOrigin, 0};
    for (int i = 0; i <= 2; ++i) {
        Waypoint w;
        w.position = east(1000.0 * i);
        w.altitude = 30;
        w.speed = 10;
        r.segments.push_back(w);
    }
    Mission m;
    m.name = QStringLiteral("line");
    m.routes.push_back(r);
    return m;
}

// A box across the line from `from` to `to` metres east, 200 m wide.
QByteArray box(const QString &name, double from, double to, const QString &limits)
{
    QStringList ring;
    for (const auto &[along, north] : {std::pair{from, -100.0}, {to, -100.0}, {to, 100.0}, {from, 100.0}, {from, -100.0}}) {
        const GeoPoint p = geodesicDirect(east(along), north < 0 ? 180 : 0, std::abs(north)).point;
        ring << QStringLiteral("[%1, %2]").arg(p.longitude, 0, 'f', 9).arg(p.latitude, 0, 'f', 9);
    }
    return QStringLiteral(R"({"type": "Feature", "properties": {"name": "%1"%2}, "geometry": {"type": "Polygon", "coordinates": [[%3]]}})")
        .arg(name, limits, ring.join(QStringLiteral(", ")))
        .toUtf8();
}

// The same box as an ED-269 zone (identifier, restriction, applicability and more as JSON members).
QByteArray ed269Box(const QString &id, const QString &name, double from, double to, const QString &members)
{
    QStringList ring;
    for (const auto &[along, north] : {std::pair{from, -100.0}, {to, -100.0}, {to, 100.0}, {from, 100.0}, {from, -100.0}}) {
        const GeoPoint p = geodesicDirect(east(along), north < 0 ? 180 : 0, std::abs(north)).point;
        ring << QStringLiteral("[%1, %2]").arg(p.longitude, 0, 'f', 9).arg(p.latitude, 0, 'f', 9);
    }
    return QStringLiteral(R"({"identifier": "%1", "country": "LVA", "name": "%2", %3,
        "geometry": [{"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AGL", "upperLimit": 120, "upperVerticalReference": "AGL",
                      "horizontalProjection": {"type": "Polygon", "coordinates": [[%4]]}}]})")
        .arg(id, name, members, ring.join(QStringLiteral(", ")))
        .toUtf8();
}

bool near(double a, double b, double tolerance = 1.0)
{
    return std::abs(a - b) <= tolerance;
}
} // namespace

class TstPlanAirspace : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(formats::saveMission(lineMission(), path("line.sortie")).ok());
        write("ctr.geojson", "{\"type\": \"FeatureCollection\", \"features\": [" +
                                 box(QStringLiteral("RIX CTR"), 1210, 1460, QStringLiteral(R"(, "ceiling": 150, "reference": "AGL")")) +
                                 ", {\"type\": \"Feature\", \"properties\": {\"name\": \"bad\"}, \"geometry\": null}]}");
        // The law's zones along the line: forbidden on weekend evenings over leg 2, an airfield that
        // needs an authorisation over leg 1, a park with conditions, a model field with none.
        write("lv-zones.json", "{\"title\": \"test\", \"features\": [" +
              ed269Box(QStringLiteral("LVP100"), QStringLiteral("Weekend evenings"), 1210, 1460, QStringLiteral(
                  R"("restriction": "PROHIBITED", "zoneAuthority": [], "applicability": [{"permanent": "NO",
                     "schedule": [{"day": ["SAT", "SUN"], "startTime": "18:00Z", "endTime": "23:00Z"}]}])")) + ", " +
              ed269Box(QStringLiteral("LVA200"), QStringLiteral("Airfield"), 300, 600, QStringLiteral(
                  R"("restriction": "REQ_AUTHORISATION", "applicability": [{"permanent": "YES"}],
                     "zoneAuthority": [{"name": "LGS", "email": "uas@lgs.example", "purpose": "AUTHORIZATION"}])")) + ", " +
              ed269Box(QStringLiteral("LVC300"), QStringLiteral("Park"), 1700, 1800, QStringLiteral(
                  R"("restriction": "CONDITIONAL", "message": "Keep 50 m from people", "applicability": [], "zoneAuthority": [])")) + ", " +
              ed269Box(QStringLiteral("LVN400"), QStringLiteral("Model field"), 100, 200, QStringLiteral(
                  R"("restriction": "NO_RESTRICTION", "applicability": [], "zoneAuthority": [])")) + "]}");
        write("high.geojson", "{\"type\": \"FeatureCollection\", \"features\": [" +
                                  box(QStringLiteral("High"), 1210, 1460, QStringLiteral(R"(, "floor": 200, "ceiling": 400, "reference": "AGL")")) + "]}");
        write("amsl.geojson", "{\"type\": \"FeatureCollection\", \"features\": [" +
                                  box(QStringLiteral("Band"), 1210, 1460, QStringLiteral(R"(, "floor": 50, "ceiling": 150)")) + ", " +
                                  box(QStringLiteral("Above"), 300, 600, QStringLiteral(R"(, "floor": 200)")) + "]}");
        // A WPL route: home (item 0, not a leg), then three items at 100 m above the geoid (frame 0).
        QByteArray wpl = "QGC WPL 110\n";
        wpl += QStringLiteral("0\t1\t0\t16\t0\t0\t0\t0\t%1\t%2\t10\t1\n").arg(kOrigin.latitude, 0, 'f', 9).arg(kOrigin.longitude, 0, 'f', 9).toUtf8();
        for (int i = 0; i <= 2; ++i)
            wpl += QStringLiteral("%1\t0\t0\t16\t0\t0\t0\t0\t%2\t%3\t100\t1\n").arg(i + 1).arg(east(1000.0 * i).latitude, 0, 'f', 9)
                       .arg(east(1000.0 * i).longitude, 0, 'f', 9).toUtf8();
        write("line.waypoints", wpl);
        // A .plan fence around everything: the route stays inside.
        write("fence.plan", QStringLiteral(R"({"fileType": "Plan", "version": 1, "geoFence": {"version": 2, "circles": [
            {"inclusion": true, "version": 1, "circle": {"center": [%1, %2], "radius": 5000}}], "polygons": []},
            "rallyPoints": {"version": 2, "points": []}, "mission": {"version": 2, "items": []}})")
                                .arg(kOrigin.latitude, 0, 'f', 9).arg(kOrigin.longitude, 0, 'f', 9).toUtf8());
    }

    // The route enters RIX CTR on its second leg from 1,210 m to 1,460 m: exit 2, the keys, the bad
    // feature named on stderr and the good one kept.
    void aRouteThroughAZoneExitsTwo()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("ctr.geojson"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json doc = Json::parse(r.out.toStdString());
        const Json &route = doc.at("routes").at(0);
        QCOMPARE(route.at("name").get<std::string>(), std::string("line"));
        const Json &a = route.at("airspace");
        QCOMPARE(a.at("zones").get<int>(), 1);
        QCOMPARE(a.at("violations").size(), size_t(1));
        const Json &v = a.at("violations").at(0);
        for (const char *key : {"zone", "kind", "leg", "fromDistance", "toDistance"})
            QVERIFY2(v.contains(key), key);
        QCOMPARE(v.at("zone").get<std::string>(), std::string("RIX CTR"));
        QCOMPARE(v.at("kind").get<std::string>(), std::string("inside-exclusion"));
        QCOMPARE(v.at("leg").get<int>(), 2);
        QVERIFY2(near(v.at("fromDistance").get<double>(), 1210) && near(v.at("toDistance").get<double>(), 1460), v.dump().c_str());
        QVERIFY2(r.err.contains("feature 2 ('bad')") && r.err.contains("no geometry"), r.err.constData());

        const Run text = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("ctr.geojson")});
        QCOMPARE(text.code, 2);
        QVERIFY2(text.out.contains("Leg 2 enters 'RIX CTR' from 1,210 m to 1,460 m (floor ground, ceiling 150 m AGL)"), text.out.constData());
    }

    // Under a zone's floor, inside a fence: exit 0; a leg near a zone: a warning, still exit 0.
    void aRouteClearOfZonesExitsZero()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("high.geojson"), QStringLiteral("--zones"),
                           path("fence.plan"), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const Json a = Json::parse(r.out.toStdString()).at("routes").at(0).at("airspace");
        QCOMPARE(a.at("zones").get<int>(), 2);
        QVERIFY(a.at("violations").empty());
        QVERIFY(a.at("warnings").empty());
        // A 200 m buffer: 170 m under the floor is now near.
        const Run wide = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("high.geojson"), QStringLiteral("--buffer"),
                              QStringLiteral("200"), QStringLiteral("--json")});
        QCOMPARE(wide.code, 0);
        const Json w = Json::parse(wide.out.toStdString()).at("routes").at(0).at("airspace").at("warnings");
        QCOMPARE(w.size(), size_t(1));
        QCOMPARE(w.at(0).at("leg").get<int>(), 2);
        QVERIFY(near(w.at(0).at("clearance").get<double>(), 170, 0.01));
    }

    // WPL frame 0 is AMSL; the home item is no leg: the band 50..150 m AMSL is entered on leg 2, the
    // zone above 200 m is passed under.
    void aWplRouteAsProfileNumbersIt()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.waypoints"), QStringLiteral("--zones"), path("amsl.geojson"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json a = Json::parse(r.out.toStdString()).at("routes").at(0).at("airspace");
        QCOMPARE(a.at("violations").size(), size_t(1));
        QCOMPARE(a.at("violations").at(0).at("zone").get<std::string>(), std::string("Band"));
        QCOMPARE(a.at("violations").at(0).at("leg").get<int>(), 2);
        QVERIFY(!a.at("violations").at(0).at("heightUnknown").get<bool>());
        QVERIFY(near(a.at("violations").at(0).at("fromDistance").get<double>(), 1210));
    }

    // An AGL route against AMSL zones: without terrain its AMSL height is unknown, so both zones'
    // shadows count (flagged); over flat ground at 100 m (--dem) it flies at 130 m AMSL: inside the
    // 50..150 m band, under the zone above 200 m.
    void theGroundDecidesAglAgainstAmsl()
    {
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("dem")));
        QVERIFY(sortie::terrain::test::writeHgt(path("dem/N56E024.hgt"), 1201, [](int, int) { return 100; }));
        const Run blind = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("amsl.geojson"), QStringLiteral("--json")});
        QCOMPARE(blind.code, 2);
        const Json b = Json::parse(blind.out.toStdString()).at("routes").at(0).at("airspace").at("violations");
        QCOMPARE(b.size(), size_t(2));
        QVERIFY(b.at(0).at("heightUnknown").get<bool>() && b.at(1).at("heightUnknown").get<bool>());
        const Run seen = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("amsl.geojson"), QStringLiteral("--dem"),
                              path("dem"), QStringLiteral("--json")});
        QCOMPARE(seen.code, 2);
        const Json v = Json::parse(seen.out.toStdString()).at("routes").at(0).at("airspace").at("violations");
        QCOMPARE(v.size(), size_t(1));
        QCOMPARE(v.at(0).at("zone").get<std::string>(), std::string("Band"));
        QVERIFY(!v.at(0).at("heightUnknown").get<bool>());
        QVERIFY(near(v.at(0).at("fromDistance").get<double>(), 1210) && near(v.at(0).at("toDistance").get<double>(), 1460));
    }

    void statsAddsTheZonesToTheIssues()
    {
        const Run r = run({QStringLiteral("stats"), path("line.sortie"), QStringLiteral("--zones"), path("ctr.geojson"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json route = Json::parse(r.out.toStdString()).at("routes").at(0);
        QVERIFY2(route.at("validation").dump().find("airspace-exclusion") != std::string::npos, route.at("validation").dump().c_str());
        QCOMPARE(route.at("airspace").at("violations").size(), size_t(1));
        const Run clear = run({QStringLiteral("stats"), path("line.sortie"), QStringLiteral("--zones"), path("high.geojson")});
        QCOMPARE(clear.code, 0);
    }

    // A Saturday-evening flight is refused by the weekend zone and by the airfield (no
    // authorisation); the park is a warning with its message, the model field information.
    void geographicalZonesOnASaturdayEvening()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--at"),
                           QStringLiteral("2026-06-06T18:30:00Z"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json a = Json::parse(r.out.toStdString()).at("routes").at(0).at("airspace");
        QCOMPARE(a.at("zones").get<int>(), 4);
        QCOMPARE(a.at("zonesOutsideWindow").get<int>(), 0);
        QCOMPARE(a.at("window").at("from").get<std::string>(), std::string("2026-06-06T18:30:00Z"));
        QVERIFY(a.at("window").at("to").get<std::string>() > std::string("2026-06-06T18:33:00Z"));  // 2 km at 10 m/s, and the climb
        const Json &v = a.at("violations");
        QCOMPARE(v.size(), size_t(2));
        QCOMPARE(v.at(0).at("identifier").get<std::string>(), std::string("LVA200"));
        QCOMPARE(v.at(0).at("restriction").get<std::string>(), std::string("REQ_AUTHORISATION"));
        QCOMPARE(v.at(0).at("volume").get<int>(), 1);
        QCOMPARE(v.at(0).at("leg").get<int>(), 1);
        QVERIFY2(near(v.at(0).at("fromDistance").get<double>(), 300) && near(v.at(0).at("toDistance").get<double>(), 600), v.dump().c_str());
        QVERIFY2(v.at(0).at("message").get<std::string>().find("needs an authorisation; none is recorded") != std::string::npos, v.dump().c_str());
        QVERIFY2(v.at(0).at("message").get<std::string>().find("uas@lgs.example") != std::string::npos, v.dump().c_str());
        QCOMPARE(v.at(1).at("identifier").get<std::string>(), std::string("LVP100"));
        QCOMPARE(v.at(1).at("restriction").get<std::string>(), std::string("PROHIBITED"));
        QCOMPARE(v.at(1).at("leg").get<int>(), 2);
        for (const char *key : {"zone", "kind", "leg", "fromDistance", "toDistance", "message"})
            QVERIFY2(v.at(1).contains(key), key);
        const Json &w = a.at("warnings");
        QCOMPARE(w.size(), size_t(1));
        QCOMPARE(w.at(0).at("identifier").get<std::string>(), std::string("LVC300"));
        QCOMPARE(w.at(0).at("restriction").get<std::string>(), std::string("CONDITIONAL"));
        QVERIFY2(w.at(0).at("message").get<std::string>().find("Keep 50 m from people") != std::string::npos, w.dump().c_str());
        const Json &info = a.at("information");
        QCOMPARE(info.size(), size_t(1));
        QCOMPARE(info.at(0).at("identifier").get<std::string>(), std::string("LVN400"));
        QCOMPARE(info.at(0).at("restriction").get<std::string>(), std::string("NO_RESTRICTION"));

        const Run text = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--at"),
                              QStringLiteral("2026-06-06T18:30:00Z")});
        QCOMPARE(text.code, 2);
        QVERIFY2(text.out.contains("error: Leg 2 enters the prohibited zone 'Weekend evenings' (LVP100, volume 1) from 1,210 m to 1,460 m"), text.out.constData());
        QVERIFY2(text.out.contains("warning: Leg 2 enters the conditional zone 'Park' (LVC300, volume 1)"), text.out.constData());
        QVERIFY2(text.out.contains("information: Leg 1 passes through 'Model field' (LVN400, volume 1)"), text.out.constData());
    }

    // On a Monday evening the weekend zone does not apply; with the airfield's authorisation
    // recorded it is a warning naming it: exit 0.
    void geographicalZonesOnAMondayWithAnAuthorisation()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--at"),
                           QStringLiteral("2026-06-08T18:30:00Z"), QStringLiteral("--authorisation"), QStringLiteral("LVA200=LGS-2026-117"),
                           QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const Json a = Json::parse(r.out.toStdString()).at("routes").at(0).at("airspace");
        QCOMPARE(a.at("zones").get<int>(), 3);
        QCOMPARE(a.at("zonesOutsideWindow").get<int>(), 1);
        QCOMPARE(a.at("violations").size(), size_t(0));
        const Json &w = a.at("warnings");
        QCOMPARE(w.size(), size_t(2));
        QCOMPARE(w.at(0).at("identifier").get<std::string>(), std::string("LVA200"));
        QCOMPARE(w.at(0).at("authorisation").get<std::string>(), std::string("LGS-2026-117"));
        QVERIFY2(w.at(0).at("message").get<std::string>().find("under authorisation LGS-2026-117") != std::string::npos, w.dump().c_str());
        QCOMPARE(w.at(1).at("identifier").get<std::string>(), std::string("LVC300"));

        // Without the authorisation the airfield is an error again; an unknown identifier is noted.
        const Run unknown = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--at"),
                                 QStringLiteral("2026-06-08T18:30:00Z"), QStringLiteral("--authorisation"), QStringLiteral("XX999=R1")});
        QCOMPARE(unknown.code, 2);
        QVERIFY2(unknown.err.contains("--authorisation XX999: no UAS geographical zone has that identifier"), unknown.err.constData());
        QVERIFY2(unknown.out.contains("1 zone(s) do not apply from 2026-06-08T18:30:00Z"), unknown.out.constData());
    }

    // The route file's own planned start and authorisations (RouteSettings, stored in .sortie)
    // count without --at or --authorisation: a Saturday-evening start meets the weekend zone, and
    // the recorded authorisation makes the airfield a warning; --at overrides the file's start.
    void theRoutesOwnStartAndAuthorisationsCount()
    {
        Mission m = lineMission();
        m.routes[0].settings.plannedStart = QDateTime(QDate(2026, 6, 6), QTime(18, 30), QTimeZone::utc());
        m.routes[0].settings.authorisations = {{QStringLiteral("LVA200"), QStringLiteral("LGS-2026-117")}};
        QVERIFY(formats::saveMission(m, path("saturday.sortie")).ok());
        const Run r = run({QStringLiteral("airspace"), path("saturday.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json a = Json::parse(r.out.toStdString()).at("routes").at(0).at("airspace");
        QCOMPARE(a.at("window").at("from").get<std::string>(), std::string("2026-06-06T18:30:00Z"));
        QCOMPARE(a.at("violations").size(), size_t(1));
        QCOMPARE(a.at("violations").at(0).at("identifier").get<std::string>(), std::string("LVP100"));
        QCOMPARE(a.at("warnings").at(0).at("identifier").get<std::string>(), std::string("LVA200"));
        QCOMPARE(a.at("warnings").at(0).at("authorisation").get<std::string>(), std::string("LGS-2026-117"));

        const Run monday = run({QStringLiteral("airspace"), path("saturday.sortie"), QStringLiteral("--zones"), path("lv-zones.json"),
                                QStringLiteral("--at"), QStringLiteral("2026-06-08T18:30:00Z")});
        QCOMPARE(monday.code, 0);
        QVERIFY2(monday.out.contains("under authorisation LGS-2026-117"), monday.out.constData());
    }

    // The ED-318 samples load as zones (France: far from the route, so nothing is found).
    void ed318SamplesLoad()
    {
        const Run r = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"),
                           (QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/geozones/ed318-two-layers.json")), QStringLiteral("--zones"),
                           (QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/geozones/ed318-circle.json")), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const Json doc = Json::parse(r.out.toStdString());
        QCOMPARE(doc.at("zoneProblems").size(), size_t(0));
        QCOMPARE(doc.at("routes").at(0).at("airspace").at("zones").get<int>() + doc.at("routes").at(0).at("airspace").at("zonesOutsideWindow").get<int>(), 3);
    }

    void badInputFails()
    {
        QCOMPARE(run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--at"),
                      QStringLiteral("Saturday")}).code, 1);
        QCOMPARE(run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("lv-zones.json"), QStringLiteral("--authorisation"),
                      QStringLiteral("LVA200")}).code, 1);
        QCOMPARE(run({QStringLiteral("airspace"), path("line.sortie")}).code, 1);  // no --zones
        const Run missing = run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("none.kml")});
        QCOMPARE(missing.code, 1);
        QVERIFY(missing.err.contains("none.kml"));
        QCOMPARE(run({QStringLiteral("airspace"), path("line.sortie"), QStringLiteral("--zones"), path("ctr.geojson"), QStringLiteral("--buffer"),
                      QStringLiteral("-3")}).code, 1);
    }

private:
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    void write(const char *name, const QByteArray &data)
    {
        QFile f(path(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TstPlanAirspace)
#include "tst_planairspace.moc"
