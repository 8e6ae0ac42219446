// Terrain from the simulated UgCS server over loopback (GetElevationProfile, GetRasterValues) against
// the same SRTM tiles read locally: the same ground, the same no-data stretches, the same rules.
// Route processing over that ground: AGL waypoints fly ground + AGL, a leg into a hill is refused.
#include "ElevationService.h"
#include "HciClient.h"
#include "HciElevationSource.h"
#include "HciReply.h"
#include "HciServer.h"
#include "HciSession.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "Messages.pb.h"
#include "SimRouteProcessor.h"
#include "SimTerrain.h"
#include "SimWorld.h"
#include "TerrainProfile.h"
#include "TerrainRule.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace sortie;
using namespace sortie::terrain;
namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;

// 20 m plain with a 200 m hill around (56.95 N, 24.50 E) and a void block around (56.95 N, 24.60 E).
int post(int r, int c)
{
    const double lat = 57.0 - r / 1200.0, lon = 24.0 + c / 1200.0;
    if (std::abs(lat - 56.95) < 0.004 && std::abs(lon - 24.60) < 0.006)
        return -32768;
    const double dy = (lat - 56.95) * 111320, dx = (lon - 24.50) * 60700;
    return int(20 + 200 * std::exp(-(dx * dx + dy * dy) / (2 * 400.0 * 400.0)));
}

ProfileRoute acrossHillAndHole()
{
    ProfileRoute r;
    r.waypoints.push_back({{56.95, 24.45}, 150, HeightReference::Amsl, 0, QStringLiteral("Waypoint 1")});
    r.waypoints.push_back({{56.95, 24.55}, 150, HeightReference::Amsl, 1, QStringLiteral("Waypoint 2")});
    r.waypoints.push_back({{56.95, 24.65}, 60, HeightReference::AboveTerrain, 2, QStringLiteral("Waypoint 3")});
    return r;
}

pb::SegmentDefinition waypoint(double lat, double lon, double altitude, bool agl)
{
    pb::SegmentDefinition s;
    s.set_algorithmclassname(sim::SimRouteProcessor::kWaypointAlgorithm);
    s.mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(lat * kRad);
    p->set_longitude(lon * kRad);
    if (agl) {
        p->set_aglaltitude(altitude);
        p->set_altitudetype(pb::AT_AGL);
    } else {
        p->set_wgs84altitude(altitude);
        p->set_altitudetype(pb::AT_WGS84);
    }
    return s;
}

