// sortie-plan conflicts, run as a process over route files the test writes: the crossing of
// tst_deconfliction (10 m/s, 50 m up, over the origin at 100 s) through the command line.
#include "DeconflictionSamples.h"
#include "JsonCursor.h"
#include "MissionFiles.h"
#include "Near.h"

#include <QProcess>
#include <QTemporaryDir>
#include "PlanRun.h"

#include <QtTest>

using namespace sortie::mission;
using namespace sortie::test;
using Json = sortie::mission::formats::Json;

namespace {
using Run = sortie::test::PlanRun;
Run run(const QStringList &args) { return sortie::test::runPlan(args); }

Mission missionOf(std::vector<Route> routes)
{
    Mission m;
    m.name = QStringLiteral("conflicts");
    m.routes = std::move(routes);
    return m;
}
} // namespace

class TstPlanConflicts : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Eastbound with a waypoint at (−500, 0): leg 1 is 500 m, leg 2 the 1500 m over the origin.
        QVERIFY(formats::saveMission(missionOf({lineRoute({{-1000, 0}, {-500, 0}, {1000, 0}})}), path("east.sortie")).ok());
        QVERIFY(formats::saveMission(missionOf({lineRoute({{0, -1000}, {0, 1000}})}), path("north.sortie")).ok());
        // Eastbound again, 50 m higher than both.
        QVERIFY(formats::saveMission(missionOf({lineRoute({{-1000, 0, 100}, {1000, 0, 100}})}), path("high.sortie")).ok());
        QVERIFY(formats::saveMission(missionOf({lineRoute({{0, 0}, {10, 0}}), lineRoute({{0, 0}, {0, 10}})}), path("two.sortie")).ok());
    }

    // Both from 0: over the origin at 100 s, under 20 m for t in (98.586, 101.414), on leg 2 of the
    // first route and leg 1 of the second. Exit 2 and exactly the keys the issue names.
    void aCrossingAtTheSameTimeExitsTwo()
    {
        const Run r = run({QStringLiteral("conflicts"), path("east.sortie"), path("north.sortie"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json doc = Json::parse(r.out.toStdString());
        QCOMPARE(doc.at("pairs").get<int>(), 1);
        QCOMPARE(doc.at("conflicts").size(), size_t(1));
        const Json &c = doc.at("conflicts").at(0);
        QCOMPARE(c.at("routes"), Json::parse("[1, 2]"));
        QCOMPARE(c.at("legs"), Json::parse("[2, 1]"));
        QNEAR(c.at("time").get<double>(), 100, 1e-3);
        QNEAR(c.at("horizontal").get<double>(), 0, 1e-2);
        QNEAR(c.at("vertical").get<double>(), 0, 1e-3);
        QNEAR(c.at("from").get<double>(), 100 - std::sqrt(2.0), 2e-3);
        QNEAR(c.at("to").get<double>(), 100 + std::sqrt(2.0), 2e-3);
        const GeoPoint origin{c.at("positions").at(0).at("latitude").get<double>(), c.at("positions").at(0).at("longitude").get<double>()};
        QNEAR(samplePlane().project(origin).x, 0, 1e-2);
        QNEAR(c.at("positions").at(1).at("altitude").get<double>(), 50, 1e-3);
    }

    // The second route a minute later: least 424.26 m apart at 130 s, no conflict, exit 0; with a
    // 500 m horizontal separation a conflict at 130 s (tst_deconfliction works the numbers).
    void aMinuteApart()
    {
        const Run r = run({QStringLiteral("conflicts"), path("east.sortie"), path("north.sortie"), QStringLiteral("--start"),
                           QStringLiteral("0,60"), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const Json doc = Json::parse(r.out.toStdString());
        QCOMPARE(doc.at("pairs").get<int>(), 1);
        QVERIFY(doc.at("conflicts").empty());

        const Run wide = run({QStringLiteral("conflicts"), path("east.sortie"), path("north.sortie"), QStringLiteral("--start"),
                              QStringLiteral("0,60"), QStringLiteral("--separation"), QStringLiteral("500,15"), QStringLiteral("--json")});
        QCOMPARE(wide.code, 2);
        const Json wideDoc = Json::parse(wide.out.toStdString());
        const Json &c = wideDoc.at("conflicts").at(0);
        QNEAR(c.at("time").get<double>(), 130, 1e-3);
        QNEAR(c.at("horizontal").get<double>(), 300 * std::sqrt(2.0), 1e-2);
    }

    // At 20 m/s both reach the origin at 50 s.
    void anotherSpeed()
    {
        const Run r = run({QStringLiteral("conflicts"), path("east.sortie"), path("north.sortie"), QStringLiteral("--speed"),
                           QStringLiteral("20"), QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        QNEAR(Json::parse(r.out.toStdString()).at("conflicts").at(0).at("time").get<double>(), 50, 1e-3);
    }

    // Three routes, three pairs: the high one is 50 m above the others; only routes 1 and 2 conflict.
    // The readable form says the same.
    void threeRoutes()
    {
        const QStringList files{path("east.sortie"), path("north.sortie"), path("high.sortie")};
        const Run r = run(QStringList{QStringLiteral("conflicts")} + files + QStringList{QStringLiteral("--json")});
        QCOMPARE(r.code, 2);
        const Json doc = Json::parse(r.out.toStdString());
        QCOMPARE(doc.at("pairs").get<int>(), 3);
        QCOMPARE(doc.at("conflicts").size(), size_t(1));
        QCOMPARE(doc.at("conflicts").at(0).at("routes"), Json::parse("[1, 2]"));

        const Run text = run(QStringList{QStringLiteral("conflicts")} + files);
        QCOMPARE(text.code, 2);
        QVERIFY2(text.out.contains("3 routes, 3 pairs, separation 20 m across and 15 m in height: 1 conflict(s)"), text.out.constData());
        QVERIFY2(text.out.contains("leg 2) and 2"), text.out.constData());
        QVERIFY2(text.out.contains("closest at 100.0 s: 0.0 m across, 0.0 m in height"), text.out.constData());
    }

    // Bad arguments: exit 1 and a message naming the problem; nothing on stdout.
    void badArguments_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString east = path("east.sortie"), north = path("north.sortie");
        QTest::newRow("one file") << QStringList{east} << QStringLiteral("at least two route files, got 1");
        QTest::newRow("starts") << QStringList{east, north, QStringLiteral("--start"), QStringLiteral("0")}
                                << QStringLiteral("--start gives 1 start(s) for 2 route files");
        QTest::newRow("start text") << QStringList{east, north, QStringLiteral("--start"), QStringLiteral("0,soon")}
                                    << QStringLiteral("--start needs numbers");
        QTest::newRow("speed") << QStringList{east, north, QStringLiteral("--speed"), QStringLiteral("0")} << QStringLiteral("--speed needs a positive");
        QTest::newRow("separation") << QStringList{east, north, QStringLiteral("--separation"), QStringLiteral("20")}
                                    << QStringLiteral("--separation needs two positive numbers");
        QTest::newRow("two routes") << QStringList{east, path("two.sortie")} << QStringLiteral("holds 2 routes; conflicts takes one route per file");
        QTest::newRow("missing") << QStringList{east, path("none.sortie")} << QStringLiteral("none.sortie");
    }
    void badArguments()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = run(QStringList{QStringLiteral("conflicts")} + args);
        QCOMPARE(r.code, 1);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TstPlanConflicts)
#include "tst_planconflicts.moc"
