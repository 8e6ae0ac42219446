// The sortie-plan tool, run as a process the way scripts run it: conversions, statistics with
// --json, area scans, exit codes, and errors that name the file and line.
#include "MissionFiles.h"
#include "MissionSamples.h"
#include "SortieFormat.h"

#include <nlohmann/json.hpp>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace sortie::mission::test;

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
}

class TestSortiePlan : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    QString path(const char *name) { return dir.filePath(QLatin1String(name)); }

private slots:
    void convertRoundTrip()
    {
        const Run a = run({QStringLiteral("convert"), samplePath(QStringLiteral("SectionTest.plan")), path("a.sortie")});
        QCOMPARE(a.code, 0);
        QVERIFY2(!a.err.contains("205"), a.err.constData());  // its gimbal control is kept, not refused
        QCOMPARE(run({QStringLiteral("convert"), path("a.sortie"), path("b.plan")}).code, 0);
        QCOMPARE(run({QStringLiteral("convert"), path("b.plan"), path("c.waypoints")}).code, 0);
        QCOMPARE(run({QStringLiteral("convert"), path("c.waypoints"), path("d.kml")}).code, 0);
        const Result<LoadedMission> first = loadMission(path("a.sortie"));
        const Result<LoadedMission> viaPlan = loadMission(path("b.plan"));
        QVERIFY(first.ok() && viaPlan.ok());
        QVERIFY(first->mission.routes[0].segments == viaPlan->mission.routes[0].segments);
        QVERIFY(std::holds_alternative<CameraControlAction>(std::get<Waypoint>(first->mission.routes[0].segments[2]).actions.at(0)));
        QVERIFY(QFile::exists(path("d.kml")));
    }

    void statsAsJson()
    {
        const Run r = run({QStringLiteral("stats"), samplePath(QStringLiteral("100Waypoints.waypoints.txt")), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const auto doc = nlohmann::json::parse(r.out.toStdString());
        QCOMPARE(doc["routes"][0]["statistics"]["waypoints"].get<int>(), 98);
        QVERIFY(doc["routes"][0]["statistics"]["lengthMeters"].get<double>() > 1000);
        QCOMPARE(doc["routes"][0]["validation"]["errors"].get<int>(), 0);
    }

    void validationErrorsGateTheExitCode()
    {
        Mission m;
        m.routes.push_back(mavlinkRoute());
        std::get<Waypoint>(m.routes[0].segments[2]).speed = -1;
        QFile f(path("bad.sortie"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(writeSortie(m));
        f.close();
        const Run stats = run({QStringLiteral("stats"), path("bad.sortie")});
        QCOMPARE(stats.code, 2);
        QVERIFY(stats.out.contains("[speed-not-positive] Waypoint 3"));
        // A conversion writes the file and names the issues; --strict refuses and writes nothing.
        const Run refused = run({QStringLiteral("convert"), path("bad.sortie"), path("bad.plan"), QStringLiteral("--strict")});
        QCOMPARE(refused.code, 2);
        QVERIFY(!QFile::exists(path("bad.plan")));
        const Run written = run({QStringLiteral("convert"), path("bad.sortie"), path("bad.plan")});
        QCOMPARE(written.code, 0);
        QVERIFY2(written.err.contains("error: route 1 [speed-not-positive] Waypoint 3"), written.err.constData());
        QVERIFY2(written.out.contains("with 1 validation error(s)"), written.out.constData());
        QVERIFY(QFile::exists(path("bad.plan")));
    }

    void brokenInputNamesFileAndLine()
    {
        QFile f(path("broken.waypoints"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t47\t8\t400\t1\n1\t0\t3\t16\t0\t0\n");
        f.close();
        const Run r = run({QStringLiteral("stats"), path("broken.waypoints")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains((path("broken.waypoints") + QStringLiteral(":3: expected 12")).toUtf8()), r.err.constData());
        QCOMPARE(run({QStringLiteral("stats")}).code, 1);
        QCOMPARE(run({QStringLiteral("frobnicate")}).code, 1);
        QCOMPARE(run({QStringLiteral("--help")}).code, 0);
    }

    void scanFromPolygon()
    {
        const Run r = run({QStringLiteral("scan"), samplePath(QStringLiteral("PolygonGood.kml")), path("scan.sortie"),
                           QStringLiteral("--gsd"), QStringLiteral("1.5"), QStringLiteral("--side"), QStringLiteral("70"),
                           QStringLiteral("--angle"), QStringLiteral("30"), QStringLiteral("--json")});
        QVERIFY2(r.code == 0, r.err.constData());
        const auto summary = nlohmann::json::parse(r.out.toStdString());
        QVERIFY(summary["transects"].get<int>() > 0);
        QCOMPARE(summary["groundSampleDistanceCm"].get<double>(), 1.5);
        const Result<LoadedMission> m = loadMission(path("scan.sortie"));
        QVERIFY(m.ok());
        const AreaScan &scan = std::get<AreaScan>(m->mission.routes[0].segments[0]);
        QCOMPARE(int(scan.polygon.size()), 4);
        QCOMPARE(scan.parameters.heightMode, ScanHeightMode::GroundSampleDistance);
        QCOMPARE(scan.parameters.sideOverlapPercent, 70.0);
        QCOMPARE(scan.parameters.directionDeg, 30.0);
        const Run bad = run({QStringLiteral("scan"), samplePath(QStringLiteral("PolygonMissingNode.kml")), path("x.sortie")});
        QCOMPARE(bad.code, 1);
        QVERIFY(bad.err.contains("PolygonMissingNode.kml:33:"));
        QCOMPARE(run({QStringLiteral("scan"), samplePath(QStringLiteral("PolygonGood.kml")), path("y.sortie"), QStringLiteral("--camera"), QStringLiteral("x,1")}).code, 1);
    }
};

QTEST_GUILESS_MAIN(TestSortiePlan)
#include "tst_sortieplan.moc"
