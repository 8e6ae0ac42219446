// RouteEndurance, the object the views bind to, over a route model and its analyzer: missing
// without a profile (never 0), the figures with one, its rule in the analyzer's validation, and
// the gate uploads and saves go through refusing a route that plans no battery change.
#include "Geodesy.h"
#include "RouteAnalyzer.h"
#include "RouteEndurance.h"
#include "RouteModel.h"
#include "ValidationGate.h"

#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::endurance;
using namespace sortie::mission;

namespace {
const GeoPoint kOrigin{56.95, 24.1};

// Four 1000 m legs at 10 m/s (8 Wh each at 288 W) from home, 30 m up.
Route lineRoute()
{
    Route r;
    r.settings.home = HomePosition{kOrigin, 0};
    for (int i = 0; i <= 4; ++i) {
        Waypoint w;
        w.position = geodesicDirect(kOrigin, 90, 1000.0 * i).point;
        w.altitude = 30;
        w.speed = 10;
        r.segments.push_back(w);
    }
    return r;
}

QByteArray profileJson(double batteryWh)
{
    return QStringLiteral(R"({"name": "Line quad", "batteryWh": %1, "cruiseSpeed": 10, "climbRate": 2, "descentRate": 1,
        "hoverPowerW": 360, "cruisePowerW": 288, "climbPowerW": 540, "descentPowerW": 180})").arg(batteryWh).toUtf8();
}

bool hasRule(const ValidationReport &report, const QString &rule, Severity severity)
{
    for (const ValidationIssue &i : report.issues)
        if (i.rule == rule && i.severity == severity)
            return true;
    return false;
}
} // namespace

class TstRouteEndurance : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        QFile::remove(path("settings.ini"));
    }

    void missingWithoutAProfileThenFiguresAndTheRule()
    {
        QSettings settings(path("settings.ini"), QSettings::IniFormat);
        RouteModel model;
        model.resetRoute(lineRoute());
        RouteAnalyzer analyzer(&model);
        RouteEndurance endurance(&settings, &analyzer, &model);
        analyzer.recomputeNow();
        QVERIFY(endurance.isMissing());
        QVERIFY(!endurance.flightTime().isValid() && !endurance.energyWh().isValid() && !endurance.batteryAtEnd().isValid());
        QVERIFY(!endurance.problem().isEmpty());
        QVERIFY(!hasRule(analyzer.validation(), QStringLiteral("endurance-battery"), Severity::Error));

        // A 22.5 Wh battery with the default 20 % reserve: 18 Wh usable, the route needs 32 Wh.
        write("small.json", profileJson(22.5));
        QSignalSpy changed(&endurance, &RouteEndurance::estimateChanged);
        QVERIFY(endurance.loadProfile(path("small.json")));
        analyzer.recomputeNow();
        QVERIFY(!changed.isEmpty());
        QVERIFY(!endurance.isMissing());
        QCOMPARE(endurance.profileName(), QStringLiteral("Line quad"));
        QCOMPARE(endurance.profileSource(), QStringLiteral("file"));
        QVERIFY(std::abs(endurance.flightTime().toDouble() - 400) < 1e-3);
        QVERIFY(std::abs(endurance.energyWh().toDouble() - 32) < 1e-3);
        QCOMPARE(endurance.batteriesNeeded().toInt(), 2);
        QCOMPARE(endurance.changeCount(), 1);
        QCOMPARE(endurance.estimate()->changes.at(0).at.segment + 1, 3); // at waypoint 3
        QCOMPARE(endurance.noReturnLeg().toInt(), 2);
        QVERIFY(endurance.noReturnDistance().isValid()); // missing would read as 0 m
        QCOMPARE(endurance.noReturnDistance().toDouble(), endurance.estimate()->pointOfNoReturn->distance);
        // Home from 1 km out, 30 m up: 8 Wh back at cruise, 1.5 Wh down.
        QVERIFY(std::abs(endurance.energyHomeWh(geodesicDirect(kOrigin, 90, 1000).point.latitude,
                                                geodesicDirect(kOrigin, 90, 1000).point.longitude, 30).toDouble() - 9.5) < 1e-3);

        // The rule is in the analyzer's report, and the gate uploads and saves use refuses it.
        QVERIFY(hasRule(analyzer.validation(), QStringLiteral("endurance-battery"), Severity::Error));
        const Result<void> refused = permitRelease(analyzer.validation(), ValidationOverride::None, QStringLiteral("Upload"));
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QStringLiteral("Waypoint 3")), qPrintable(refused.error().message));

        // A head wind the legs cannot be flown against: an error too, and the figures are missing.
        endurance.setWindSpeed(12);
        endurance.setWindFrom(90);
        analyzer.recomputeNow();
        QVERIFY(endurance.isMissing());
        QVERIFY(hasRule(analyzer.validation(), QStringLiteral("endurance-wind"), Severity::Error));
        endurance.setWindSpeed(0);

        // A battery big enough: no error, and the choice is remembered.
        write("big.json", profileJson(200));
        QVERIFY(endurance.loadProfile(path("big.json")));
        analyzer.recomputeNow();
        QCOMPARE(endurance.batteriesNeeded().toInt(), 1);
        QVERIFY(!endurance.noReturnDistance().isValid() && !endurance.noReturnLeg().isValid()); // none: undefined, never 0
        QVERIFY(permitRelease(analyzer.validation(), ValidationOverride::None, QStringLiteral("Upload")).ok());
        RouteEndurance again(&settings, &analyzer, &model);
        QCOMPARE(again.profilePath(), path("big.json"));
        QVERIFY(!again.isMissing());
    }

    void aBadProfileFileIsAProblemNamingItsLine()
    {
        QSettings settings(path("settings.ini"), QSettings::IniFormat);
        RouteModel model;
        model.resetRoute(lineRoute());
        RouteAnalyzer analyzer(&model);
        RouteEndurance endurance(&settings, &analyzer, &model);
        write("bad.json", "{\n \"batteryWh\": -1\n}\n");
        QVERIFY(!endurance.loadProfile(path("bad.json")));
        QVERIFY(endurance.isMissing());
        QVERIFY2(endurance.problem().contains(path("bad.json")), qPrintable(endurance.problem()));
    }

private:
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
    void write(const char *name, const QByteArray &data)
    {
        QFile f(path(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TstRouteEndurance)
#include "tst_routeendurance.moc"
