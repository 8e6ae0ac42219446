// The simulated vehicle's flight model: refusals a real autopilot gives, and a mission flown in order.
#include "FlightModel.h"

#include <QtTest>

using sortie::sim::FlightModel;

namespace {
constexpr double kRigaLat = 56.9496, kRigaLon = 24.1052;

void run(FlightModel &m, double seconds, double dt = 0.1)
{
    for (double t = 0; t < seconds; t += dt)
        m.tick(dt);
}
} // namespace

class TestFlightModel : public QObject
{
    Q_OBJECT

private slots:
    void refusesWhatAnAutopilotRefuses()
    {
        FlightModel m(kRigaLat, kRigaLon, 10);
        QCOMPARE(QString::fromStdString(m.takeoff()), QStringLiteral("arm before take-off"));
        QVERIFY(!m.startMission().empty());
        QVERIFY(!m.land().empty());
        QVERIFY(m.arm().empty());
        QVERIFY(!m.arm().empty()); // twice
        QVERIFY(m.takeoff(30).empty());
        run(m, 2);
        QVERIFY(m.state().airborne());
        QCOMPARE(QString::fromStdString(m.disarm()), QStringLiteral("cannot disarm in flight; land first"));
    }

    void takeoffClimbsToAltitudeAndHolds()
    {
        FlightModel m(kRigaLat, kRigaLon, 10);
        m.arm();
        m.takeoff(30);
        run(m, 5);
        QVERIFY(m.state().verticalSpeed > 0);
        run(m, 20);
        QCOMPARE(m.state().mode, FlightModel::Mode::Hold);
        QVERIFY(qAbs(m.state().altitudeAgl - 30) < 0.5);
        QVERIFY(qAbs(m.state().altitudeAmsl() - 40) < 0.5);
        QVERIFY(m.state().batteryRemaining < 1.0);
    }

