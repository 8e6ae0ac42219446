// sortie-plan stats --vehicle, run as a process over a route file and profile the test writes.
#include "Geodesy.h"
#include "JsonCursor.h"
#include "MissionFiles.h"

#include <QProcess>
#include <QTemporaryDir>
#include "LineQuad.h"
#include "PlanRun.h"

#include <QtTest>

using namespace sortie::mission;
using Json = sortie::mission::formats::Json;

namespace {
using Run = sortie::test::PlanRun;
Run run(const QStringList &args) { return sortie::test::runPlan(args); }

const GeoPoint kOrigin = sortie::test::kLineOrigin;
using sortie::test::lineMission;
const QByteArray kProfile = sortie::test::kLineQuadProfile;
} // namespace

class TstPlanEndurance : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(formats::saveMission(lineMission(4), path("two.sortie")).ok());
        QVERIFY(formats::saveMission(lineMission(1), path("one.sortie")).ok());
        QFile f(path("quad.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kProfile);
        f.close();
        QFile bad(path("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\n  \"batteryWh\": 22.5,\n  \"reserve\": oops\n}\n");
    }

    // Four 8 Wh legs (32 Wh) need two batteries: exit 2, the keys the issue names, legs numbered
    // from 1 as `profile` numbers them.
    void aRouteNeedingTwoBatteriesExitsTwo()
    {
        const Run r = run({QStringLiteral("stats"), path("two.sortie"), QStringLiteral("--vehicle"), path("quad.json"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json doc = Json::parse(r.out.toStdString());
        const Json &e = doc.at("routes").at(0).at("endurance");
        for (const char *key : {"flightTime", "energyWh", "batteryAtEnd", "batteriesNeeded", "pointOfNoReturn", "legs"})
            QVERIFY2(e.contains(key), key);
        QCOMPARE(e.at("flightTime").get<double>(), 400.0);
        QCOMPARE(e.at("energyWh").get<double>(), 32.0);
        QCOMPARE(e.at("batteriesNeeded").get<int>(), 2);
        QVERIFY(std::abs(e.at("batteryAtEnd").get<double>() - (1 - 32 / 22.5)) < 1e-3);
        QCOMPARE(e.at("legs").size(), size_t(4));
        for (int i = 0; i < 4; ++i) {
            QCOMPARE(e.at("legs").at(i).at("leg").get<int>(), i + 1);
            QCOMPARE(e.at("legs").at(i).at("time").get<double>(), 100.0);
            QCOMPARE(e.at("legs").at(i).at("energyWh").get<double>(), 8.0);
        }
        // Out s metres: 18 - 0.016·s - 1.5 (the 30 m descent at home) >= 0 while s <= 1031.25.
        QCOMPARE(e.at("pointOfNoReturn").at("leg").get<int>(), 2);
        QVERIFY(std::abs(e.at("pointOfNoReturn").at("distance").get<double>() - 1031.25) < 0.05);
        QCOMPARE(e.at("batteryChanges").size(), size_t(1));
        QCOMPARE(e.at("batteryChanges").at(0).at("waypoint").get<int>(), 3);
        const Json &issues = doc.at("routes").at(0).at("validation");
        QVERIFY2(issues.dump().find("endurance-battery") != std::string::npos, issues.dump().c_str());

        const Run text = run({QStringLiteral("stats"), path("two.sortie"), QStringLiteral("--vehicle"), path("quad.json")});
        QCOMPARE(text.code, 2);
        QVERIFY2(text.out.contains("2 batteries") && text.out.contains("change the battery at Waypoint 3"), text.out.constData());
        QVERIFY(text.out.contains("point of no return: leg 2"));
    }

    // One leg fits: exit 0, no point of no return (home stays in reach).
    void aRouteThatFitsExitsZero()
    {
        const Run r = run({QStringLiteral("stats"), path("one.sortie"), QStringLiteral("--vehicle"), path("quad.json"), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const Json e = Json::parse(r.out.toStdString()).at("routes").at(0).at("endurance");
        QVERIFY(e.at("pointOfNoReturn").is_null());
        QCOMPARE(e.at("batteriesNeeded").get<int>(), 1);
        // A 4 m/s head wind from the east: 6 m/s over the ground, 1000 m take 166.667 s at 288 W.
        const Run windy = run({QStringLiteral("stats"), path("one.sortie"), QStringLiteral("--vehicle"), path("quad.json"),
                               QStringLiteral("--wind"), QStringLiteral("4,90"), QStringLiteral("--json")});
        const Json w = Json::parse(windy.out.toStdString()).at("routes").at(0).at("endurance");
        QVERIFY(std::abs(w.at("flightTime").get<double>() - 1000.0 / 6) < 1e-2);
        QVERIFY(std::abs(w.at("energyWh").get<double>() - 288.0 * 1000 / 6 / 3600) < 1e-2);
        // A wind the vehicle cannot fly against: exit 2, an error naming the leg.
        const Run stuck = run({QStringLiteral("stats"), path("one.sortie"), QStringLiteral("--vehicle"), path("quad.json"),
                               QStringLiteral("--wind"), QStringLiteral("12,90")});
        QCOMPARE(stuck.code, 2);
        QVERIFY2(stuck.out.contains("leg 1 cannot be flown"), stuck.out.constData());
    }

    void aBadProfileNamesItsFileAndLine()
    {
        const Run r = run({QStringLiteral("stats"), path("one.sortie"), QStringLiteral("--vehicle"), path("bad.json")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(path("bad.json").toUtf8() + ":3"), r.err.constData());
        const Run missing = run({QStringLiteral("stats"), path("one.sortie"), QStringLiteral("--wind"), QStringLiteral("3,0")});
        QCOMPARE(missing.code, 1);
    }

private:
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TstPlanEndurance)
#include "tst_planendurance.moc"
