// A route uploaded straight to a VCI vehicle over real ground: a simulated VCI vehicle standing on
// SRTM tiles the test writes, VciVehicleLink over TCP with an ElevationService on the same tiles.
// The profile flies heights above home, so AGL heights are turned into them through the ground
// under each point, and an AGL area scan follows the hill it crosses (points added within its
// tolerance) — checked on the mission the vehicle holds and on the height it flies.
#include "AreaScan.h"
#include "CommandCatcher.h"
#include "ElevationService.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "MissionDifference.h"
#include "VciMissionPlanner.h"
#include "PathSampling.h"
#include "Route.h"
#include "SimTerrain.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace sortie;
using namespace sortie::vehicle;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kPlain = 20.0;      // m AMSL
constexpr double kHill = 60.0;       // m above the plain at its top
constexpr double kHillLat = 56.95, kHillLon = 24.45;
constexpr double kHomeLat = 56.95, kHomeLon = 24.44;  // ~600 m west of the top, on the plain

// The ground the tiles carry: a plain with a round hill (Gaussian, 300 m wide).
double groundAt(double lat, double lon)
{
    const double north = (lat - kHillLat) * 111320.0, east = (lon - kHillLon) * 111320.0 * std::cos(kHillLat * kRad);
    return kPlain + kHill * std::exp(-(north * north + east * east) / (300.0 * 300.0));
}

struct Prepared
{
    bool done = false;
    CommandResult result;
    PreparedMission mission;
};

// An AGL scan across the hill, 60 m above the ground, and a waypoint before it.
mission::Route scanOverTheHill()
{
    mission::Route route;
    route.settings.name = QStringLiteral("over the hill");
    mission::Waypoint start;
    start.position = {kHomeLat, kHomeLon + 0.001};
    start.altitude = 30;
    route.segments.push_back(start);
    mission::AreaScan scan;
    scan.polygon = {{56.9485, 24.442}, {56.9485, 24.458}, {56.9515, 24.458}, {56.9515, 24.442}};
    scan.parameters.altitude = 60;
    scan.parameters.directionDeg = 90;  // passes run east over the hill
    scan.parameters.sideDistanceMeters = 150;
    scan.parameters.toleranceMeters = 4;
    scan.parameters.speed = 8;
    mission::syncDerivedFields(scan.parameters);
    route.segments.push_back(scan);
    return route;
}

// The lowest height above the tiles' ground that flying straight between the mission's points
// (from the first scan point on) keeps, probed every 5 m.
double lowestAboveGround(const std::vector<MissionItem> &items, size_t from, double homeAmsl)
{
    double lowest = 1e9;
    for (size_t i = from; i + 1 < items.size(); ++i) {
        const mission::GeoPoint a{items[i].latitude, items[i].longitude};
        const mission::GeoPoint b{items[i + 1].latitude, items[i + 1].longitude};
        const terrain::SampledPath probes = terrain::samplePath({a, b}, 5.0);
        const double length = probes.length();
        for (const terrain::PathSamplePoint &p : probes.points) {
            const double f = length > 0 ? p.distance / length : 0.0;
            const double altitude = homeAmsl + items[i].altitude + f * (items[i + 1].altitude - items[i].altitude);
            lowest = std::min(lowest, altitude - groundAt(p.position.latitude, p.position.longitude));
        }
    }
    return lowest;
}

} // namespace

