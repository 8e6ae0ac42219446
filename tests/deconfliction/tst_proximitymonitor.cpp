// ProximityMonitor against real simulated vehicles: two VCI vehicles of sortie-sim take off and are
// sent at each other at the same height; the alert names both, lands in the command log as an
// alert (the flight recorder keeps those), and goes when they have passed. Against manned traffic
// (a picture fed as a source feeds it): an aircraft inbound at its height alerts, one 50 km away
// does not, and a pressure altitude 500 m above the vehicle alerts where an MSL one does not (the
// 250 m margin for the day's pressure).
#include "CommandLog.h"
#include "HciClient.h"
#include "HciSession.h"
#include "ProximityMonitor.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "TrafficPicture.h"
#include "VehicleFleet.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using deconfliction::ProximityMonitor;

class TestProximityMonitor : public QObject
{
    Q_OBJECT

    std::unique_ptr<sim::SimVciFleet> m_vci;
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_client;
    std::unique_ptr<client::VehicleFleet> m_fleet;

    // Two VCI vehicles in the air, 30 m above home; false when they did not get there.
    bool twoAirborne()
    {
        sim::SimVciFleetOptions options;
        options.count = 2;
        options.firstPort = 0;
        options.vehicle.timeScale = 4;
        m_vci = std::make_unique<sim::SimVciFleet>(options);
        QString error;
        if (!m_vci->start(&error))
            return false;
        m_session = std::make_unique<hci::HciSession>();
        m_client = std::make_unique<hci::HciClient>(m_session.get());
        m_fleet = std::make_unique<client::VehicleFleet>(m_client.get());
        for (const auto &listener : m_vci->listeners())
            m_fleet->addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(listener->port()));
        for (int row = 0; row < 2; ++row) {
            vehicle::Vehicle *v = m_fleet->vehicleAt(row);
            if (!QTest::qWaitFor([v] { return v->isConnected() && v->position().isValid(); }, 10000))
                return false;
            v->arm();
            if (!QTest::qWaitFor([v] { return v->armed(); }, 10000))
                return false;
            v->takeoff(30);
        }
        return QTest::qWaitFor([this] { return m_fleet->vehicleAt(0)->altitudeAgl() > 25 && m_fleet->vehicleAt(1)->altitudeAgl() > 25; }, 30000);
    }

private slots:
    void cleanup()
    {
        m_fleet.reset();
        m_client.reset();
        m_session.reset();
        m_vci.reset();
    }

    void twoVehiclesSentAtEachOther()
    {
        QVERIFY(twoAirborne());
        ProximityMonitor monitor(m_fleet.get(), nullptr, 0);
        monitor.check();
        QCOMPARE(monitor.count(), 0);  // hovering a few hundred metres apart

        // Each flies to where the other is, at the same height: head-on.
        const QGeoCoordinate a = m_fleet->vehicleAt(0)->position(), b = m_fleet->vehicleAt(1)->position();
        m_fleet->goTo(0, b.latitude(), b.longitude());
        m_fleet->goTo(1, a.latitude(), a.longitude());
        QSignalSpy raised(&monitor, &ProximityMonitor::alertRaised);
        QVERIFY(QTest::qWaitFor([&] { monitor.check(); return monitor.count() > 0; }, 60000));
        const ProximityMonitor::Alert alert = monitor.alerts().front();
        QVERIFY2(alert.text.contains(m_fleet->vehicleAt(0)->name()) && alert.text.contains(m_fleet->vehicleAt(1)->name()), qPrintable(alert.text));
        QVERIFY(!alert.traffic);
        QVERIFY(alert.horizontal < 20 && alert.vertical < 15);
        QVERIFY(alert.inSeconds >= 0 && alert.inSeconds <= 60);
        QCOMPARE(raised.count(), 1);

        // Raised once: in the command log as an alert, not again while it stays.
        const vehicle::CommandLog &log = *m_fleet->commandLog();
        int alerts = 0;
        for (int row = 0; row < log.count(); ++row)
            alerts += log.at(row).status == vehicle::CommandLog::Status::Alert ? 1 : 0;
        QCOMPARE(alerts, 1);
        QCOMPARE(log.at(log.count() - 1).command, alert.text);
        QVERIFY(log.index(log.count() - 1).data(vehicle::CommandLog::FailedRole).toBool());  // shown as a problem
        monitor.check();
        QCOMPARE(raised.count(), 1);

        // Once they have passed each other it goes.
        QSignalSpy cleared(&monitor, &ProximityMonitor::alertCleared);
        QVERIFY(QTest::qWaitFor([&] { monitor.check(); return monitor.count() == 0; }, 90000));
        QCOMPARE(cleared.count(), 1);
    }

    void trafficInboundAtTheVehiclesHeight()
    {
        QVERIFY(twoAirborne());
        qint64 now = 1'000'000;
        traffic::TrafficPicture picture([&now] { return now; });
        ProximityMonitor monitor(m_fleet.get(), &picture, 0);
        const vehicle::Vehicle &v = *m_fleet->vehicleAt(0);
        const double amsl = v.altitudeAmsl();
        QVERIFY(std::isfinite(amsl));

        const auto aircraft = [&](quint32 address, double eastKm, double heightAbove, traffic::AltitudeReference reference) {
            traffic::TrafficReport r;
            r.address = address;
            r.callsign = QStringLiteral("TST%1").arg(address);
            r.latitude = v.position().latitude();
            r.longitude = v.position().longitude() + eastKm * 1000.0 / (111320.0 * std::cos(v.position().latitude() * M_PI / 180.0));
            r.altitudeM = amsl + heightAbove;
            r.altitudeReference = reference;
            r.groundSpeedMps = 60;
            r.trackDeg = 270;  // westbound, towards the vehicle
            r.verticalRateMps = 0;
            picture.report(r);
        };
        aircraft(0xABC001, 50, 0, traffic::AltitudeReference::MeanSeaLevel);    // 50 km out: not within 60 s
        aircraft(0xABC002, 3, 500, traffic::AltitudeReference::MeanSeaLevel);   // overhead by 500 m: separated
        monitor.check();
        QCOMPARE(monitor.count(), 0);

        aircraft(0xABC003, 3, 500, traffic::AltitudeReference::Barometric);     // 500 m by pressure: maybe not
        monitor.check();
        QVERIFY(monitor.count() >= 1);
        QVERIFY2(monitor.alerts().front().key.contains(QStringLiteral("traffic:ABC003")), qPrintable(monitor.alerts().front().key));
        QVERIFY(monitor.alerts().front().traffic);

        aircraft(0xABC004, 3, 50, traffic::AltitudeReference::MeanSeaLevel);    // at its height, 3 km out
        monitor.check();
        bool found = false;
        for (const auto &a : monitor.alerts())
            found = found || (a.key.contains(QStringLiteral("ABC004")) && a.text.contains(QStringLiteral("TST")));
        QVERIFY(found);
    }
};

QTEST_GUILESS_MAIN(TestProximityMonitor)
#include "tst_proximitymonitor.moc"