    void flysTheMissionInOrderThenHolds()
    {
        FlightModel m(kRigaLat, kRigaLon, 10);
        double lat1, lon1, lat2, lon2;
        sortie::sim::sphericalDestination(kRigaLat, kRigaLon, 90, 100, &lat1, &lon1);
        sortie::sim::sphericalDestination(lat1, lon1, 0, 100, &lat2, &lon2);
        QVERIFY(m.setMission({{lat1, lon1, 25, 10}, {lat2, lon2, 35, 10}}).empty());
        m.arm();
        QVERIFY(m.startMission().empty());
        int seenFirst = -1;
        for (int i = 0; i < 600 && m.state().mode == FlightModel::Mode::Auto; ++i) {
            QVERIFY(!m.state().missionComplete);
            m.tick(0.1);
            if (m.state().currentWaypoint == 1 && seenFirst < 0)
                seenFirst = i;
        }
        QVERIFY(seenFirst > 0);
        QCOMPARE(m.state().mode, FlightModel::Mode::Hold);
        QVERIFY(m.state().missionComplete); // what the HCI server's RoutePass and the VCI progress report
        QCOMPARE(m.state().currentWaypoint, 1);
        QVERIFY(sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, lat2, lon2) < 2.5);
        QVERIFY(qAbs(m.state().altitudeAgl - 35) < 0.6);
    }

    // A mission started on the ground begins straight up (mission::flownLegs' take-off): the vehicle
    // stays over where it stood until it is at the first waypoint's height, then moves across; a
    // landing waypoint is reached at its height and landed on straight down, onto the ground under it.
    void missionLeavesTheGroundStraightUpAndLandsStraightDown()
    {
        FlightModel m(kRigaLat, kRigaLon, 10);
        double lat1, lon1;
        sortie::sim::sphericalDestination(kRigaLat, kRigaLon, 90, 150, &lat1, &lon1);
        m.setGround([&](double lat, double lon) -> std::optional<double> {
            return sortie::sim::sphericalDistance(lat, lon, lat1, lon1) < 20 ? 16.0 : 10.0;  // a 6 m mound at the landing point
        });
        FlightModel::Waypoint land{lat1, lon1, 30, 10};
        land.landHere = true;
        QVERIFY(m.setMission({{kRigaLat, kRigaLon, 30, 10}, land}).empty());
        m.arm();
        QVERIFY(m.startMission().empty());
        double offDuringClimb = 0;
        while (m.state().altitudeAgl < 29.5) {
            m.tick(0.1);
            offDuringClimb = std::max(offDuringClimb, sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, kRigaLat, kRigaLon));
        }
        QVERIFY2(offDuringClimb < 0.01, qPrintable(QString::number(offDuringClimb)));
        double offDuringDescent = 0;
        for (int i = 0; i < 1000 && m.state().armed; ++i) {
            m.tick(0.1);
            if (m.state().mode == FlightModel::Mode::Land)
                offDuringDescent = std::max(offDuringDescent, sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, lat1, lon1));
        }
        QVERIFY(!m.state().armed);  // landed and disarmed
        QVERIFY(m.state().missionComplete);
        QVERIFY2(offDuringDescent < 2.5, qPrintable(QString::number(offDuringDescent)));  // within the acceptance radius
        QVERIFY(qAbs(m.state().altitudeAmsl() - 16) < 0.01);  // on the mound, not at home's height
        QVERIFY(!m.state().airborne());
    }

    void pauseHoldsAndResumeContinues()
    {
        FlightModel m(kRigaLat, kRigaLon, 0);
        double lat, lon;
        sortie::sim::sphericalDestination(kRigaLat, kRigaLon, 45, 300, &lat, &lon);
        m.setMission({{lat, lon, 20, 8}});
        m.arm();
        m.startMission();
        run(m, 10);
        QVERIFY(m.pause().empty());
        const double held = sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, lat, lon);
        run(m, 5);
        QCOMPARE(sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, lat, lon), held);
        QVERIFY(m.resume().empty());
        run(m, 5);
        QVERIFY(sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, lat, lon) < held - 20);
    }

    void returnHomeLandsAndDisarms()
    {
        FlightModel m(kRigaLat, kRigaLon, 0);
        m.arm();
        double lat, lon;
        sortie::sim::sphericalDestination(kRigaLat, kRigaLon, 180, 150, &lat, &lon);
        QVERIFY(m.goTo(lat, lon, 15).empty());
        run(m, 40);
        QCOMPARE(m.state().mode, FlightModel::Mode::Hold);
        QVERIFY(m.returnHome().empty());
        run(m, 120);
        QVERIFY(!m.state().armed);
        QVERIFY(!m.state().airborne());
        QVERIFY(sortie::sim::sphericalDistance(m.state().latitude, m.state().longitude, kRigaLat, kRigaLon) < 2.5);
    }

    // The battery is an energy store drained by the profile's powers: hover, level flight at the
    // cruise speed, a straight climb; nothing while disarmed; arming refused below 10 %.
    void batteryDrainsByWhatTheVehicleDoes()
    {
        FlightModel m(kRigaLat, kRigaLon, 10);
        const auto &p = m.limits().energy;
        run(m, 60);
        QCOMPARE(m.state().batteryRemaining, 1.0); // disarmed: kept
        QCOMPARE(m.state().batteryCurrent, 0.0);
        QVERIFY(std::abs(m.state().batteryVoltage - 16.8) < 1e-9); // a full 4S at rest
        m.arm();
        m.takeoff(30);
        run(m, 3);
        QVERIFY(std::abs(m.state().batteryVoltage * m.state().batteryCurrent - p.climbPowerW) < 1e-6);
        run(m, 20);
        QCOMPARE(m.state().mode, FlightModel::Mode::Hold);
        const double before = m.battery().energyLeftWh();
        run(m, 100);
        QVERIFY(std::abs(m.state().batteryVoltage * m.state().batteryCurrent - p.hoverPowerW) < 1e-6);
        QVERIFY(std::abs((before - m.battery().energyLeftWh()) - p.hoverPowerW * 100 / 3600) < 0.01);
        QVERIFY(m.state().batteryVoltage < 16.8 - 0.3); // sags under load
        double lat, lon;
        sortie::sim::sphericalDestination(kRigaLat, kRigaLon, 90, 2000, &lat, &lon);
        m.goTo(lat, lon, 30);
        run(m, 20);
        QCOMPARE(m.state().groundSpeed, p.cruiseSpeed);
        QVERIFY(std::abs(m.state().batteryVoltage * m.state().batteryCurrent - p.cruisePowerW) < 0.5);
        QCOMPARE(m.state().batteryRemaining, m.battery().energyLeftWh() / p.batteryWh);

        // Flown down to under 10 %: landed, it may not arm again.
        m.land();
        run(m, 20);
        QVERIFY(!m.state().armed);
        QVERIFY(sortie::sim::SimBattery::cellVoltage(0.5) < sortie::sim::SimBattery::cellVoltage(0.9));
        FlightModel::Limits small = FlightModel::Limits::forProfile(p);
        small.energy.batteryWh = 1; // 15 s of hover
        FlightModel low(kRigaLat, kRigaLon, 10, small);
        low.arm();
        low.takeoff(5);
        run(low, 20);
        low.land();
        run(low, 10);
        QVERIFY(low.state().batteryRemaining < 0.1);
        QCOMPARE(QString::fromStdString(low.arm()), QStringLiteral("battery too low to arm"));
    }

    void modesByName()
    {
        FlightModel::Mode mode;
        QVERIFY(FlightModel::modeFromName("return_home", &mode));
        QCOMPARE(mode, FlightModel::Mode::ReturnHome);
        QVERIFY(!FlightModel::modeFromName("loiter-ish", &mode));
    }
};

QTEST_APPLESS_MAIN(TestFlightModel)
#include "tst_flightmodel.moc"
