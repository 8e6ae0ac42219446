// sortie-plan profile and stats --dem, run as a process over tiles and WPL files the test writes:
// the JSON keys the issue fixes, WPL altitude frames 0/3/10, no data as null, exit codes, bad tiles.
#include "HgtWriter.h"

#include <nlohmann/json.hpp>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {
struct Run { int code; QByteArray out; QByteArray err; };

Run run(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(SORTIE_PLAN_BIN), args);
    if (!p.waitForFinished(60000))
        qFatal("sortie-plan did not finish");
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

// 100 m everywhere, a void block around 56.50 N, 24.52–24.53 E.
int post(int r, int c)
{
    return (c >= 624 && c <= 636 && r >= 588 && r <= 612) ? -32768 : 100;
}

QByteArray wpl(const QList<QByteArray> &items)
{
    QByteArray out = "QGC WPL 110\n";
    for (const QByteArray &i : items)
        out += QByteArray(i).replace(' ', '\t') + "\n";
    return out;
}
} // namespace

class TstPlanProfile : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    QString path(const char *name) { return dir.filePath(QLatin1String(name)); }

private slots:
    void initTestCase()
    {
        QVERIFY(QDir(dir.path()).mkdir("dem"));
        QVERIFY(sortie::terrain::test::writeHgt(path("dem/N56E024.hgt"), 1201, post));
    }

    void framesAndJsonKeys()
    {
        // Home at 56.5 N 24.5 E; take-off there 30 m above home (frame 3); 150 m AMSL (frame 0);
        // 40 m above the ground under it (frame 10), past the hole.
        QVERIFY(sortie::terrain::test::writeFile(path("frames.waypoints"), wpl({
            "0 1 0 16 0 0 0 0 56.5 24.5 123 1",
            "1 0 3 22 0 0 0 0 0 0 30 1",
            "2 0 0 16 0 0 0 0 56.5 24.51 150 1",
            "3 0 10 16 0 0 0 0 56.5 24.54 40 1",
        })));
        const Run r = run({QStringLiteral("profile"), path("frames.waypoints"), QStringLiteral("--dem"), path("dem"), QStringLiteral("--json")});
        QVERIFY2(r.code == 0, r.err.constData());
        const auto doc = nlohmann::json::parse(r.out.toStdString());
        const auto &route = doc["routes"][0];
        QVERIFY(route.contains("name"));
        const auto &t = route["terrain"];
        for (const char *key : {"minClearance", "minClearanceAt", "noData", "samples"})
            QVERIFY2(t.contains(key), key);
        QCOMPARE(t["minClearance"].get<double>(), 30.0);  // at the take-off: 130 m over 100 m ground
        QCOMPARE(t["minClearanceAt"]["leg"].get<int>(), 1);
        QCOMPARE(t["minClearanceAt"]["distance"].get<double>(), 0.0);
        QCOMPARE(t["noData"].size(), size_t(1));
        QCOMPARE(t["noData"][0]["leg"].get<int>(), 2);
        const double from = t["noData"][0]["fromDistance"].get<double>(), to = t["noData"][0]["toDistance"].get<double>();
        QVERIFY(from > 0 && to > from);
        const auto &wps = t["waypoints"];
        QCOMPARE(wps.size(), size_t(3));
        QCOMPARE(wps[0]["altitudeAmsl"].get<double>(), 130.0);
        QCOMPARE(wps[1]["altitudeAmsl"].get<double>(), 150.0);
        QCOMPARE(wps[2]["altitudeAmsl"].get<double>(), 140.0);
        int nulls = 0;
        double previous = -1;
        for (const auto &s : t["samples"]) {
            for (const char *key : {"distance", "latitude", "longitude", "ground", "altitudeAmsl", "clearance"})
                QVERIFY2(s.contains(key), key);
            const double d = s["distance"].get<double>();
            QVERIFY(d > previous);
            previous = d;
            const double lon = s["longitude"].get<double>();
            if (s["ground"].is_null()) {
                ++nulls;
                QVERIFY(s["clearance"].is_null());
                QVERIFY(d >= from && d <= to);
                QVERIFY(lon > 24.519 && lon < 24.531);
            } else {
                QCOMPARE(s["ground"].get<double>(), 100.0);
                QCOMPARE(s["clearance"].get<double>(), s["altitudeAmsl"].get<double>() - 100.0);
            }
        }
        QVERIFY(nulls >= 15);  // about 700 m of hole at 30 m
        QVERIFY(route["validation"].dump().find("terrain-no-data") != std::string::npos);

        // The readable table says the same.
        const Run text = run({QStringLiteral("profile"), path("frames.waypoints"), QStringLiteral("--dem"), path("dem/N56E024.hgt"),
                              QStringLiteral("--step"), QStringLiteral("100")});
        QCOMPARE(text.code, 0);
        QVERIFY(text.out.contains("lowest clearance 30.0 m on leg 1"));
        QVERIFY(text.out.contains("warning [terrain-no-data] Leg 2 (Waypoint 2 → Waypoint 3)"));
    }

    void tooLowExitsTwo()
    {
        QVERIFY(sortie::terrain::test::writeFile(path("low.waypoints"), wpl({
            "0 1 0 16 0 0 0 0 56.4 24.3 0 1",
            "1 0 0 16 0 0 0 0 56.4 24.3 150 1",
            "2 0 0 16 0 0 0 0 56.4 24.32 105 1",
        })));
        const Run r = run({QStringLiteral("profile"), path("low.waypoints"), QStringLiteral("--dem"), path("dem"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const auto t = nlohmann::json::parse(r.out.toStdString())["routes"][0]["terrain"];
        QCOMPARE(t["minClearance"].get<double>(), 5.0);
        QCOMPARE(t["minClearanceAt"]["leg"].get<int>(), 1);
        const Run stats = run({QStringLiteral("stats"), path("low.waypoints"), QStringLiteral("--dem"), path("dem")});
        QCOMPARE(stats.code, 2);
        QVERIFY2(stats.out.contains("error [terrain-clearance] Leg 1 (Waypoint 1 → Waypoint 2) flies"), stats.out.constData());
        // Without --dem, stats knows nothing of the ground.
        QVERIFY(!run({QStringLiteral("stats"), path("low.waypoints")}).out.contains("terrain-"));
    }

    void badInput()
    {
        QVERIFY(QDir(dir.path()).mkdir("bad"));
        QVERIFY(sortie::terrain::test::writeFile(path("bad/N56E024.hgt"), QByteArray(1000, '\0')));
        QVERIFY(sortie::terrain::test::writeFile(path("one.waypoints"), wpl({"0 1 0 16 0 0 0 0 56.4 24.3 0 1",
                                                                               "1 0 0 16 0 0 0 0 56.4 24.3 150 1",
                                                                               "2 0 0 16 0 0 0 0 56.4 24.32 150 1"})));
        const Run single = run({QStringLiteral("profile"), path("one.waypoints"), QStringLiteral("--dem"), path("bad/N56E024.hgt")});
        QCOMPARE(single.code, 1);
        QVERIFY2(single.err.contains("N56E024.hgt: 1000 bytes is not an SRTM tile"), single.err.constData());
        const Run folder = run({QStringLiteral("profile"), path("one.waypoints"), QStringLiteral("--dem"), path("bad"), QStringLiteral("--json")});
        QCOMPARE(folder.code, 1);
        QVERIFY(folder.err.contains("N56E024.hgt: 1000 bytes"));
        const auto t = nlohmann::json::parse(folder.out.toStdString())["routes"][0]["terrain"];
        QVERIFY(t["minClearance"].is_null());  // never half-used, never 0
        QCOMPARE(run({QStringLiteral("profile"), path("one.waypoints")}).code, 1);  // --dem is required
        QCOMPARE(run({QStringLiteral("profile"), path("one.waypoints"), QStringLiteral("--dem"), path("dem"), QStringLiteral("--step"),
                      QStringLiteral("-3")}).code, 1);
    }
};

QTEST_GUILESS_MAIN(TstPlanProfile)
#include "tst_planprofile.moc"
