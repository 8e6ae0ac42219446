// The checklist file and the verdict rules (core/preflight), on their own.
#include "Checklist.h"
#include "PreflightVerdict.h"

#include <QTest>

using namespace sortie::preflight;

class TstChecklist : public QObject
{
    Q_OBJECT

private slots:
    void aFileIsReadInItsOrder()
    {
        const auto read = readChecklist(R"({
  "name": "Survey quad",
  "items": [
    {"check": "satellites", "minimum": 12},
    {"title": "Lens cap off"},
    {"check": "route_on_board", "gates": ["auto"]},
    {"check": "camera", "required": false}
  ]
})");
        QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : read.error().toString()));
        const Checklist &list = read.value();
        QCOMPARE(list.name, QStringLiteral("Survey quad"));
        QCOMPARE(list.items.size(), size_t(4));
        QCOMPARE(list.items[0].check, Check::Satellites);
        QCOMPARE(list.items[0].minimum.value_or(-1), 12.0);
        QCOMPARE(list.items[0].gates, unsigned(GateArm | GateAuto));
        QCOMPARE(list.items[1].check, Check::Manual);
        QCOMPARE(list.items[1].title, QStringLiteral("Lens cap off"));
        QVERIFY(list.items[1].required);
        QCOMPARE(list.items[2].gates, unsigned(GateAuto));
        QVERIFY(!list.items[3].required);
    }

    // A mistake names where it is: the line and column of a syntax error, the JSON path of an item
    // that cannot be used. The file is refused whole.
    void aMistakeNamesWhereItIs_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("words");
        QTest::newRow("syntax") << QByteArray("{\n  \"items\": [\n    {\"check\": \"link\"}\n    {\"check\": \"home\"}\n  ]\n}") << 4 << QString()
                                << QStringLiteral("not valid JSON");
        QTest::newRow("unknown check") << QByteArray(R"({"items": [{"check": "link"}, {"check": "wind"}]})") << 0
                                       << QStringLiteral("/items/1/check") << QStringLiteral("unknown value \"wind\"");
        QTest::newRow("no minimum") << QByteArray(R"({"items": [{"check": "battery"}]})") << 0 << QStringLiteral("/items/0")
                                    << QStringLiteral("needs a \"minimum\"");
        QTest::newRow("minimum out of range") << QByteArray(R"({"items": [{"check": "battery", "minimum": 800}]})") << 0
                                              << QStringLiteral("/items/0/minimum") << QStringLiteral("outside 1..100");
        QTest::newRow("minimum on a yes/no") << QByteArray(R"({"items": [{"check": "home", "minimum": 1}]})") << 0
                                             << QStringLiteral("/items/0/minimum") << QStringLiteral("takes no minimum");
        QTest::newRow("untitled tick") << QByteArray(R"({"items": [{"required": true}]})") << 0 << QStringLiteral("/items/0")
                                       << QStringLiteral("needs a \"title\"");
        QTest::newRow("unknown gate") << QByteArray(R"({"items": [{"check": "home", "gates": ["takeoff"]}]})") << 0
                                      << QStringLiteral("/items/0/gates/0") << QStringLiteral("unknown value \"takeoff\"");
        QTest::newRow("no gates") << QByteArray(R"({"items": [{"check": "home", "gates": []}]})") << 0 << QStringLiteral("/items/0/gates")
                                  << QStringLiteral("holds nothing back");
        QTest::newRow("misspelt key") << QByteArray(R"({"items": [{"check": "home", "requird": false}]})") << 0
                                      << QStringLiteral("/items/0/requird") << QStringLiteral("unknown key");
        QTest::newRow("empty") << QByteArray(R"({"items": []})") << 0 << QStringLiteral("/items") << QStringLiteral("at least one item");
        QTest::newRow("not an object") << QByteArray(R"([1, 2])") << 0 << QStringLiteral("/") << QStringLiteral("expected an object");
    }
    void aMistakeNamesWhereItIs()
    {
        QFETCH(QByteArray, json);
        QFETCH(int, line);
        QFETCH(QString, path);
        QFETCH(QString, words);
        const auto read = readChecklist(json);
        QVERIFY(!read.ok());
        const auto &error = read.error();
        QCOMPARE(error.line, line);
        QCOMPARE(error.jsonPath, path);
        QVERIFY2(error.message.contains(words), qPrintable(error.toString()));
    }

    // Sortie's own list holds back Arm on what a healthy vehicle on the ground has, and Auto also on
    // the route; its reminders and the camera hold back nothing.
    void theDefaultHoldsBackOnlyOnWhatItChecks()
    {
        const Checklist list = defaultChecklist();
        PreflightFacts healthy;
        healthy.linkUp = true;
        healthy.gpsFix = 3;
        healthy.satellites = 14;
        healthy.batteryPercent = 100;
        healthy.homeSet = true;
        int armBlockers = 0, autoBlockers = 0;
        for (const ChecklistItem &item : list.items) {
            const ItemVerdict v = judge(item, healthy, false);
            armBlockers += holdsBack(item, v, GateArm) ? 1 : 0;
            autoBlockers += holdsBack(item, v, GateAuto) ? 1 : 0;
        }
        QCOMPARE(armBlockers, 0);
        QCOMPARE(autoBlockers, 1); // the route on board: Sortie gave it none
        healthy.routeOnBoard = true;
        autoBlockers = 0;
        for (const ChecklistItem &item : list.items)
            autoBlockers += holdsBack(item, judge(item, healthy, false), GateAuto) ? 1 : 0;
        QCOMPARE(autoBlockers, 0);
    }

    // A value not known is missing, not 0; without the link the telemetry is old, so missing too.
    void aMissingValueIsMissingNotZero()
    {
        const ChecklistItem satellites{Check::Satellites, {}, 8.0, true, GateArm};
        PreflightFacts facts;
        facts.linkUp = true;
        QCOMPARE(judge(satellites, facts, false).outcome, Outcome::Missing);
        facts.satellites = 6;
        const ItemVerdict few = judge(satellites, facts, false);
        QCOMPARE(few.outcome, Outcome::Fail);
        QCOMPARE(few.value.value_or(-1), 6.0);
        facts.satellites = 8;
        QCOMPARE(judge(satellites, facts, false).outcome, Outcome::Pass);
        facts.linkUp = false;
        QCOMPARE(judge(satellites, facts, false).outcome, Outcome::Missing);
        QVERIFY(holdsBack(satellites, judge(satellites, facts, false), GateArm));
        QVERIFY(!holdsBack(satellites, judge(satellites, facts, false), GateAuto)); // not its gate
    }

    void aTickPassesOnlyAnItemToTick()
    {
        const ChecklistItem props{Check::Manual, QStringLiteral("Propellers"), std::nullopt, true, GateArm | GateAuto};
        const PreflightFacts nothing;
        QCOMPARE(judge(props, nothing, false).outcome, Outcome::Unticked);
        QVERIFY(holdsBack(props, judge(props, nothing, false), GateArm));
        QCOMPARE(judge(props, nothing, true).outcome, Outcome::Ticked);
        QVERIFY(!holdsBack(props, judge(props, nothing, true), GateArm));
        const ChecklistItem home{Check::Home, {}, std::nullopt, true, GateArm};
        PreflightFacts noHome;
        noHome.linkUp = true;
        noHome.homeSet = false;
        QCOMPARE(judge(home, noHome, true).outcome, Outcome::Fail); // a tick does not pass a checked item
    }

    // A link that never reports a home (HCI) cannot be checked for one: shown, holding nothing back.
    void whatTheLinkNeverReportsHoldsNothingBack()
    {
        const ChecklistItem home{Check::Home, {}, std::nullopt, true, GateArm | GateAuto};
        PreflightFacts facts;
        facts.linkUp = true;
        QCOMPARE(judge(home, facts, false).outcome, Outcome::Missing); // reportable, not reported yet
        QVERIFY(holdsBack(home, judge(home, facts, false), GateArm));
        facts.homeReportable = false;
        QCOMPARE(judge(home, facts, false).outcome, Outcome::NotReported);
        QVERIFY(!holdsBack(home, judge(home, facts, false), GateArm));
    }

    void theRouteCheckCountsErrors()
    {
        const ChecklistItem check{Check::RouteCheck, {}, std::nullopt, true, GateAuto};
        PreflightFacts facts;
        QCOMPARE(judge(check, facts, false).outcome, Outcome::Missing);
        facts.routeErrors = 2;
        QCOMPARE(judge(check, facts, false).outcome, Outcome::Fail);
        QCOMPARE(judge(check, facts, false).value.value_or(-1), 2.0);
        facts.routeErrors = 0;
        QCOMPARE(judge(check, facts, false).outcome, Outcome::Pass);
    }
};

QTEST_GUILESS_MAIN(TstChecklist)
#include "tst_checklist.moc"
