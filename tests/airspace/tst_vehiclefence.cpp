// The fence on a VCI vehicle, end to end against sortie-sim's VCI vehicle over TCP: MissionUploader
// sends the route's own fence and the airspace zones near it (limits converted, far and inactive
// zones left out), the vehicle holds exactly that, and flying into an exclusion zone or out of an
// inclusion fence makes it land, return or hold, with the breach in its telemetry and one alert
// line in the command log. The fence is made where the zones are (airspace::vciFenceFor), handed to
// the link as the client graph hands it; a link without it refuses a route that asks for a fence.
#include "AirspaceCheck.h"
#include "CommandLog.h"
#include "MissionUploader.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciVehicleLink.h"
#include "VciFenceBuilder.h"
#include "Vehicle.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using airspace::Zone;
using airspace::ZoneKind;
using client::MissionUploader;
using vehicle::CommandLog;
using vehicle::TelemetryField;
namespace profile = vci::profile;

namespace {

constexpr double kHomeLat = 56.9496, kHomeLon = 24.1052; // the sim's home
constexpr int kFlightMs = 30000;

mission::Waypoint waypoint(double north, double east, double altitude)
{
    mission::Waypoint w;
    w.position = {kHomeLat + north, kHomeLon + east};
    w.altitude = altitude;
    w.speed = 8;
    return w;
}

mission::Route routeOf(std::vector<mission::Waypoint> points)
{
    mission::Route r;
    r.settings.name = QStringLiteral("fence test");
    for (auto &p : points)
        r.segments.push_back(std::move(p));
    return r;
}

// A square of ±`dLat` by ±`dLon` degrees around a point north of home.
std::vector<mission::GeoPoint> square(double north, double dLat, double dLon)
{
    const double lat = kHomeLat + north;
    return {{lat - dLat, kHomeLon - dLon}, {lat - dLat, kHomeLon + dLon}, {lat + dLat, kHomeLon + dLon}, {lat + dLat, kHomeLon - dLon}};
}

Zone circleZone(const QString &name, double north, double radius, ZoneKind kind = ZoneKind::Exclusion)
{
    Zone z;
    z.name = name;
    z.kind = kind;
    z.shape = airspace::ZoneCircle{{kHomeLat + north, kHomeLon}, radius};
    return z;
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;

} // namespace

class TestVehicleFence : public QObject
{
    Q_OBJECT

    std::unique_ptr<sim::SimVciVehicle> m_sim;
    std::unique_ptr<sim::SimVciListener> m_listener;
    std::unique_ptr<vehicle::VciVehicleLink> m_link;
    std::unique_ptr<vehicle::Vehicle> m_vehicle;
    std::unique_ptr<CommandLog> m_log;
    std::unique_ptr<MissionUploader> m_uploader;

    bool upload(const mission::Route &route)
    {
        QSignalSpy finished(m_uploader.get(), &MissionUploader::finished);
        if (!m_uploader->start(route, m_vehicle.get()))
            return false;
        if (!finished.wait(20000))
            return false;
        return finished.front().front().toBool();
    }

    int alerts() const
    {
        int n = 0;
        for (int i = 0; i < m_log->count(); ++i)
            n += m_log->at(i).status == CommandLog::Status::Alert;
        return n;
    }

    QString lastAlert() const
    {
        for (int i = m_log->count() - 1; i >= 0; --i)
            if (m_log->at(i).status == CommandLog::Status::Alert)
                return m_log->at(i).command;
        return {};
    }

