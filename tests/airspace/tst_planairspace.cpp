// sortie-plan airspace (and stats --zones), run as a process over route and zone files the test
// writes: the JSON keys the issue names, legs numbered as `profile` numbers them, the exit codes.
#include "Geodesy.h"
#include "HgtWriter.h"
#include "JsonCursor.h"
#include "MissionFiles.h"

#include <QProcess>
#include <QTemporaryDir>
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

    void badInputFails()
    {
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
