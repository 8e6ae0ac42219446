// Issue 21, end to end: a UgCS-style route (take-off on the ground, waypoints over a hill, landing on
// the ground) over SRTM tiles the test writes. sortie-sim processes it over HCI on 127.0.0.1 and
// accepts it; the terrain profile and the time model show the vertical climb and descent; a
// simulated VCI vehicle standing at the take-off point flies it, climbing straight up before it
// moves and coming straight down at the landing point (what the client records of its telemetry).
#include "CommandCatcher.h"
#include "ElevationService.h"
#include "HciClient.h"
#include "HciReply.h"
#include "HciRouteMapper.h"
#include "HciServer.h"
#include "HciSession.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "Messages.pb.h"
#include "Route.h"
#include "RouteTiming.h"
#include "SimTerrain.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "SimWorld.h"
#include "TerrainProfile.h"
#include "TerrainRule.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QGeoCoordinate>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace sortie;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kPlain = 20.0;  // m AMSL
constexpr double kHill = 60.0;   // m above the plain at its top
constexpr double kHillLat = 56.95, kHillLon = 24.45;
constexpr double kTakeoffLat = 56.95, kTakeoffLon = 24.438;  // ~730 m west of the top
constexpr double kLandLat = 56.9505, kLandLon = 24.462;      // ~730 m east of it
constexpr double kHeight = 40.0;                              // m AGL of the waypoints
constexpr double kClimbRate = 3.0, kDescentRate = 2.0;        // the sim vehicle's defaults

// A plain with a round hill (Gaussian, 300 m wide), rising slightly to the east.
double groundAt(double lat, double lon)
{
    const double north = (lat - kHillLat) * 111320.0, east = (lon - kHillLon) * 111320.0 * std::cos(kHillLat * kRad);
    return kPlain + 0.005 * (east + 1000.0) + kHill * std::exp(-(north * north + east * east) / (300.0 * 300.0));
}

mission::Waypoint point(double lat, double lon, double altitude, mission::WaypointRole role = mission::WaypointRole::Pass)
{
    mission::Waypoint w;
    w.position = {lat, lon};
    w.altitude = altitude;
    w.altitudeType = mission::AltitudeType::Agl;
    w.speed = 8;
    w.role = role;
    return w;
}

// Take-off at 0 m AGL (as the UgCS SDK builds it), three waypoints 40 m AGL over the hill, landing at 0 m.
mission::Route overTheHill()
{
    mission::Route route;
    route.settings.name = QStringLiteral("take-off, over the hill, landing");
    route.settings.initialSpeed = 8;
    route.settings.profile.climbRate = kClimbRate;
    route.settings.profile.descentRate = kDescentRate;
    route.segments.push_back(point(kTakeoffLat, kTakeoffLon, 0, mission::WaypointRole::Takeoff));
    route.segments.push_back(point(56.95, 24.444, kHeight));
    route.segments.push_back(point(56.9505, 24.450, kHeight));
    route.segments.push_back(point(56.9505, 24.456, kHeight));
    route.segments.push_back(point(kLandLat, kLandLon, 0, mission::WaypointRole::Land));
    return route;
}

template<typename T>
std::pair<T, QString> call(hci::HciReply *reply)
{
    reply->setAutoDelete(false);
    if (!reply->isFinished()) {
        QSignalSpy done(reply, &hci::HciReply::finished);
        done.wait(10000);
    }
    std::pair<T, QString> out{reply->response<T>(), reply->isOk() ? QString() : reply->error().message()};
    delete reply;
    return out;
}

double metresBetween(const QGeoCoordinate &a, double lat, double lon)
{
    return a.distanceTo(QGeoCoordinate(lat, lon));
}

} // namespace

class TstTakeoffLanding : public QObject
{
    Q_OBJECT