    void flyMission()
    {
        QSignalSpy armed(m_vehicle.get(), &vehicle::Vehicle::commandFinished);
        m_vehicle->arm();
        QTRY_COMPARE_WITH_TIMEOUT(armed.count(), 1, 5000);
        QVERIFY(armed.front().at(1).toBool());
        m_vehicle->setMode(QStringLiteral("auto"));
        QTRY_COMPARE_WITH_TIMEOUT(armed.count(), 2, 5000);
        QVERIFY2(armed.at(1).at(1).toBool(), qPrintable(armed.at(1).at(2).toString()));
    }

private slots:
    void init()
    {
        sim::SimVciOptions options;
        options.id = QStringLiteral("vci-fence");
        options.name = QStringLiteral("Fenced");
        options.telemetryRate = 25;
        options.timeScale = 8;
        m_sim = std::make_unique<sim::SimVciVehicle>(options);
        m_listener = std::make_unique<sim::SimVciListener>(m_sim.get());
        QVERIFY(m_listener->listen(0));
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()), &error);
        QVERIFY2(endpoint, qPrintable(error));
        m_link = std::make_unique<vehicle::VciVehicleLink>(*endpoint);
        m_link->setFenceBuilder(airspace::vciFenceFor);
        m_vehicle = std::make_unique<vehicle::Vehicle>(m_link.get());
        m_vehicle->setNotifyInterval(20);
        m_log = std::make_unique<CommandLog>();
        m_vehicle->setCommandLog(m_log.get());
        m_uploader = std::make_unique<MissionUploader>();
        m_uploader->setCommandLog(m_log.get());
        m_link->start();
        QTRY_VERIFY(m_vehicle->isConnected());
        QTRY_COMPARE(m_vehicle->name(), QStringLiteral("Fenced"));
        QTRY_VERIFY(!m_vehicle->isStale(TelemetryField::FenceBreach)); // /fence/status is subscribed
        QCOMPARE(m_vehicle->value(TelemetryField::FenceBreach), 0.0);
    }

    void cleanup()
    {
        m_uploader.reset();
        m_vehicle.reset();
        m_link.reset();
        m_log.reset();
        m_listener.reset();
        m_sim.reset();
    }

    void uploadCarriesRouteFenceAndNearbyZones()
    {
        mission::Route route = routeOf({waypoint(0.0001, 0, 30), waypoint(0.0010, 0, 30)});
        route.fence.polygons.push_back({square(0.0005, 0.0015, 0.0015), true});
        route.fence.circles.push_back({{kHomeLat + 0.0008, kHomeLon + 0.0008}, 20, false});

        Zone amsl = circleZone(QStringLiteral("mast"), 0.0004, 25);
        amsl.floor = airspace::HeightLimit{100, terrain::HeightReference::Amsl};
        amsl.ceiling = airspace::HeightLimit{300, terrain::HeightReference::Amsl};
        Zone aboveHome = circleZone(QStringLiteral("crane"), 0.0006, 15);
        aboveHome.ceiling = airspace::HeightLimit{60, terrain::HeightReference::AboveHome};
        Zone agl = circleZone(QStringLiteral("hospital"), 0.0009, 40);
        agl.ceiling = airspace::HeightLimit{50, terrain::HeightReference::AboveTerrain};
        Zone far = circleZone(QStringLiteral("far away"), 1.0, 500);  // 111 km north: not near the route
        Zone off = circleZone(QStringLiteral("inactive"), 0.0005, 30);
        off.active = false;
        auto zones = std::make_shared<const airspace::FenceZoneSet>(std::vector<Zone>{amsl, aboveHome, agl, far, off});
        m_uploader->setFenceSettings({zones, vehicle::FenceBreachAction::Land});

        QVERIFY2(upload(route), qPrintable(m_uploader->message()));
        // What the vehicle holds (the uploader read it back too): the route's two, then the three near zones.
        const profile::Fence &held = m_sim->fence().fence();
        QCOMPARE(held.breachAction, profile::BreachAction::Land);
        QCOMPARE(int(held.items.size()), 5);
        QCOMPARE(held.items[0].name, std::string("route fence polygon 1"));
        QCOMPARE(held.items[0].kind, profile::FenceKind::Inclusion);
        QCOMPARE(int(held.items[0].polygon.size()), 4);
        QVERIFY(std::abs(held.items[0].polygon[0].latitude - (kHomeLat + 0.0005 - 0.0015) * kDeg) < 1e-12);
        QCOMPARE(held.items[1].name, std::string("route fence circle 1"));
        QCOMPARE(held.items[1].kind, profile::FenceKind::Exclusion);
        QCOMPARE(held.items[1].radius, 20.0);
        QVERIFY(!held.items[1].floor && !held.items[1].ceiling); // a .plan fence is the whole column
        QCOMPARE(held.items[2].name, std::string("mast"));
        QCOMPARE(held.items[2].floor, (profile::FenceLimit{100, profile::FenceReference::Amsl}));
        QCOMPARE(held.items[2].ceiling, (profile::FenceLimit{300, profile::FenceReference::Amsl}));
        QCOMPARE(held.items[3].name, std::string("crane"));
        QCOMPARE(held.items[3].ceiling, (profile::FenceLimit{60, profile::FenceReference::Home}));
        // No ground source here: the AGL ceiling cannot be placed, so it keeps out of the whole column.
        QCOMPARE(held.items[4].name, std::string("hospital"));
        QVERIFY(!held.items[4].floor && !held.items[4].ceiling);
        const QString message = m_uploader->message();
        QVERIFY2(message.contains(QStringLiteral("fence: 2 of the route's own, 3 airspace zone(s) near it; on a breach the vehicle will land")),
                 qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("zone 'hospital': no ground under it, so its AGL limits were dropped")), qPrintable(message));

        // An inclusion zone whose AGL limits cannot be placed is refused, naming it; the vehicle keeps its fence.
        const uint64_t version = m_sim->fence().version();
        Zone keepIn = circleZone(QStringLiteral("park"), 0.0005, 400, ZoneKind::Inclusion);
        keepIn.ceiling = airspace::HeightLimit{80, terrain::HeightReference::AboveTerrain};
        m_uploader->setFenceSettings({std::make_shared<const airspace::FenceZoneSet>(std::vector<Zone>{keepIn}), vehicle::FenceBreachAction::Return});
        QVERIFY(!upload(route));
        QVERIFY2(m_uploader->message().contains(QStringLiteral("zone 'park': its AGL limits need the ground under it")), qPrintable(m_uploader->message()));
        QCOMPARE(m_sim->fence().version(), version);

        // No fence at all clears the vehicle's.
        m_uploader->setFenceSettings({});
        QVERIFY2(upload(routeOf({waypoint(0.0001, 0, 30), waypoint(0.0003, 0, 30)})), qPrintable(m_uploader->message()));
        QVERIFY(m_sim->fence().fence().empty());
        QTRY_COMPARE(m_sim->fence().status(0).state, std::string("none"));
    }

    void withoutAFenceBuilderOnlyAnUnfencedRouteGoesUp()
    {
        m_link->setFenceBuilder({});
        mission::Route fenced = routeOf({waypoint(0.0001, 0, 30), waypoint(0.0010, 0, 30)});
        fenced.fence.circles.push_back({{kHomeLat + 0.0008, kHomeLon + 0.0008}, 20, false});
        m_uploader->setFenceSettings({});
        QVERIFY(!upload(fenced));
        QVERIFY2(m_uploader->message().contains(QStringLiteral("the fence cannot be made: this link was given no fence builder")),
                 qPrintable(m_uploader->message()));
        // Zones to carry are a fence asked for too, even on a route without one of its own.
        const mission::Route plain = routeOf({waypoint(0.0001, 0, 30), waypoint(0.0003, 0, 30)});
        m_uploader->setFenceSettings({std::make_shared<const airspace::FenceZoneSet>(std::vector<Zone>{circleZone(QStringLiteral("mast"), 0.0002, 25)}),
                                      vehicle::FenceBreachAction::Return});
        QVERIFY(!upload(plain));
        QVERIFY2(m_uploader->message().contains(QStringLiteral("no fence builder")), qPrintable(m_uploader->message()));
        QCOMPARE(m_sim->fence().version(), uint64_t(0)); // nothing was sent
        // Nothing asked for: the route goes up with an empty fence, the breach action as set.
        m_uploader->setFenceSettings({nullptr, vehicle::FenceBreachAction::Hold});
        QVERIFY2(upload(plain), qPrintable(m_uploader->message()));
        QVERIFY(m_sim->fence().fence().empty());
        QCOMPARE(m_sim->fence().fence().breachAction, profile::BreachAction::Hold);
    }

    void exclusionZoneMakesItLand()
    {
        // Straight north through a keep-out circle 111 m away.
        mission::Route route = routeOf({waypoint(0.0001, 0, 25), waypoint(0.0025, 0, 25)});
        route.fence.circles.push_back({{kHomeLat + 0.0010, kHomeLon}, 30, false});
        m_uploader->setFenceSettings({nullptr, vehicle::FenceBreachAction::Land});
        QVERIFY2(upload(route), qPrintable(m_uploader->message()));
        flyMission();
        QTRY_COMPARE_WITH_TIMEOUT(m_vehicle->value(TelemetryField::FenceBreach), 1.0, kFlightMs);
        QVERIFY(m_vehicle->fenceBreached());
        QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("land"));
        QCOMPARE(m_vehicle->value(TelemetryField::FenceBreaches), 1.0);
        // It stopped inside the circle's edge region, well short of the far waypoint, and comes down there.
        const double north = (m_vehicle->position().latitude() - kHomeLat) * 111200.0;
        QVERIFY2(north > 70 && north < 160, qPrintable(QString::number(north)));
        QTRY_VERIFY_WITH_TIMEOUT(!m_vehicle->armed(), kFlightMs); // landed and disarmed
        QCOMPARE(alerts(), 1);
        QCOMPARE(lastAlert(), QStringLiteral("fence breach: entered the exclusion zone 'route fence circle 1'; landing"));
    }

    void leavingTheInclusionFenceReturnsHome()
    {
        // The fence is ±89 m north-south around home; the route goes 222 m north.
        mission::Route route = routeOf({waypoint(0.0001, 0, 25), waypoint(0.0020, 0, 25)});
        route.fence.polygons.push_back({square(0, 0.0008, 0.0012), true});
        QVERIFY2(upload(route), qPrintable(m_uploader->message())); // the breach action: return, the default
        flyMission();
        QTRY_COMPARE_WITH_TIMEOUT(m_vehicle->value(TelemetryField::FenceBreach), 1.0, kFlightMs);
        QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("return_home"));
        QCOMPARE(lastAlert(), QStringLiteral("fence breach: left its fence 'route fence polygon 1'; returning home"));
        // Back inside on the way home: the breach is over, counted once.
        QTRY_COMPARE_WITH_TIMEOUT(m_vehicle->value(TelemetryField::FenceBreach), 0.0, kFlightMs);
        QCOMPARE(m_vehicle->value(TelemetryField::FenceBreaches), 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(!m_vehicle->armed(), kFlightMs);
        QVERIFY(m_vehicle->position().distanceTo(QGeoCoordinate(kHomeLat, kHomeLon)) < 5);
        QCOMPARE(alerts(), 1);
    }

    void exclusionFloorIsThreeDimensionalAndHoldStops()
    {
        // A keep-out box from 40 m above home up, 133 m north: flown under at 25 m, then climbed into.
        mission::Route route = routeOf({waypoint(0.0001, 0, 25), waypoint(0.0022, 0, 25), waypoint(0.0012, 0, 55)});
        airspace::Zone box;
        box.name = QStringLiteral("upper box");
        box.shape = airspace::ZonePolygons{{airspace::ZonePolygon{{square(0.0012, 0.0003, 0.0010)}}}};
        box.floor = airspace::HeightLimit{40, terrain::HeightReference::AboveHome};
        m_uploader->setFenceSettings({std::make_shared<const airspace::FenceZoneSet>(std::vector<Zone>{box}), vehicle::FenceBreachAction::Hold});
        QVERIFY2(upload(route), qPrintable(m_uploader->message()));
        flyMission();
        // Under the floor: the far waypoint is reached without a breach.
        QTRY_VERIFY_WITH_TIMEOUT(m_vehicle->missionCurrent() == 2, kFlightMs);
        QCOMPARE(m_vehicle->value(TelemetryField::FenceBreaches), 0.0);
        QCOMPARE(alerts(), 0);
        // While it flies the mission, the fence is not replaced (as the mission is not).
        std::optional<vci::VciResult> refused;
        m_link->connection()->put(QStringLiteral("/fence"), profile::encodeFence({}), this, [&](const vci::VciResult &r) { refused = r; });
        QTRY_VERIFY(refused);
        QCOMPARE(refused->statusCode, 400);
        QVERIFY2(refused->message.endsWith(QStringLiteral(": cannot replace the fence while flying the mission; pause first")),
                 qPrintable(refused->message));
        QCOMPARE(int(m_sim->fence().fence().items.size()), 1);
        // Climbing back into it: hold where the breach began.
        QTRY_COMPARE_WITH_TIMEOUT(m_vehicle->value(TelemetryField::FenceBreach), 1.0, kFlightMs);
        QTRY_COMPARE(m_vehicle->mode(), QStringLiteral("hold"));
        QCOMPARE(lastAlert(), QStringLiteral("fence breach: entered the exclusion zone 'upper box'; holding"));
        QVERIFY(m_vehicle->altitudeAgl() > 39);
        QCOMPARE(m_sim->model().state().mode, sim::FlightModel::Mode::Hold);
        QTRY_COMPARE(m_sim->model().state().groundSpeed, 0.0); // hovering where it stopped
        QCOMPARE(alerts(), 1);
    }
};

QTEST_GUILESS_MAIN(TestVehicleFence)
#include "tst_vehiclefence.moc"