class TstVciTerrain : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dem.isValid());
        QVERIFY(terrain::test::writeHgt(m_dem.filePath(QStringLiteral("N56E024.hgt")), 1201, [](int row, int column) {
            return int(std::lround(groundAt(57.0 - row / 1200.0, 24.0 + column / 1200.0)));
        }));
        QString error;
        m_simTerrain = sim::SimTerrain::fromDem(m_dem.path(), &error);
        QVERIFY2(m_simTerrain, qPrintable(error));
        m_tiles = std::make_unique<terrain::HgtTileSource>(m_dem.path());
        QVERIFY(m_tiles->isUsable());
    }

    void init()
    {
        sim::SimVciOptions options;
        options.homeLatitude = kHomeLat;
        options.homeLongitude = kHomeLon;
        options.terrain = m_simTerrain.get();
        options.telemetryRate = 25;
        options.timeScale = 40;
        m_simVehicle = std::make_unique<sim::SimVciVehicle>(options);
        m_listener = std::make_unique<sim::SimVciListener>(m_simVehicle.get());
        QVERIFY(m_listener->listen(0));
        m_elevation = std::make_unique<terrain::ElevationService>();
        m_elevation->setSources({m_tiles.get()});
    }

    void cleanup()
    {
        m_vehicle.reset();
        m_link.reset();
        m_listener.reset();
        m_simVehicle.reset();
        m_elevation.reset();
    }

    // The vehicle's home is on the plain (20 m AMSL): AGL heights go up as ground + AGL − home,
    // and the scan adds points over the hill so that every leg keeps 60 m ± 4 m above the ground.
    // Without the ground the same scan would fly into the hill (checked, so the test can fail).
    void aglScanFollowsTheHillOverVci()
    {
        startLink(m_elevation.get());
        const mission::Route route = scanOverTheHill();
        const Prepared prepared = prepare(route);
        QVERIFY2(prepared.result.ok, qPrintable(prepared.result.message));
        QVERIFY2(prepared.mission.notices.isEmpty(), qPrintable(prepared.mission.notices.join(u'\n')));
        const std::vector<MissionItem> &items = prepared.mission.items;
        const double homeAmsl = groundAt(kHomeLat, kHomeLon);
        // ±0.5 m: the tiles hold whole metres.
        QVERIFY2(std::abs(items.front().altitude - (groundAt(kHomeLat, kHomeLon + 0.001) + 30 - homeAmsl)) < 0.5,
                 qPrintable(QString::number(items.front().altitude)));
        const double lowest = lowestAboveGround(items, 1, homeAmsl);
        QVERIFY2(lowest > 60 - 4 - 1.0, qPrintable(QString::number(lowest)));  // ±1 m: tiles round to whole metres
        double highestPoint = 0;
        for (const MissionItem &item : items)
            highestPoint = std::max(highestPoint, item.altitude);
        QVERIFY2(highestPoint > kHill + 50, qPrintable(QString::number(highestPoint)));  // it climbs over the hill

        // The same scan planned without the ground is flown 60 m above home, into the hill, and says so.
        auto flat = vciMissionFor(route, {nullptr, homeAmsl});
        QVERIFY(flat);
        QVERIFY(lowestAboveGround(flat->items, 1, homeAmsl) < 60 - kHill + 5);
        QCOMPARE(flat->notices.size(), 1);
        QVERIFY(flat->items.size() < items.size());

        // Up, back as sent, and flown: the vehicle's own height above the ground stays near 60 m.
        Result upload;
        m_link->uploadMission(prepared.mission, {}, upload.callback());
        QTRY_VERIFY(upload.done);
        QVERIFY2(upload.result.ok, qPrintable(upload.result.message));
        std::vector<MissionItem> back;
        bool downloaded = false;
        m_link->downloadMission([&](const CommandResult &r, const std::vector<MissionItem> &held) {
            downloaded = r.ok;
            back = held;
        });
        QTRY_VERIFY(downloaded);
        QCOMPARE(missionDifference(items, back), QString());

        Result arm, takeoff, go;
        m_link->arm(true, arm.callback());
        m_link->takeoff(30, takeoff.callback());
        m_link->setMode(FlightMode::Auto, go.callback());
        QTRY_VERIFY(go.done);
        QVERIFY2(arm.result.ok && takeoff.result.ok && go.result.ok, qPrintable(go.result.message));
        QTRY_COMPARE(m_vehicle->missionState(), QStringLiteral("active"));
        double lowestFlown = 1e9;
        int samples = 0;
        connect(m_vehicle.get(), &Vehicle::telemetryChanged, this, [&] {
            if (m_vehicle->value(TelemetryField::MissionReached) >= 2) {  // on the scan
                lowestFlown = std::min(lowestFlown, m_vehicle->altitudeAgl());
                ++samples;
            }
        });
        QTRY_VERIFY_WITH_TIMEOUT(m_vehicle->missionState() == QLatin1String("complete"), 60000);
        QVERIFY(samples > 50);
        qInfo("planned: %zu points (%zu without the ground), lowest %.1f m above the ground; flown: lowest %.1f m", items.size(),
              flat->items.size(), lowest, lowestFlown);
        // Within the tolerance, 2 m more for the model's climb and descent rates on the flanks.
        QVERIFY2(lowestFlown > 60 - 4 - 2, qPrintable(QString::number(lowestFlown)));
    }

    // A source still fetching the ground holds the plan back until it answers.
    void waitsForTheGround()
    {
        SlowSource slow(m_tiles.get());
        m_elevation->setSources({&slow});
        startLink(m_elevation.get());
        Prepared prepared;
        m_link->prepareMission(scanOverTheHill(), [&](const CommandResult &r, const PreparedMission &m) {
            prepared = {true, r, m};
        });
        QTRY_VERIFY(slow.asked > 0);
        // Still waiting for the ground: what the asking queued has run (posted events drained), and
        // only the source's answer completes the plan.
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
        QVERIFY(!prepared.done);
        slow.answer();
        QTRY_VERIFY(prepared.done);
        QVERIFY2(prepared.result.ok, qPrintable(prepared.result.message));
        QVERIFY(prepared.mission.notices.isEmpty());
        QVERIFY(lowestAboveGround(prepared.mission.items, 1, kPlain) > 60 - 4 - 1.0);
    }

    // Without any ground the heights go up above home, and the operator is told which and why.
    void withoutGroundTheNoticeSaysSo()
    {
        terrain::ElevationService none;
        startLink(&none);
        const Prepared prepared = prepare(scanOverTheHill());
        QVERIFY2(prepared.result.ok, qPrintable(prepared.result.message));
        QCOMPARE(prepared.mission.notices.size(), 1);
        QVERIFY2(prepared.mission.notices.front().contains(QLatin1String("no terrain source is set")), qPrintable(prepared.mission.notices.front()));
        QCOMPARE(prepared.mission.items.front().altitude, 30.0);
    }