    using Result = test::CommandCatcher;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dem.isValid());
        QVERIFY(terrain::test::writeHgt(m_dem.filePath(QStringLiteral("N56E024.hgt")), 1201, [](int row, int column) {
            return int(std::lround(groundAt(57.0 - row / 1200.0, 24.0 + column / 1200.0)));
        }));
        m_tiles = std::make_unique<terrain::HgtTileSource>(m_dem.path());
        QVERIFY(m_tiles->isUsable());
        m_elevation.setSources({m_tiles.get()});
    }

    // sortie-sim over HCI accepts the route; its take-off goes up to 40 m over the take-off ground.
    void processedOverHci()
    {
        sim::SimWorld::Config config;
        config.telemetryRateHz = 5;
        config.demPath = m_dem.path();
        sim::SimWorld world(config);
        sim::HciServer server(world);
        QVERIFY2(server.listen(QHostAddress::LocalHost, 0), qPrintable(server.errorString()));
        hci::HciSession session;
        QSignalSpy ready(&session, &hci::HciSession::ready);
        session.open(QStringLiteral("127.0.0.1"), server.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
        hci::HciClient client(&session);
        const pb::Route route = mission::routeToHci(overTheHill());
        QCOMPARE(route.segments(0).algorithmclassname(), std::string("com.ugcs.ucs.service.routing.impl.TakeOffAlgorithm"));
        QCOMPARE(route.segments(4).algorithmclassname(), std::string("com.ugcs.ucs.service.routing.impl.LandingAlgorithm"));
        const auto [response, error] = call<pb::ProcessRouteResponse>(client.processRoute(route));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const pb::ProcessedRoute &processed = response.processedroute();
        QCOMPARE(processed.segments_size(), 5);
        for (const auto &segment : processed.segments()) {
            QStringList messages;
            for (const auto &m : segment.messageset().messages())
                messages << QString::fromStdString(m.defaulttext());
            QVERIFY2(segment.status() == pb::RPS_PROCESSED, qPrintable(messages.join(u'\n')));
        }
        const double takeoffGround = m_tiles->sample({kTakeoffLat, kTakeoffLon}).ground;
        bool found = false;
        for (const auto &a : processed.segments(0).segmentactions())
            if (a.has_takeoff()) {
                found = true;
                QVERIFY(std::abs(a.takeoff().elevation() - takeoffGround) < 1e-6);
                QVERIFY(std::abs(a.takeoff().wgs84altitude() - (takeoffGround + kHeight)) < 1e-6);
            }
        QVERIFY(found);
    }

    // The profile: the first sample is already 40 m up (the climb is a vertical move from the
    // ground), the last still 40 m up (the descent follows); no leg is too close to the ground.
    void profileShowsTheVerticalMoves()
    {
        const mission::Route route = overTheHill();
        const terrain::ProfileRoute pr = terrain::profileRouteOf(route);
        const terrain::TerrainProfile profile = terrain::computeProfile(pr, m_elevation, 10.0);
        const double takeoffGround = m_tiles->sample({kTakeoffLat, kTakeoffLon}).ground;
        const double landGround = m_tiles->sample({kLandLat, kLandLon}).ground;
        QCOMPARE(profile.verticals.size(), size_t(2));
        const terrain::VerticalMove &climb = profile.verticals.front(), &descent = profile.verticals.back();
        QVERIFY(climb.climb);
        QCOMPARE(climb.leg, 0);
        QCOMPARE(climb.distance, 0.0);
        QCOMPARE(climb.fromAmsl, takeoffGround);
        QCOMPARE(climb.toAmsl, takeoffGround + kHeight);
        QVERIFY(!descent.climb);
        QCOMPARE(descent.leg, 3);
        QCOMPARE(descent.distance, profile.path.length());
        QCOMPARE(descent.toAmsl, landGround);
        QCOMPARE(descent.fromAmsl, landGround + kHeight);
        QCOMPARE(profile.altitudeAmsl.front(), takeoffGround + kHeight);
        QCOMPARE(profile.altitudeAmsl.back(), landGround + kHeight);
        QVERIFY2(profile.minClearance && profile.minClearance->clearance > 25,
                 qPrintable(QString::number(profile.minClearance ? profile.minClearance->clearance : NAN)));
        for (const mission::ValidationIssue &issue : terrain::terrainIssues(pr, profile))
            QVERIFY2(issue.rule != QLatin1String("terrain-clearance"), qPrintable(issue.message));
    }

    // The time model: the climb (40 m at 3 m/s) in the first leg, the descent (40 m at 2 m/s) in the last.
    void timeModelCountsThem()
    {
        const mission::Route route = overTheHill();
        const auto timeline = mission::timeRoute(route, mission::timingOf(route.settings));
        QVERIFY(timeline);
        const auto &legs = timeline->legs();
        QCOMPARE(legs.size(), size_t(4));
        QCOMPARE(legs.front().takeoffClimb, kHeight);
        QCOMPARE(legs.front().takeoffSeconds, kHeight / kClimbRate);
        QCOMPARE(legs.front().heightChange, 0.0);  // across at the height it climbed to
        QCOMPARE(legs.back().landingDescent, kHeight);
        QCOMPARE(legs.back().landingSeconds, kHeight / kDescentRate);
        QCOMPARE(legs.back().heightChange, 0.0);
        double across = 0;
        for (const mission::TimedLeg &l : legs)
            across += l.moveSeconds;
        QCOMPARE(timeline->totalSeconds(), across + kHeight / kClimbRate + kHeight / kDescentRate);
        // Half-way up the climb the vehicle is over the take-off point.
        const mission::TimelinePosition half = timeline->positionAt(kHeight / kClimbRate / 2);
        QVERIFY(half.position == (mission::GeoPoint{kTakeoffLat, kTakeoffLon}));
        QCOMPARE(half.altitude, kHeight / 2);
    }

    // A VCI vehicle standing at the take-off point flies the route: straight up to 40 m over the
    // ground there before it moves across, and at the end straight down over the landing point.
    void flownOverVci()
    {
        sim::SimVciOptions options;
        options.homeLatitude = kTakeoffLat;
        options.homeLongitude = kTakeoffLon;
        QString error;
        const std::unique_ptr<sim::SimTerrain> simTerrain = sim::SimTerrain::fromDem(m_dem.path(), &error);
        QVERIFY2(simTerrain, qPrintable(error));
        options.terrain = simTerrain.get();
        options.telemetryRate = 25;
        options.timeScale = 20;
        sim::SimVciVehicle simVehicle(options);
        sim::SimVciListener listener(&simVehicle);
        QVERIFY(listener.listen(0));
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port()), &error);
        QVERIFY2(endpoint, qPrintable(error));
        vehicle::VciVehicleLink link(*endpoint, &m_elevation);
        vehicle::Vehicle vehicle(&link);
        vehicle.setNotifyInterval(20);
        link.start();
        QTRY_VERIFY(vehicle.isConnected());

        bool prepared = false;
        vehicle::CommandResult prepareResult;
        vehicle::PreparedMission mission;
        link.prepareMission(overTheHill(), [&](const vehicle::CommandResult &r, const vehicle::PreparedMission &m) {
            prepared = true;
            prepareResult = r;
            mission = m;
        });
        QTRY_VERIFY(prepared);
        QVERIFY2(prepareResult.ok, qPrintable(prepareResult.message));
        // The take-off point is flown 40 m over its ground, the landing point 40 m over its ground, then "land".
        const double takeoffGround = m_tiles->sample({kTakeoffLat, kTakeoffLon}).ground;
        const double landGround = m_tiles->sample({kLandLat, kLandLon}).ground;
        QCOMPARE(mission.items.size(), size_t(5));
        QVERIFY(std::abs(mission.items.front().altitude - kHeight) < 0.5);
        QVERIFY(std::abs(mission.items.back().altitude - (landGround + kHeight - takeoffGround)) < 0.5);
        QCOMPARE(mission.items.back().actions.back().type, QStringLiteral("land"));
        Result upload, arm, go;
        link.uploadMission(mission, {}, upload.callback());
        QTRY_VERIFY(upload.done);
        QVERIFY2(upload.result.ok, qPrintable(upload.result.message));

        struct Sample
        {
            QGeoCoordinate at;
            double amsl;
        };
        std::vector<Sample> flight;
        connect(&vehicle, &vehicle::Vehicle::telemetryChanged, this, [&] {
            if (vehicle.position().isValid() && std::isfinite(vehicle.altitudeAmsl()))
                flight.push_back({vehicle.position(), vehicle.altitudeAmsl()});
        });
        link.arm(true, arm.callback());
        QTRY_VERIFY(arm.done);
        QVERIFY2(arm.result.ok, qPrintable(arm.result.message));
        link.setMode(vehicle::FlightMode::Auto, go.callback());
        QTRY_VERIFY(go.done);
        QVERIFY2(go.result.ok, qPrintable(go.result.message));
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.missionState() == QLatin1String("complete"), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(!vehicle.armed(), 30000);  // landed and disarmed
        // The disarm is read at once, the samples are notified at most every 20 ms: the last ones
        // (on the ground) may come just after it.
        QTRY_VERIFY2_WITH_TIMEOUT(!flight.empty() && std::abs(flight.back().amsl - landGround) < 1.0,
                                  qPrintable(QString::number(flight.empty() ? qQNaN() : flight.back().amsl)), 5000);

        // Until it is 40 m up (less 1 m), within 3 m of the take-off point; then it moves away.
        size_t i = 0;
        double offDuringClimb = 0;
        for (; i < flight.size() && flight[i].amsl < takeoffGround + kHeight - 1.0; ++i)
            offDuringClimb = std::max(offDuringClimb, metresBetween(flight[i].at, kTakeoffLat, kTakeoffLon));
        QVERIFY2(i > 3 && i < flight.size(), qPrintable(QStringLiteral("%1 of %2 samples").arg(i).arg(flight.size())));
        QVERIFY2(offDuringClimb < 3.0, qPrintable(QString::number(offDuringClimb)));
        double farthest = 0;
        for (const Sample &s : flight)
            farthest = std::max(farthest, metresBetween(s.at, kTakeoffLat, kTakeoffLon));
        QVERIFY(farthest > 1000);
        // From the last sample 40 m up (less 1 m) down to the ground: within 3 m of the landing point.
        size_t j = flight.size();
        double offDuringDescent = 0;
        while (j > 0 && flight[j - 1].amsl < landGround + kHeight - 1.0) {
            --j;
            offDuringDescent = std::max(offDuringDescent, metresBetween(flight[j].at, kLandLat, kLandLon));
        }
        QVERIFY2(j + 3 < flight.size(), qPrintable(QStringLiteral("%1 of %2 samples").arg(j).arg(flight.size())));
        QVERIFY2(offDuringDescent < 3.0, qPrintable(QString::number(offDuringDescent)));
        QVERIFY2(std::abs(flight.back().amsl - landGround) < 1.0, qPrintable(QString::number(flight.back().amsl)));
        qInfo("recorded %zu samples: climbed %.1f m within %.2f m of the take-off point, descended within %.2f m of the landing point",
              flight.size(), kHeight, offDuringClimb, offDuringDescent);
    }

private:
    QTemporaryDir m_dem;
    std::unique_ptr<terrain::HgtTileSource> m_tiles;
    terrain::ElevationService m_elevation;
};

QTEST_GUILESS_MAIN(TstTakeoffLanding)
#include "tst_takeofflanding.moc"
