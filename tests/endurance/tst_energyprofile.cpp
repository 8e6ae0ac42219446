#include "EnergyProfile.h"

#include <QtTest>

using namespace sortie::endurance;

namespace {
QByteArray quadJson()
{
    return R"({"name": "Quad", "batteryWh": 90, "cruiseSpeed": 10, "climbRate": 3, "descentRate": 2,
               "hoverPowerW": 300, "cruisePowerW": 260, "climbPowerW": 420, "descentPowerW": 210})";
}
} // namespace

class TstEnergyProfile : public QObject
{
    Q_OBJECT
private slots:
    void readsAFileWithTheDefaultReserve()
    {
        const auto p = readEnergyProfile(quadJson());
        QVERIFY2(p.ok(), qPrintable(p.ok() ? QString() : p.error().toString()));
        QCOMPARE(p->name, QStringLiteral("Quad"));
        QCOMPARE(p->source, ProfileSource::File);
        QCOMPARE(p->batteryWh, 90.0);
        QCOMPARE(p->reserve, 0.2);
        QCOMPARE(p->usableWh(), 72.0);
        QVERIFY(!p->acceleration.has_value());
    }

    void roundTripsThroughItsFileForm()
    {
        EnergyProfile p = readEnergyProfile(quadJson()).value();
        p.source = ProfileSource::Fit;
        p.acceleration = 2.5;
        p.reserve = 0.25;
        const auto back = readEnergyProfile(writeEnergyProfile(p));
        QVERIFY(back.ok());
        QCOMPARE(back.value(), p);
    }

    // The curve goes through hover power at rest and cruise power at cruise speed; between them
    // it is the documented parabola, above cruise speed the cube.
    void levelPowerFollowsTheDocumentedCurve()
    {
        const EnergyProfile p = readEnergyProfile(quadJson()).value();
        QCOMPARE(p.levelPowerW(0), 300.0);
        QCOMPARE(p.levelPowerW(10), 260.0);
        QCOMPARE(p.levelPowerW(5), 300.0 - 40.0 * 0.25);
        QCOMPARE(p.levelPowerW(20), 260.0 * 8);
    }

    void namesWhatIsMissingOrWrong_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        QTest::newRow("missing power") << QByteArray(R"({"batteryWh": 90, "cruiseSpeed": 10, "climbRate": 3,
            "descentRate": 2, "hoverPowerW": 300, "cruisePowerW": 260, "climbPowerW": 420})")
                                       << QStringLiteral("descentPowerW");
        QTest::newRow("zero battery") << quadJson().replace("\"batteryWh\": 90", "\"batteryWh\": 0")
                                      << QStringLiteral("batteryWh must be a positive number");
        QTest::newRow("reserve of one") << quadJson().replace("{", "{\"reserve\": 1, ")
                                        << QStringLiteral("reserve must be a fraction");
        QTest::newRow("text for a number") << quadJson().replace("\"climbRate\": 3", "\"climbRate\": \"fast\"")
                                           << QStringLiteral("/climbRate");
        QTest::newRow("unknown source") << quadJson().replace("{", "{\"source\": \"guess\", ")
                                        << QStringLiteral("/source");
        QTest::newRow("syntax") << QByteArray("{\n  \"batteryWh\": 90,\n  oops\n}") << QStringLiteral(":3:");
    }
    void namesWhatIsMissingOrWrong()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        const auto p = readEnergyProfile(json);
        QVERIFY(!p.ok());
        const QString text = p.error().withFile(QStringLiteral("quad.json")).toString();
        QVERIFY2(text.contains(expected), qPrintable(text));
    }
};

QTEST_APPLESS_MAIN(TstEnergyProfile)
#include "tst_energyprofile.moc"
