// ZoneAlertMonitor against a real simulated vehicle: sortie-sim's VCI vehicle takes off and is sent
// towards an exclusion zone (under another zone whose floor it passes below): one alert, 30 s or
// less ahead, naming the zone; one line in the command log however often it is checked; gone once
// the vehicle has flown through and out. Sent out of its own fence: the alert says it leaves it.
#include "CommandLog.h"
#include "HciClient.h"
#include "HciSession.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "VehicleFleet.h"
#include "ZoneAlertMonitor.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using airspace::Zone;
using airspace::ZoneAlertMonitor;

namespace {

Zone circle(const QString &name, const QGeoCoordinate &centre, double radius)
{
    Zone z;
    z.name = name;
    z.shape = airspace::ZoneCircle{{centre.latitude(), centre.longitude()}, radius};
    return z;
}

int alertLines(const vehicle::CommandLog &log)
{
    int n = 0;
    for (int row = 0; row < log.count(); ++row)
        n += log.at(row).status == vehicle::CommandLog::Status::Alert ? 1 : 0;
    return n;
}

} // namespace

class TestZoneAlertMonitor : public QObject
{
    Q_OBJECT

    std::unique_ptr<sim::SimVciFleet> m_vci;
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_client;
    std::unique_ptr<client::VehicleFleet> m_fleet;

    vehicle::Vehicle *airborne()
    {
        sim::SimVciFleetOptions options;
        options.count = 1;
        options.firstPort = 0;
        options.vehicle.timeScale = 4;
        m_vci = std::make_unique<sim::SimVciFleet>(options);
        QString error;
        if (!m_vci->start(&error))
            return nullptr;
        m_session = std::make_unique<hci::HciSession>();
        m_client = std::make_unique<hci::HciClient>(m_session.get());
        m_fleet = std::make_unique<client::VehicleFleet>(m_client.get());
        m_fleet->addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(m_vci->listeners().front()->port()));
        vehicle::Vehicle *v = m_fleet->vehicleAt(0);
        if (!QTest::qWaitFor([v] { return v->isConnected() && v->position().isValid(); }, 10000))
            return nullptr;
        v->arm();
        if (!QTest::qWaitFor([v] { return v->armed(); }, 10000))
            return nullptr;
        v->takeoff(30);
        return QTest::qWaitFor([v] { return v->altitudeAgl() > 29 && v->mode() == QLatin1String("hold"); }, 30000) ? v : nullptr;
    }

