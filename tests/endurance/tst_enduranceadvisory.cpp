// EnduranceAdvisory, the fly view's "time to come home", on a Vehicle fed telemetry by hand. Every
// expected figure is worked out here from the profile's numbers: hover 360 W, cruise 288 W at
// 10 m/s, descent 180 W at 1 m/s, a 100 Wh battery with a 20 % reserve (20 Wh), so 1000 m level at
// cruise is 100 s × 288 W = 8 Wh and 30 m down is 30 s × 180 W = 1.5 Wh.
#include "EnduranceAdvisory.h"
#include "Geodesy.h"
#include "RouteAnalyzer.h"
#include "RouteEndurance.h"
#include "RouteModel.h"
#include "Vehicle.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;
using namespace sortie::endurance;
using F = vehicle::TelemetryField;
using Level = EnduranceAdvisory::Level;

namespace {
const mission::GeoPoint kHome{56.95, 24.1};
constexpr double kHomeAmsl = 100;

EnergyProfile quad()
{
    EnergyProfile p;
    p.name = QStringLiteral("Test quad");
    p.batteryWh = 100;
    p.reserve = 0.2;
    p.cruiseSpeed = 10;
    p.climbRate = 2;
    p.descentRate = 1;
    p.hoverPowerW = 360;
    p.cruisePowerW = 288;
    p.climbPowerW = 540;
    p.descentPowerW = 180;
    return p;
}

mission::GeoPoint east(double metres)
{
    return mission::geodesicDirect(kHome, 90, metres).point;
}

// Four waypoints 30 m above home, 0, 1, 2 and 3 km east of it, at 10 m/s.
std::vector<vehicle::MissionItem> line()
{
    std::vector<vehicle::MissionItem> items;
    for (int i = 0; i < 4; ++i)
        items.push_back({east(1000.0 * i).latitude, east(1000.0 * i).longitude, 30, 10, 0, {}});
    return items;
}

// Armed, 1 km east of home and 30 m above it, flying to waypoint 3 (index 2), with `battery` left.
void flying(vehicle::Vehicle &v, double battery, qint64 time)
{
    v.ingest({{F::Latitude, east(1000).latitude, time}, {F::Longitude, east(1000).longitude, time},
              {F::AltitudeAmsl, kHomeAmsl + 30, time}, {F::AltitudeAgl, 30, time},
              {F::HomeLatitude, kHome.latitude, time}, {F::HomeLongitude, kHome.longitude, time},
              {F::HomeAltitudeAmsl, kHomeAmsl, time}, {F::Armed, 1, time}, {F::MissionCurrent, 2, time},
              {F::BatteryRemaining, battery, time}});
}

bool near(const QVariant &v, double expected, double tolerance = 1e-6)
{
    return v.isValid() && std::abs(v.toDouble() - expected) <= tolerance;
}
} // namespace

