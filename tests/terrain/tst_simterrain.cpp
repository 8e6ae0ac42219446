// The simulator's ground: the built-in hills near Riga, --dem tiles, and route processing's terrain
// pass (AGL waypoints over the real ground, legs closer than the safe distance refused).
#include "HgtWriter.h"
#include "Messages.pb.h"
#include "SimDemoContent.h"
#include "SimRouteProcessor.h"
#include "SimRouteTerrain.h"
#include "SimTerrain.h"
#include "SimVciVehicle.h"
#include "VciProfile.h"

#include <QTemporaryDir>
#include <QTest>

#include <numbers>

using namespace sortie;
namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;

pb::SegmentDefinition waypoint(double lat, double lon, double agl)
{
    pb::SegmentDefinition s;
    s.set_algorithmclassname(sim::SimRouteProcessor::kWaypointAlgorithm);
    s.mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(lat * kRad);
    p->set_longitude(lon * kRad);
    p->set_aglaltitude(agl);
    p->set_altitudetype(pb::AT_AGL);
    return s;
}
} // namespace

class TstSimTerrain : public QObject
{
    Q_OBJECT

private slots:
    void builtInHills()
    {
        sim::SimTerrain terrain(10.0);
        // Flat under every vehicle's home: the demo starts on level ground.
        for (const auto &home : sim::SimDemoContent::vehicleHomes(6))
            QCOMPARE(terrain.groundAt(home.latitude, home.longitude), std::optional<double>(10.0));
        auto &hills = static_cast<sim::BuiltInTerrain &>(terrain.source()).hills();
        QVERIFY(hills.size() >= 3);
        for (const auto &h : hills) {
            QCOMPARE(*terrain.groundAt(h.latitude, h.longitude), 10.0 + h.height);
            QVERIFY(h.height >= 20 && h.height <= 90);  // tens of metres
        }
        // Deterministic and smooth: the same answer twice, no step between neighbours.
        QCOMPARE(terrain.groundAt(56.99, 24.061), terrain.groundAt(56.99, 24.061));
        QVERIFY(std::abs(*terrain.groundAt(56.99, 24.061) - *terrain.groundAt(56.99, 24.0611)) < 0.5);
        QVERIFY(std::isfinite(*terrain.groundAt(-33.0, 151.0)));  // the built-in world has ground everywhere
    }

    // A simulated VCI vehicle stands on the same ground: at home on a hill top its home is the hill's
    // height above sea level and it is 0 m above the ground; without the world's terrain, flat ground.
    void vciVehicleStandsOnTheGround()
    {
        sim::SimTerrain terrain(10.0);
        const auto &hill = static_cast<sim::BuiltInTerrain &>(terrain.source()).hills().front();
        sim::SimVciOptions options;
        options.homeLatitude = hill.latitude;
        options.homeLongitude = hill.longitude;
        options.terrain = &terrain;
        sim::SimVciVehicle onHill(options);
        const nlohmann::json home = *onHill.resource(std::string(vci::profile::kHome));
        QCOMPARE(home["altitudeAmsl"].get<double>(), 10.0 + hill.height);
        const nlohmann::json position = *onHill.resource(std::string(vci::profile::kPosition));
        QCOMPARE(position["altitudeAmsl"].get<double>(), 10.0 + hill.height);
        QVERIFY(std::abs(position["altitudeAgl"].get<double>()) < 1e-9);

        options.terrain = nullptr;
        sim::SimVciVehicle flat(options);
        QCOMPARE((*flat.resource(std::string(vci::profile::kHome)))["altitudeAmsl"].get<double>(), options.groundElevation);
    }

    void demTiles()
    {
        QTemporaryDir dir;
        QVERIFY(terrain::test::writeHgt(dir.filePath("N56E024.hgt"), 1201, [](int, int) { return 33; }));
        QString error;
        auto terrain = sim::SimTerrain::fromDem(dir.path(), &error);
        QVERIFY2(terrain, qPrintable(error));
        QCOMPARE(terrain->groundAt(56.5, 24.5), std::optional<double>(33.0));
        QVERIFY(!terrain->groundAt(55.5, 24.5));
        QCOMPARE(terrain->groundOr(55.5, 24.5, 7.0), 7.0);
        QVERIFY(!sim::SimTerrain::fromDem(dir.filePath("missing"), &error));
        QVERIFY(error.contains(QStringLiteral("missing")));
        QTemporaryDir empty;
        QVERIFY(!sim::SimTerrain::fromDem(empty.path(), &error));
        QVERIFY(error.contains(QStringLiteral("no SRTM tile")));
    }

    // The processor's geometry, then the terrain pass: across the 60 m hill NW of the homes at 40 m
    // AGL (set over the flat ground at both ends) the leg passes below the hilltop.
    void processingOverTheHills()
    {
        sim::SimTerrain terrain(10.0);
        pb::Route route;
        *route.add_segments() = waypoint(56.99, 24.05, 40);
        *route.add_segments() = waypoint(56.99, 24.07, 40);
        *route.add_segments() = waypoint(56.99, 24.0601, 90);  // on the hilltop, 90 m above it
        pb::ProcessedRoute processed = sim::SimRouteProcessor::process(route, {}, 10.0);
        sim::SimRouteTerrain::apply(processed, terrain, 10.0);
        QCOMPARE(processed.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(processed.segments(1).status(), pb::RPS_INVALID);
        const QString text = QString::fromStdString(processed.segments(1).messageset().messages(0).defaulttext());
        QVERIFY2(text.startsWith(QStringLiteral("The leg from waypoint 1 to waypoint 2 passes")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("safe distance to terrain of 10.0 m")));
        // The third waypoint flies above the hilltop's ground, not the plain's.
        const auto &third = processed.segments(2);
        for (const auto &a : third.segmentactions())
            if (a.has_waypoint()) {
                const double ground = *terrain.groundAt(56.99, 24.0601);
                QVERIFY(ground > 60);
                QCOMPARE(a.waypoint().elevation(), ground);
                QCOMPARE(a.waypoint().wgs84altitude(), ground + 90);
            }
        // A smaller safe distance from the vehicle profile does not save a leg through the hill.
        pb::VehicleProfile profile;
        auto *p = profile.add_parameters();
        p->set_type(pb::VPT_SAFE_DISTANCE_TO_TERRAIN);
        p->set_value(2.5);
        QCOMPARE(sim::SimRouteTerrain::safeDistance(profile, nullptr), 2.5);
        QCOMPARE(sim::SimRouteTerrain::safeDistance(pb::VehicleProfile(), nullptr), 10.0);
    }

    // The demo route is flyable over the built-in terrain: its first leg crosses a knoll safely.
    void demoRouteIsClear()
    {
        sim::SimTerrain terrain(10.0);
        pb::Route route;
        *route.add_segments() = waypoint(56.97650, 24.07350, 40);
        *route.add_segments() = waypoint(56.97800, 24.07600, 50);
        *route.add_segments() = waypoint(56.97700, 24.07950, 50);
        *route.add_segments() = waypoint(56.97580, 24.07500, 40);
        pb::ProcessedRoute processed = sim::SimRouteProcessor::process(route, {}, 10.0);
        sim::SimRouteTerrain::apply(processed, terrain, 10.0);
        for (const auto &s : processed.segments())
            QCOMPARE(s.status(), pb::RPS_PROCESSED);
        QVERIFY(*terrain.groundAt(56.97725, 24.07475) > 25);  // the knoll is there
    }
};

QTEST_GUILESS_MAIN(TstSimTerrain)
#include "tst_simterrain.moc"
