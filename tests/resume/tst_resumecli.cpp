// sortie-plan resume, run as a process over a route and an energy profile the test writes: the rest
// from the endurance model's battery change and from a last photo, read back from its file; and
// every mistake named.
#include "Geodesy.h"
#include "JsonCursor.h"
#include "MissionFiles.h"
#include "LineQuad.h"
#include "PlanRun.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::mission;
using Json = sortie::mission::formats::Json;

namespace {

const GeoPoint kOrigin = sortie::test::kLineOrigin;

// Four legs of the line quad's route, the camera every 50 m from the first waypoint; its profile
// changes the battery after two.
Mission lineMission()
{
    Mission m = sortie::test::lineMission(4);
    CameraSeriesByDistanceAction every50;
    every50.intervalMeters = 50;
    std::get<Waypoint>(m.routes[0].segments[0]).actions.push_back(every50);
    return m;
}

const QByteArray kProfile = sortie::test::kLineQuadProfile;

sortie::test::PlanRun run(const QStringList &args) { return sortie::test::runPlan(args); }

} // namespace

class TestResumeCli : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
    QString takeoff() const { return QStringLiteral("%1,%2").arg(kOrigin.latitude, 0, 'f', 7).arg(kOrigin.longitude, 0, 'f', 7); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(formats::saveMission(lineMission(), path("line.sortie")).ok());
        QFile f(path("quad.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kProfile);
    }

    // The battery runs short after two legs: the rest starts at waypoint 3, the series on again there.
    void fromTheBatteryChange()
    {
        const auto r = run({QStringLiteral("resume"), path("line.sortie"), path("rest.sortie"), QStringLiteral("--takeoff"), takeoff(),
                            QStringLiteral("--battery-change"), QStringLiteral("1"), QStringLiteral("--vehicle"), path("quad.json"), QStringLiteral("--json")});
        QVERIFY2(r.code == 0, r.err.constData());
        const Json summary = Json::parse(r.out.toStdString());
        QCOMPARE(summary.at("resumedRow").get<int>(), 3);
        const GeoPoint third = std::get<Waypoint>(lineMission().routes[0].segments[2]).position;
        const GeoPoint at{summary.at("resumeAt").at("latitude").get<double>(), summary.at("resumeAt").at("longitude").get<double>()};
        QVERIFY(geodesicDistance(at, third) < 0.01);
        QVERIFY(std::abs(summary.at("flown").get<double>() - 2000) < 0.1);
        QVERIFY(std::abs(summary.at("remaining").get<double>() - 2000) < 0.1);

        const auto rest = formats::loadMission(path("rest.sortie"));
        QVERIFY2(rest, qPrintable(rest ? QString() : rest.error().toString()));
        const Route &route = rest->mission.routes.at(0);
        QCOMPARE(route.settings.name, QStringLiteral("line (resumed)"));
        QCOMPARE(route.segments.size(), size_t(4)); // take-off, waypoint 3 (resumed), 4, 5
        QCOMPARE(std::get<Waypoint>(route.segments[0]).role, WaypointRole::Takeoff);
        const Waypoint &resumed = std::get<Waypoint>(route.segments[1]);
        QVERIFY(geodesicDistance(resumed.position, third) < 0.01);
        QCOMPARE(resumed.actions.size(), size_t(1));
        QCOMPARE(std::get<CameraSeriesByDistanceAction>(resumed.actions.front()).intervalMeters, 50.0);
        QCOMPARE(route.segments[3], lineMission().routes[0].segments[4]);
        // It reads back with no validation error.
        QCOMPARE(run({QStringLiteral("stats"), path("rest.sortie")}).code, 0);
    }

    // The last photo at 1,512 m: the next was due at 1,562 m.
    void fromTheLastPhoto()
    {
        const GeoPoint photo = geodesicDirect(kOrigin, 90, 1512).point;
        const auto r = run({QStringLiteral("resume"), path("line.sortie"), path("rest-photo.sortie"), QStringLiteral("--takeoff"), takeoff(),
                            QStringLiteral("--photo"), QStringLiteral("%1,%2").arg(photo.latitude, 0, 'f', 9).arg(photo.longitude, 0, 'f', 9),
                            QStringLiteral("--transit"), QStringLiteral("45"), QStringLiteral("--json")});
        QVERIFY2(r.code == 0, r.err.constData());
        const Json summary = Json::parse(r.out.toStdString());
        QVERIFY2(std::abs(summary.at("flown").get<double>() - 1562) < 0.05, r.out.constData());
        const auto rest = formats::loadMission(path("rest-photo.sortie"));
        QVERIFY(rest);
        const Route &route = rest->mission.routes.at(0);
        QCOMPARE(std::get<Waypoint>(route.segments[0]).altitude, 45.0);
        QCOMPARE(std::get<Waypoint>(route.segments[1]).altitude, 45.0); // over the resume point, then down to 30 m
        QCOMPARE(std::get<Waypoint>(route.segments[2]).altitude, 30.0);
    }

    void namesEveryMistake()
    {
        const QString line = path("line.sortie"), out = path("never.sortie");
        const auto noTakeoff = run({QStringLiteral("resume"), line, out, QStringLiteral("--photo"), takeoff()});
        QCOMPARE(noTakeoff.code, 1);
        QVERIFY(noTakeoff.err.contains("--takeoff"));
        const auto neither = run({QStringLiteral("resume"), line, out, QStringLiteral("--takeoff"), takeoff()});
        QCOMPARE(neither.code, 1);
        QVERIFY(neither.err.contains("one of --photo"));
        const auto noProfile = run({QStringLiteral("resume"), line, out, QStringLiteral("--takeoff"), takeoff(), QStringLiteral("--battery-change"), QStringLiteral("1")});
        QCOMPARE(noProfile.code, 1);
        QVERIFY(noProfile.err.contains("--vehicle"));
        const auto tooMany = run({QStringLiteral("resume"), line, out, QStringLiteral("--takeoff"), takeoff(), QStringLiteral("--battery-change"),
                                  QStringLiteral("2"), QStringLiteral("--vehicle"), path("quad.json")});
        QCOMPARE(tooMany.code, 1);
        QVERIFY2(tooMany.err.contains("has 1 battery change(s)"), tooMany.err.constData());
        const auto farAway = run({QStringLiteral("resume"), line, out, QStringLiteral("--takeoff"), takeoff(), QStringLiteral("--photo"), QStringLiteral("57.5,25")});
        QCOMPARE(farAway.code, 1);
        QVERIFY2(farAway.err.contains("not this route's flight"), farAway.err.constData());
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(TestResumeCli)
#include "tst_resumecli.moc"