class TstEnduranceAdvisory : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        m_settings = std::make_unique<QSettings>(m_dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        m_analyzer = std::make_unique<mission::RouteAnalyzer>(&m_model);
        m_endurance = std::make_unique<RouteEndurance>(m_settings.get(), m_analyzer.get(), &m_model);
    }
    void cleanup()
    {
        m_endurance.reset();
        m_analyzer.reset();
        m_settings.reset();
    }

    // Missing inputs are missing, never 0: no profile, no battery figure, no home.
    void unknownWithoutItsInputs()
    {
        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        EnduranceAdvisory advisory;
        advisory.setInterval(0);
        advisory.setVehicle(&v);
        advisory.setEndurance(m_endurance.get());
        flying(v, 0.5, 1000);
        QTRY_VERIFY(advisory.problem().contains(QStringLiteral("profile")));
        QCOMPARE(advisory.level(), Level::Unknown);
        QVERIFY(!advisory.energyLeftWh().isValid() && !advisory.energyHomeWh().isValid() && !advisory.margin().isValid());
        QCOMPARE(advisory.summary(), QStringLiteral("Battery at end of route: — · home needs —"));

        m_endurance->setProfile(quad());
        QTRY_COMPARE(advisory.level(), Level::Normal);

        vehicle::Vehicle noBattery(nullptr);
        noBattery.ingest({{F::Latitude, kHome.latitude, 1}, {F::Longitude, kHome.longitude, 1},
                          {F::HomeLatitude, kHome.latitude, 1}, {F::HomeLongitude, kHome.longitude, 1}});
        advisory.setVehicle(&noBattery);
        QCOMPARE(advisory.level(), Level::Unknown);
        QVERIFY(!advisory.energyLeftWh().isValid());
        QVERIFY(advisory.problem().contains(QStringLiteral("battery")));

        vehicle::Vehicle noHome(nullptr);
        noHome.ingest({{F::Latitude, kHome.latitude, 1}, {F::Longitude, kHome.longitude, 1}, {F::BatteryRemaining, 0.9, 1}});
        advisory.setVehicle(&noHome);
        QCOMPARE(advisory.level(), Level::Unknown);
        QVERIFY(!advisory.energyHomeWh().isValid());
        QVERIFY(advisory.problem().contains(QStringLiteral("home")));
    }

    // 50 Wh left; home is 8 Wh across and 1.5 Wh down; the reserve 20 Wh: 20.5 Wh to spare. The
    // rest of the mission (to waypoint 3 at 2 km, then 4 at 3 km) is 2000 m at cruise: 16 Wh.
    void figuresByHand()
    {
        m_endurance->setProfile(quad());
        vehicle::Vehicle v(nullptr);
        v.setMission(line());
        EnduranceAdvisory advisory;
        advisory.setInterval(0);
        advisory.setEndurance(m_endurance.get());
        advisory.setVehicle(&v);
        flying(v, 0.5, 1000);
        QTRY_VERIFY(near(advisory.energyLeftWh(), 50));
        QVERIFY(near(advisory.energyHomeWh(), 9.5, 1e-6));
        QVERIFY(near(advisory.reserveWh(), 20));
        QVERIFY(near(advisory.margin(), 20.5, 1e-6));
        QVERIFY(near(advisory.batteryAtEnd(), (50 - 16) / 100.0, 1e-8));
        QCOMPARE(advisory.level(), Level::Normal);
        QCOMPARE(advisory.summary(), QStringLiteral("Battery at end of route: 34 % · home needs 9.5 Wh"));
        QVERIFY(advisory.advice().isEmpty());

        // Past the last waypoint nothing is left to fly: the battery at the end is the battery now.
        v.ingest({{F::MissionCurrent, 4, 2000}});
        QTRY_VERIFY(near(advisory.batteryAtEnd(), 0.5));
        // Without a mission on board there is no end to predict (missing), and home still counts.
        v.setMission({});
        QTRY_VERIFY(!advisory.batteryAtEnd().isValid());
        QVERIFY(near(advisory.energyHomeWh(), 9.5, 1e-6));

        // A 12 m/s wind from the west: home lies west, so no headway: Red, and home is missing.
        m_endurance->setWindSpeed(12);
        m_endurance->setWindFrom(270);
        QTRY_COMPARE(advisory.level(), Level::Red);
        QVERIFY(!advisory.energyHomeWh().isValid());
        QVERIFY(advisory.advice().contains(QStringLiteral("headway")));
    }

    // Amber within 10 Wh (10 % of the battery) of the reserve, Red at it; each escalation one log
    // line, none while the level holds, and back to Normal only past 10 + 2 Wh.
    void escalatesOnceWithHysteresis()
    {
        m_endurance->setProfile(quad());
        vehicle::CommandLog log;
        vehicle::Vehicle v(nullptr);
        v.setCommandLog(&log);
        v.setMission(line());
        EnduranceAdvisory advisory;
        advisory.setInterval(0);
        advisory.setEndurance(m_endurance.get());
        advisory.setVehicle(&v);
        QSignalSpy escalated(&advisory, &EnduranceAdvisory::escalated);
        qint64 t = 1000;
        auto battery = [&](double fraction, Level expected) {
            flying(v, fraction, t += 1000);
            QTRY_VERIFY(near(advisory.energyLeftWh(), fraction * 100, 1e-9));
            QCOMPARE(advisory.level(), expected);
        };

        battery(0.50, Level::Normal);   // margin 20.5
        QCOMPARE(log.count(), 0);
        battery(0.39, Level::Amber);    // 39 − 9.5 − 20 = 9.5 ≤ 10
        QCOMPARE(log.count(), 1);
        QVERIFY2(log.at(0).command.startsWith(QStringLiteral("Battery: time to come home — 39 Wh left, home needs 9.5 Wh")),
                 qPrintable(log.at(0).command));
        QVERIFY(advisory.advice().contains(QStringLiteral("9.5 Wh to spare")));
        battery(0.405, Level::Amber);   // 11 Wh: above the band but within the hysteresis
        battery(0.39, Level::Amber);
        QCOMPARE(log.count(), 1);
        battery(0.29, Level::Red);      // −0.5 Wh
        QCOMPARE(log.count(), 2);
        QVERIFY(log.at(1).command.contains(QStringLiteral("reserve is being used")));
        battery(0.31, Level::Red);      // 1.5 Wh: not yet clear of 0 by 2 Wh
        battery(0.30, Level::Red);
        QCOMPARE(log.count(), 2);
        battery(0.32, Level::Amber);    // 2.5 Wh: clear of Red, not of Amber; no line for a fall
        QCOMPARE(log.count(), 2);
        battery(0.45, Level::Normal);   // 15.5 Wh
        battery(0.38, Level::Amber);    // after Normal, an escalation is news again
        QCOMPARE(log.count(), 3);
        QCOMPARE(escalated.count(), 3);
        QCOMPARE(log.at(2).vehicle, v.name());
        QVERIFY(!advisory.returnHomeQuestion().isEmpty());

        // Disarmed (on the ground), a low battery is shown but not logged as news.
        vehicle::Vehicle parked(nullptr);
        parked.setCommandLog(&log);
        advisory.setVehicle(&parked);
        parked.ingest({{F::Latitude, kHome.latitude, 1}, {F::Longitude, kHome.longitude, 1}, {F::HomeLatitude, kHome.latitude, 1},
                       {F::HomeLongitude, kHome.longitude, 1}, {F::BatteryRemaining, 0.1, 1}, {F::Armed, 0, 1}});
        QTRY_COMPARE(advisory.level(), Level::Red);
        QCOMPARE(log.count(), 3);
    }

    void judgeAtTheEdges()
    {
        QCOMPARE(EnduranceAdvisory::judge(0.0, 10, 2, Level::Normal), Level::Red);
        QCOMPARE(EnduranceAdvisory::judge(10.0, 10, 2, Level::Normal), Level::Amber);
        QCOMPARE(EnduranceAdvisory::judge(10.5, 10, 2, Level::Normal), Level::Normal);
        QCOMPARE(EnduranceAdvisory::judge(12.0, 10, 2, Level::Amber), Level::Amber);
        QCOMPARE(EnduranceAdvisory::judge(12.1, 10, 2, Level::Amber), Level::Normal);
        QCOMPARE(EnduranceAdvisory::judge(2.0, 10, 2, Level::Red), Level::Red);
        QCOMPARE(EnduranceAdvisory::judge(2.1, 10, 2, Level::Red), Level::Amber);
        QCOMPARE(EnduranceAdvisory::judge(13.0, 10, 2, Level::Red), Level::Normal);
    }

    // However fast telemetry comes, the advisory recomputes at most once per interval.
    void throttled()
    {
        m_endurance->setProfile(quad());
        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        EnduranceAdvisory advisory;
        advisory.setInterval(250);
        advisory.setEndurance(m_endurance.get());
        advisory.setVehicle(&v);
        QSignalSpy changed(&advisory, &EnduranceAdvisory::changed);
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < 100; ++i) {
            flying(v, 0.9 - i * 0.001, 1000 + i);
            QCoreApplication::processEvents();
        }
        const qint64 elapsed = clock.elapsed();
        // The first change at once, then one per 250 ms at most (the loop's own time allowed for).
        QVERIFY2(changed.count() <= 2 + elapsed / 250, qPrintable(QString::number(changed.count())));
        QTRY_VERIFY(near(advisory.energyLeftWh(), (0.9 - 99 * 0.001) * 100, 1e-9));
    }

private:
    QTemporaryDir m_dir;
    mission::RouteModel m_model;
    std::unique_ptr<QSettings> m_settings;
    std::unique_ptr<mission::RouteAnalyzer> m_analyzer;
    std::unique_ptr<RouteEndurance> m_endurance;
};

QTEST_GUILESS_MAIN(TstEnduranceAdvisory)
#include "tst_enduranceadvisory.moc"