pb::SegmentDefinition takeoffOrLanding(double lat, double lon, bool takeoff)
{
    // As the UgCS SDK builds them: one figure point at 0 m above the ground.
    pb::SegmentDefinition s;
    s.set_algorithmclassname(takeoff ? "com.ugcs.ucs.service.routing.impl.TakeOffAlgorithm"
                                     : "com.ugcs.ucs.service.routing.impl.LandingAlgorithm");
    s.mutable_figure()->set_type(takeoff ? pb::FT_TAKEOFF_POINT : pb::FT_LANDING_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(lat * kRad);
    p->set_longitude(lon * kRad);
    p->set_aglaltitude(0);
    p->set_altitudetype(pb::AT_AGL);
    return s;
}

QString messagesOf(const pb::ProcessedRoute &route)
{
    QStringList all;
    for (const auto &s : route.segments())
        for (const auto &m : s.messageset().messages())
            if (m.severity() == pb::MS_ERROR)
                all << QString::fromStdString(m.defaulttext());
    return all.join(u'\n');
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
} // namespace

class TstTerrainServer : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<sim::SimWorld> m_world;
    std::unique_ptr<sim::HciServer> m_server;
    std::unique_ptr<hci::HciSession> m_session;

private slots:
    void initTestCase()
    {
        QVERIFY(test::writeHgt(m_dir.filePath("N56E024.hgt"), 1201, post));
        sim::SimWorld::Config config;
        config.telemetryRateHz = 5;
        config.demPath = m_dir.path();
        m_world = std::make_unique<sim::SimWorld>(config);
        m_server = std::make_unique<sim::HciServer>(*m_world);
        QVERIFY2(m_server->listen(QHostAddress::LocalHost, 0), qPrintable(m_server->errorString()));
        m_session = std::make_unique<hci::HciSession>();
        QSignalSpy ready(m_session.get(), &hci::HciSession::ready);
        m_session->open(QStringLiteral("127.0.0.1"), m_server->port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
    }

    void cleanupTestCase()
    {
        m_session.reset();
        m_server.reset();
        m_world.reset();
    }

    // The profile from the server equals the profile from the tiles, sample for sample.
    void profileMatchesLocalTiles()
    {
        HciElevationSource server(m_session.get());
        HgtTileSource tiles(m_dir.path());
        ElevationService remote, local;
        remote.setSources({&server});
        local.setSources({&tiles});
        const ProfileRoute route = acrossHillAndHole();

        TerrainProfile first = computeProfile(route, remote, 30);
        QVERIFY(first.pending);  // asked, not blocked
        QSignalSpy changed(&remote, &ElevationService::changed);
        QVERIFY(changed.wait(10000));
        QCOMPARE(server.requestsSent(), 1);
        const TerrainProfile fromServer = computeProfile(route, remote, 30);
        QVERIFY(!fromServer.pending);
        QCOMPARE(server.requestsSent(), 1);  // cached for the session
        const TerrainProfile fromTiles = computeProfile(route, local, 30);

        QCOMPARE(fromServer.size(), fromTiles.size());
        int withData = 0, without = 0;
        for (size_t i = 0; i < fromTiles.size(); ++i) {
            QCOMPARE(fromServer.ground[i].status, fromTiles.ground[i].status);
            if (fromTiles.ground[i].hasValue()) {
                ++withData;
                QVERIFY2(std::abs(fromServer.ground[i].ground - fromTiles.ground[i].ground) < 1e-6,
                         qPrintable(QStringLiteral("%1: %2 vs %3").arg(i).arg(fromServer.ground[i].ground, 0, 'f', 9).arg(fromTiles.ground[i].ground, 0, 'f', 9)));
            } else {
                ++without;
            }
        }
        QVERIFY(withData > 100);
        QVERIFY(without > 5);
        QCOMPARE(fromServer.noData, fromTiles.noData);
        QCOMPARE(fromServer.lowStretches.size(), fromTiles.lowStretches.size());
        QCOMPARE(fromServer.minClearance->clearance, fromTiles.minClearance->clearance);
        QVERIFY(fromTiles.minClearance->clearance < 0);  // into the hill

        // The same rules fire on the same legs; only the source named differs.
        const auto a = terrainIssues(route, fromServer), b = terrainIssues(route, fromTiles);
        QCOMPARE(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i) {
            QCOMPARE(a[i].rule, b[i].rule);
            QCOMPARE(a[i].segment, b[i].segment);
        }
        QVERIFY(std::any_of(a.begin(), a.end(), [](const auto &i) { return i.rule == QLatin1String("terrain-clearance") && i.segment == 0; }));
        QVERIFY(std::any_of(a.begin(), a.end(), [](const auto &i) {
            return i.rule == QLatin1String("terrain-no-data") && i.segment == 1 && i.message.contains(QLatin1String("tried: UgCS server"));
        }));
    }

    // Single points go out in one GetRasterValues per event-loop turn.
    void pointsAreBatched()
    {
        HciElevationSource server(m_session.get());
        HgtTileSource tiles(m_dir.path());
        const std::vector<GeoPoint> points{{56.95, 24.50}, {56.95, 24.60}, {56.90, 24.30}, {56.951, 24.501}};
        for (const GeoPoint &p : points)
            QCOMPARE(server.sample(p).status, SampleStatus::Pending);
        QSignalSpy changed(&server, &ElevationSource::dataChanged);
        QVERIFY(changed.wait(10000));
        QCOMPARE(server.requestsSent(), 1);
        for (const GeoPoint &p : points) {
            const ElevationSample s = server.sample(p), t = tiles.sample(p);
            QCOMPARE(s.status, t.status);
            if (t.hasValue())
                QVERIFY(std::abs(s.ground - t.ground) < 1e-3);  // float on the wire
        }
        QCOMPARE(server.sample({56.95, 24.60}).status, SampleStatus::NoData);
    }

    void badRequestsAreRefused()
    {
        pb::GetElevationProfileRequest request;
        request.set_samplingstep(0);
        auto *l = request.add_locations();
        l->set_latitude(0.99);
        l->set_longitude(0.43);
        l->set_altitude(0);
        l->set_altitudetype(pb::AT_WGS84);
        const auto [response, error] = call<pb::GetElevationProfileResponse>(m_session->send(request));
        QVERIFY(error.contains(QStringLiteral("samplingStep")));
    }

    // ProcessRoute: an AGL waypoint flies the ground under it + AGL; a leg into the hill is refused.
    void processRouteOverTerrain()
    {
        hci::HciClient client(m_session.get());
        pb::Route route;
        route.set_name("terrain");
        *route.add_segments() = waypoint(56.95, 24.45, 50, true);
        *route.add_segments() = waypoint(56.95, 24.55, 50, true);  // the leg between crosses the 220 m hill at ~70 m AMSL
        *route.add_segments() = waypoint(56.95, 24.56, 300, false);
        const auto [response, error] = call<pb::ProcessRouteResponse>(client.processRoute(route));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto &processed = response.processedroute();
        QCOMPARE(processed.segments_size(), 3);
        HgtTileSource tiles(m_dir.path());
        const double ground0 = tiles.sample({56.95, 24.45}).ground;
        bool found = false;
        for (const auto &a : processed.segments(0).segmentactions()) {
            if (!a.has_waypoint())
                continue;
            found = true;
            QVERIFY(std::abs(a.waypoint().elevation() - ground0) < 1e-6);
            QVERIFY(std::abs(a.waypoint().wgs84altitude() - (ground0 + 50)) < 1e-6);
        }
        QVERIFY(found);
        const auto &second = processed.segments(1);
        QCOMPARE(second.status(), pb::RPS_INVALID);
        const QString message = QString::fromStdString(second.messageset().messages(0).defaulttext());
        QVERIFY2(message.contains(QStringLiteral("The leg from waypoint 1 to waypoint 2 passes")) && message.contains(QStringLiteral("below the ground")),
                 qPrintable(message));
        QCOMPARE(processed.segments(2).status(), pb::RPS_PROCESSED);  // 300 m AMSL clears everything
    }

    // An area scan flown AGL over the hill follows it: waypoints are added where the ground departs
    // more than the tolerance, every leg keeps its height above the ground within it, and nothing is
    // refused; the same scan without terrain following (AMSL) would fly through the hill.
    void processRouteFollowsTerrainInAScan()
    {
        hci::HciClient client(m_session.get());
        pb::Route route;
        route.set_name("scan over the hill");
        pb::SegmentDefinition scan;
        scan.set_algorithmclassname("com.ugcs.ucs.service.routing.impl.AreaScanAlgorithm");
        scan.mutable_figure()->set_type(pb::FT_POLYGON);
        for (const auto &[lat, lon] : std::vector<std::pair<double, double>>{
                 {56.947, 24.49}, {56.947, 24.51}, {56.953, 24.51}, {56.953, 24.49}, {56.947, 24.49}}) {
            auto *p = scan.mutable_figure()->add_points();
            p->set_latitude(lat * kRad);
            p->set_longitude(lon * kRad);
            p->set_altitudetype(pb::AT_AGL);
        }
        const auto set = [&scan](const char *name, const char *value) {
            auto *v = scan.add_parametervalues();
            v->set_name(name);
            v->set_value(value);
        };
        set("height", "60");
        set("altitudeType", "AGL");
        set("sideDistance", "200");
        set("directionAngle", "90");
        set("tolerance", "5");
        *route.add_segments() = scan;
        const auto [response, error] = call<pb::ProcessRouteResponse>(client.processRoute(route));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto &segment = response.processedroute().segments(0);
        QVERIFY2(segment.status() == pb::RPS_PROCESSED,
                 qPrintable(segment.messageset().messages_size() ? QString::fromStdString(segment.messageset().messages(0).defaulttext()) : QString()));
        std::vector<pb::Waypoint> points;
        int added = 0;
        for (const auto &a : segment.segmentactions())
            if (a.has_waypoint()) {
                points.push_back(a.waypoint());
                added += a.origin() == pb::OO_SYSTEM ? 1 : 0;
            }
        QVERIFY2(added > 4, qPrintable(QString::number(added)));
        // Between consecutive waypoints, probed every 5 m: 60 m above the tiles' ground within 5 m.
        HgtTileSource tiles(m_dir.path());
        double lowest = INFINITY, highest = -INFINITY;
        for (size_t i = 1; i < points.size(); ++i) {
            const pb::Waypoint &a = points[i - 1], &b = points[i];
            const SampledPath path = samplePath({{a.latitude() / kRad, a.longitude() / kRad}, {b.latitude() / kRad, b.longitude() / kRad}}, 5);
            for (const PathSamplePoint &p : path.points) {
                const double f = path.length() > 0 ? p.distance / path.length() : 0.0;
                const double agl = a.wgs84altitude() + f * (b.wgs84altitude() - a.wgs84altitude()) - tiles.sample(p.position).ground;
                lowest = std::min(lowest, agl);
                highest = std::max(highest, agl);
            }
        }
        QVERIFY2(lowest > 60 - 5 - 1 && highest < 60 + 5 + 1, qPrintable(QStringLiteral("%1..%2").arg(lowest).arg(highest)));

        // Flown AMSL at 120 m, the scan does not follow: the hill (220 m) refuses it.
        for (auto &v : *scan.mutable_parametervalues())
            if (v.name() == "altitudeType")
                v.set_value("AMSL");
            else if (v.name() == "height")
                v.set_value("120");
        *route.mutable_segments(0) = scan;
        const auto [amsl, amslError] = call<pb::ProcessRouteResponse>(client.processRoute(route));
        QVERIFY2(amslError.isEmpty(), qPrintable(amslError));
        QCOMPARE(amsl.processedroute().segments(0).status(), pb::RPS_INVALID);
    }

    // Issue 21: a route that starts with a Take-off segment at 0 m AGL was refused ("The leg from
    // waypoint 1 to waypoint 2 passes 0.0 m above the ground 0.0 m along it"): the first leg was
    // judged as a slant line from the ground. The vehicle climbs straight up to the next waypoint's
    // height and lands straight down; those vertical moves are not judged, the legs across are.
    void takeoffAndLandingAreVertical()
    {
        hci::HciClient client(m_session.get());
        pb::Route route;
        route.set_name("take-off, waypoint, landing on the plain");
        *route.add_segments() = takeoffOrLanding(56.95, 24.45, true);
        *route.add_segments() = waypoint(56.95, 24.46, 50, true);
        *route.add_segments() = takeoffOrLanding(56.95, 24.47, false);
        const auto [response, error] = call<pb::ProcessRouteResponse>(client.processRoute(route));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const pb::ProcessedRoute &processed = response.processedroute();
        for (int i = 0; i < processed.segments_size(); ++i)
            QVERIFY2(processed.segments(i).status() == pb::RPS_PROCESSED, qPrintable(messagesOf(processed)));
        HgtTileSource tiles(m_dir.path());
        const double ground0 = tiles.sample({56.95, 24.45}).ground, ground2 = tiles.sample({56.95, 24.47}).ground;
        // The take-off goes up to 50 m over its own ground (the next waypoint's height); the landing is on the ground.
        const pb::Action *takeoff = nullptr, *landing = nullptr;
        for (const auto &a : processed.segments(0).segmentactions())
            takeoff = a.has_takeoff() ? &a : takeoff;
        for (const auto &a : processed.segments(2).segmentactions())
            landing = a.has_landing() ? &a : landing;
        QVERIFY(takeoff && landing);
        QCOMPARE(takeoff->takeoff().elevation(), ground0);
        QCOMPARE(takeoff->takeoff().wgs84altitude(), ground0 + 50);
        QCOMPARE(landing->landing().wgs84altitude(), ground2);
        // What the vehicle flies: straight up, across, over the landing point at the height it left, down.
        QString planError;
        const auto plan = sim::SimRouteProcessor::flightPlan(processed, ground0, &planError);
        QVERIFY2(planError.isEmpty(), qPrintable(planError));
        QCOMPARE(plan.size(), size_t(3));
        QCOMPARE(plan[0].altitudeAgl, 50.0);
        QVERIFY(std::abs(plan[2].altitudeAgl - (ground2 + 50 - ground0)) < 1e-9);
        QVERIFY(plan[2].landHere);

        // A leg across that passes too close is still refused, after a take-off and before a landing.
        pb::Route hill;
        hill.set_name("take-off, then across the hill");
        *hill.add_segments() = takeoffOrLanding(56.95, 24.45, true);
        *hill.add_segments() = waypoint(56.95, 24.55, 50, true);  // 50 m over the take-off: ~70 m AMSL, the hill is 220 m
        const auto [across, acrossError] = call<pb::ProcessRouteResponse>(client.processRoute(hill));
        QVERIFY2(acrossError.isEmpty(), qPrintable(acrossError));
        QCOMPARE(across.processedroute().segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(across.processedroute().segments(1).status(), pb::RPS_INVALID);
        QVERIFY2(messagesOf(across.processedroute()).contains(QStringLiteral("The leg from waypoint 1 to waypoint 2 passes")),
                 qPrintable(messagesOf(across.processedroute())));
        pb::Route down;
        down.set_name("across the hill to a landing");
        *down.add_segments() = waypoint(56.95, 24.45, 50, true);
        *down.add_segments() = takeoffOrLanding(56.95, 24.55, false);  // flown at ~70 m AMSL until over it
        const auto [landed, landedError] = call<pb::ProcessRouteResponse>(client.processRoute(down));
        QVERIFY2(landedError.isEmpty(), qPrintable(landedError));
        QCOMPARE(landed.processedroute().segments(1).status(), pb::RPS_INVALID);
        QVERIFY2(messagesOf(landed.processedroute()).contains(QStringLiteral("below the ground")), qPrintable(messagesOf(landed.processedroute())));
    }
};

QTEST_GUILESS_MAIN(TstTerrainServer)
#include "tst_terrainserver.moc"