private:
    using Result = test::CommandCatcher;

    // The tiles behind a source that answers Pending until told to answer.
    class SlowSource : public terrain::ElevationSource
    {
    public:
        explicit SlowSource(terrain::ElevationSource *tiles) : m_tiles(tiles) {}
        QString name() const override { return QStringLiteral("slow server"); }
        terrain::ElevationSample sample(const terrain::GeoPoint &p) override
        {
            ++asked;
            return m_answering ? m_tiles->sample(p) : terrain::ElevationSample::pending();
        }
        void answer()
        {
            m_answering = true;
            emit dataChanged();
        }
        int asked = 0;

    private:
        terrain::ElevationSource *m_tiles;
        bool m_answering = false;
    };

    void startLink(terrain::ElevationService *elevation)
    {
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(m_listener->port()), &error);
        QVERIFY2(endpoint, qPrintable(error));
        m_link = std::make_unique<VciVehicleLink>(*endpoint, elevation);
        m_vehicle = std::make_unique<Vehicle>(m_link.get());
        m_vehicle->setNotifyInterval(20);
        m_link->start();
        QTRY_VERIFY(m_vehicle->isConnected());
    }

    Prepared prepare(const mission::Route &route)
    {
        Prepared prepared;
        m_link->prepareMission(route, [&](const CommandResult &r, const PreparedMission &m) {
            prepared = {true, r, m};
        });
        if (!QTest::qWaitFor([&] { return prepared.done; }, 10000))
            prepared.result = CommandResult::failure(QStringLiteral("no answer in 10 s"));
        return prepared;
    }

    QTemporaryDir m_dem;
    std::unique_ptr<sim::SimTerrain> m_simTerrain;
    std::unique_ptr<terrain::HgtTileSource> m_tiles;
    std::unique_ptr<terrain::ElevationService> m_elevation;
    std::unique_ptr<sim::SimVciVehicle> m_simVehicle;
    std::unique_ptr<sim::SimVciListener> m_listener;
    std::unique_ptr<VciVehicleLink> m_link;
    std::unique_ptr<Vehicle> m_vehicle;
};

QTEST_GUILESS_MAIN(TstVciTerrain)
#include "tst_vciterrain.moc"
