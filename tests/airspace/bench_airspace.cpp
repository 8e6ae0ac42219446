// The airspace check on the shared 10,000-waypoint route (tests/mission/BenchRoute.h, a 5 x 5 km
// lawnmower near Riga, 60..66 m AGL) against 2,000 zones over 20 x 20 km around it: polygons of 6
// to 12 vertices and circles, 40 to 400 m across, half with AGL floors and ceilings. Targets: the
// whole check under 20 ms; the re-check after moving one waypoint (only its two legs) under 16 ms.
#include "AirspaceCheck.h"
#include "Airspace.h"
#include "BenchClock.h"
#include "BenchRoute.h"
#include "FlownPath.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"
#include "ZoneEditor.h"

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>

#include <cstdio>
#include <random>

using namespace sortie::airspace;
using namespace sortie::mission;
using namespace sortie::test;

namespace {
bool report(const char *what, Timing t, double targetMs)
{
    const Verdict v = judge(t, targetMs);
    std::printf("%-52s %8.3f ms wall, %8.3f ms CPU, worst %8.3f ms", what, t.wallMs, t.cpuMs, t.worstMs);
    if (targetMs > 0)
        std::printf("  (target < %.0f ms)%s", targetMs, v.note);
    std::printf("\n");
    return v.met;
}

std::vector<Zone> benchZones(int n)
{
    std::mt19937 random(22);
    std::uniform_real_distribution<double> where(-10000, 10000), size(20, 200), unit(0, 1);
    const LocalTangentPlane plane({56.95, 24.1});
    std::vector<Zone> zones;
    for (int i = 0; i < n; ++i) {
        Zone z;
        z.name = QStringLiteral("zone %1").arg(i + 1);
        const double x = where(random), y = where(random), r = size(random);
        if (i % 4 == 3) {
            z.shape = ZoneCircle{plane.unproject({x, y}), r};
        } else {
            const int vertices = 6 + i % 7;
            std::vector<GeoPoint> ring;
            for (int k = 0; k < vertices; ++k) {
                const double a = 2 * M_PI * k / vertices, rr = r * (0.6 + 0.4 * unit(random));
                ring.push_back(plane.unproject({x + rr * std::cos(a), y + rr * std::sin(a)}));
            }
            z.shape = ZonePolygons{{ZonePolygon{{ring}}}};
        }
        if (i % 2) {
            z.floor = HeightLimit{40.0 + 10 * (i % 5), HeightReference::AboveTerrain};
            z.ceiling = HeightLimit{120, HeightReference::AboveTerrain};
        }
        zones.push_back(std::move(z));
    }
    return zones;
}
} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);  // the route analyzer's timer
    constexpr int kWaypoints = 10000, kZones = 2000;
    std::printf("Sortie airspace benchmark (%d waypoints, %d zones; median of repeated runs; load average %.2f on %u cores)\n", kWaypoints,
                kZones, loadAverage(), std::thread::hardware_concurrency());
    Route route = benchRoute(kWaypoints);
    const auto zones = std::make_shared<const ZoneSet>(benchZones(kZones));

    bool ok = true;
    FlownPath path;
    report("flown path in 3D (profile route, plane, legs)", median(11, [&] { path = flownPath(route); }), 0);
    AirspaceReport found;
    ok &= report("check: every leg, fresh checker (frame, index)", median(11, [&] {
        AirspaceChecker checker(zones);
        found = checker.check(path);
    }), 20);
    std::printf("%-52s %zu violations, %zu warnings, %d active zones\n", "  found", found.violations.size(), found.warnings.size(), found.zones);

    // Dragging: one waypoint moves a little each frame; the checker keeps its frame and legs.
    AirspaceChecker checker(zones);
    checker.check(path);
    const LocalTangentPlane plane = path.plane;
    const GeoPoint start = std::get<Waypoint>(route.segments[5050]).position;
    std::vector<FlownPath> dragged;
    for (int i = 0; i < 11; ++i) {
        std::get<Waypoint>(route.segments[5050]).position = geodesicDirect(start, 45, 3.0 * (i + 1)).point;
        dragged.push_back(flownPath(route, nullptr, nullptr, &plane));
    }
    int checked = 0;
    ok &= report("re-check after moving one waypoint", measure(11, [&](int i) {
        found = checker.check(dragged[size_t(i)]);
        checked = checker.legsCheckedLastTime();
    }), 16);
    std::printf("%-52s %d legs checked again\n", "  ", checked);
    int frame = 0;
    report("  with the flown path rebuilt (what an edit costs)", median(11, [&] {
        std::get<Waypoint>(route.segments[5050]).position = geodesicDirect(start, 45, 40.0 + frame++).point;
        found = checker.check(flownPath(route, nullptr, nullptr, &plane));
    }), 0);

    // The client's store: a drawn zone's corner dragged among the 2,000 zones. Each step rebuilds the
    // zone set (every zone's validity, the R-tree) and hands it to the route's rule; with the route's
    // analyzer run at each step, the whole route is checked again (a new zone set, a fresh checker).
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
    RouteModel model;
    model.resetRoute(route);
    RouteAnalyzer analyzer(&model);
    Airspace store(&settings, &analyzer, &model, nullptr);
    store.setServerZones(benchZones(kZones));
    const GeoPoint c{56.95, 24.1};
    const auto corner = [&](double east, double north) {
        const GeoPoint p = geodesicDirect(geodesicDirect(c, 90, east).point, 0, north).point;
        return QGeoCoordinate(p.latitude, p.longitude);
    };
    store.editor()->addPolygon({corner(-100, -100), corner(100, -100), corner(100, 100), corner(-100, 100)});
    report("store: one drag step of a drawn zone's corner", measure(11, [&](int i) {
        store.editor()->moveVertex(0, 2, corner(100 + i, 100 + i), EditStep::Continuing);
    }), 16);
    report("  the same with the route's analyzer run", measure(11, [&](int i) {
        store.editor()->moveVertex(0, 2, corner(120 + i, 120 + i), EditStep::Continuing);
        analyzer.recomputeNow();
    }), 0);
    std::printf("%-52s %d errors, %d warnings\n", "  ", analyzer.validation().errorCount(), analyzer.validation().warningCount());
    std::printf("%s\n", ok ? "all targets met" : "TARGET MISSED");
    return ok ? 0 : 1;
}