private slots:
    void cleanup()
    {
        m_fleet.reset();
        m_client.reset();
        m_session.reset();
        m_vci.reset();
    }

    void flyingTowardsAnExclusionZone()
    {
        vehicle::Vehicle *v = airborne();
        QVERIFY(v);
        const QGeoCoordinate here = v->position();
        // 400 m north, 60 m across, up to 100 m AMSL (the vehicle flies at 42 m AMSL)...
        Zone tower = circle(QStringLiteral("tower"), here.atDistanceAndAzimuth(400, 0), 60);
        tower.ceiling = airspace::HeightLimit{100, terrain::HeightReference::Amsl};
        // ...and nearer, a zone from 200 m AMSL up that it passes beneath.
        Zone high = circle(QStringLiteral("high"), here.atDistanceAndAzimuth(200, 0), 80);
        high.floor = airspace::HeightLimit{200, terrain::HeightReference::Amsl};
        ZoneAlertMonitor monitor(m_fleet.get(), nullptr, 0);
        monitor.setZones(std::make_shared<const airspace::ZoneSet>(std::vector<Zone>{tower, high}));
        monitor.check();
        QCOMPARE(monitor.count(), 0); // hovering, outside both

        QSignalSpy raised(&monitor, &ZoneAlertMonitor::alertRaised);
        const QGeoCoordinate beyond = here.atDistanceAndAzimuth(900, 0);
        m_fleet->goTo(0, beyond.latitude(), beyond.longitude());
        QVERIFY(QTest::qWaitFor([&] { monitor.check(); return monitor.count() > 0; }, 60000));
        const ZoneAlertMonitor::Alert alert = monitor.alerts().front();
        QCOMPARE(monitor.count(), 1);
        QCOMPARE(alert.zone, QStringLiteral("tower"));
        QCOMPARE(alert.kind, ZoneAlertMonitor::Kind::EntersExclusion);
        QVERIFY2(alert.inSeconds > 5 && alert.inSeconds <= ZoneAlertMonitor::kHorizonSeconds, qPrintable(QString::number(alert.inSeconds)));
        QVERIFY(alert.text.startsWith(v->name() + QStringLiteral(" enters 'tower' in ")));
        QVERIFY(!alert.heightUnknown);
        QCOMPARE(raised.count(), 1);
        const vehicle::CommandLog &log = *m_fleet->commandLog();
        QCOMPARE(alertLines(log), 1);
        QCOMPARE(log.at(log.count() - 1).command, alert.text);

        // Through the zone and out: the one alert stays (inside, it says so) and then goes.
        QSignalSpy cleared(&monitor, &ZoneAlertMonitor::alertCleared);
        bool sawInside = false;
        QVERIFY(QTest::qWaitFor([&] {
            monitor.check();
            sawInside = sawInside || (monitor.count() == 1 && monitor.alerts().front().inSeconds == 0);
            return cleared.count() > 0;
        }, 60000));
        QVERIFY(sawInside);
        QCOMPARE(raised.count(), 1);
        QCOMPARE(alertLines(log), 1);
        QCOMPARE(monitor.count(), 0);
    }

    // A UAS geographical zone counts by the clock: a zone forbidden on weekend evenings around the
    // hovering vehicle raises nothing on a Monday and "is inside" on a Saturday evening; a zone with
    // no restriction around it never does.
    void aGeographicalZoneCountsByTheClock()
    {
        vehicle::Vehicle *v = airborne();
        QVERIFY(v);
        const QGeoCoordinate here = v->position();
        auto weekend = std::make_shared<airspace::ed::GeoZone>();
        weekend->identifier = QStringLiteral("LVP100");
        weekend->restriction = airspace::ed::Restriction::Prohibited;
        airspace::ed::TimePeriod evenings;
        evenings.schedule.push_back({0x60, 18 * 3600, 23 * 3600, false});
        weekend->applicability.push_back(evenings);
        Zone inWeekend = circle(QStringLiteral("Weekend evenings"), here, 150);
        inWeekend.geoZone = weekend;
        inWeekend.volume = 1;
        auto free = std::make_shared<airspace::ed::GeoZone>();
        free->identifier = QStringLiteral("LVN400");
        free->restriction = airspace::ed::Restriction::NoRestriction;
        Zone model = circle(QStringLiteral("Model field"), here, 200);
        model.geoZone = free;
        model.volume = 1;
        ZoneAlertMonitor monitor(m_fleet.get(), nullptr, 0);
        monitor.setZones(std::make_shared<const airspace::ZoneSet>(std::vector<Zone>{inWeekend, model}));
        QDateTime now = QDateTime::fromString(QStringLiteral("2026-06-08T18:30:00Z"), Qt::ISODate);  // a Monday
        monitor.setClock([&] { return now; });
        monitor.check();
        QCOMPARE(monitor.count(), 0);
        now = QDateTime::fromString(QStringLiteral("2026-06-06T18:30:00Z"), Qt::ISODate);  // a Saturday
        monitor.check();
        QCOMPARE(monitor.count(), 1);
        QCOMPARE(monitor.alerts().front().zone, QStringLiteral("Weekend evenings"));
        QVERIFY2(monitor.alerts().front().text.contains(QStringLiteral(" is inside 'Weekend evenings'")), qPrintable(monitor.alerts().front().text));
    }

    void leavingItsOwnFence()
    {
        vehicle::Vehicle *v = airborne();
        QVERIFY(v);
        const QGeoCoordinate here = v->position();
        Zone fence = circle(QStringLiteral("route fence circle 1"), here, 250);
        fence.kind = airspace::ZoneKind::Inclusion;
        ZoneAlertMonitor monitor(m_fleet.get(), nullptr, 0);
        monitor.setZones(std::make_shared<const airspace::ZoneSet>()); // no airspace: only its fence
        monitor.setVehicleZones(v->id(), {fence});
        monitor.check();
        QCOMPARE(monitor.count(), 0);

        const QGeoCoordinate out = here.atDistanceAndAzimuth(700, 90);
        m_fleet->goTo(0, out.latitude(), out.longitude());
        QVERIFY(QTest::qWaitFor([&] { monitor.check(); return monitor.count() > 0; }, 60000));
        const ZoneAlertMonitor::Alert alert = monitor.alerts().front();
        QCOMPARE(alert.kind, ZoneAlertMonitor::Kind::LeavesInclusion);
        QCOMPARE(alert.zone, fence.name);
        QVERIFY(alert.inSeconds > 0 && alert.inSeconds <= ZoneAlertMonitor::kHorizonSeconds);
        QVERIFY2(alert.text.contains(QStringLiteral(" leaves 'route fence circle 1' in ")), qPrintable(alert.text));
        QCOMPARE(alertLines(*m_fleet->commandLog()), 1);
        // Outside now and flying on: still the one alert, still one line.
        QVERIFY(QTest::qWaitFor([&] { monitor.check(); return monitor.count() == 1 && monitor.alerts().front().inSeconds == 0; }, 60000));
        QVERIFY(monitor.alerts().front().text.contains(QStringLiteral(" is outside 'route fence circle 1'")));
        QCOMPARE(alertLines(*m_fleet->commandLog()), 1);
    }
};

QTEST_GUILESS_MAIN(TestZoneAlertMonitor)
#include "tst_zonealertmonitor.moc"
