// Terrain benchmark: a 100 km route's profile at a 30 m step from 1″ SRTM tiles, the terrain
// validation of the 10,000-waypoint route, and (with the UI) a full profile refresh while a
// waypoint of that route is dragged. Prints each figure with its target; exits 1 if one is missed.
// Run: build/tests/terrain/bench_terrain
#include "BenchClock.h"
#include "BenchRoute.h"
#include "ElevationService.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "TerrainProfile.h"
#include "TerrainRule.h"
#ifdef SORTIE_BENCH_UI
#include "RouteModel.h"
#include "TerrainProfileModel.h"
#endif

#include <QCoreApplication>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <thread>
#include <vector>

// Moves a waypoint of the model in place, as an edit of the route does (the profile sees a change of row).
[[maybe_unused]] static void moveWaypointIn(sortie::mission::RouteModel &model, int row, sortie::mission::GeoPoint to)
{
    sortie::mission::Segment s = model.segment(row);
    sortie::mission::asWaypoint(s)->position = to;
    model.replaceSegments({row}, {s});
}

using namespace sortie;
using namespace sortie::terrain;

namespace {
using sortie::test::judge;
using sortie::test::loadAverage;
using sortie::test::median;
using sortie::test::Timing;

bool report(const char *what, Timing t, double targetMs)
{
    const auto verdict = judge(t, targetMs);
    std::printf("%-52s %9.3f ms wall %9.3f ms cpu", what, t.wallMs, t.cpuMs);
    if (targetMs > 0)
        std::printf("   (target < %g ms)%s", targetMs, verdict.note);
    std::printf("\n");
    return verdict.met;
}

// Rolling hills: a few hundred metres of relief, continuous across tile edges.
int height(int south, int west, int r, int c)
{
    const double lat = south + 1 - r / 3600.0, lon = west + c / 3600.0;
    return int(150 + 80 * std::sin(lat * 40) * std::cos(lon * 25) + 30 * std::sin(lon * 170 + lat * 90));
}
} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    bool ok = true;
    std::printf("Sortie terrain benchmark (median of repeated runs; load average %.2f on %u cores)\n", loadAverage(),
                std::thread::hardware_concurrency());
    QTemporaryDir dir;
    for (int west : {24, 25})
        if (!terrain::test::writeHgt(dir.filePath(hgtName({56, west})), 3601, [west](int r, int c) { return height(56, west, r, c); }))
            return 1;
    HgtTileSource tiles(dir.path());
    ElevationService service;
    service.setSources({&tiles});

    // 100 km across two 1″ tiles.
    ProfileRoute longRoute;
    longRoute.waypoints = {{{56.20, 24.20}, 500, HeightReference::Amsl, 0, {}},
                           {{56.50, 24.90}, 500, HeightReference::Amsl, 1, {}},
                           {{56.78, 25.55}, 500, HeightReference::Amsl, 2, {}}};
    TerrainProfile profile;
    report("100 km profile, first (opens and checks 2 tiles)", median(1, [&] { profile = computeProfile(longRoute, service, 30); }), 0);
    ok &= report("100 km profile at 30 m from 1\u2033 tiles", median(21, [&] { profile = computeProfile(longRoute, service, 30); }), 20);
    std::printf("%-52s %9.1f km, %zu samples\n", "  route", profile.path.length() / 1000, profile.size());

    // The 10,000-waypoint route: its terrain rules.
    mission::Route big = mission::benchRoute(10000);
    TerrainRule rule(&service, 30);
    std::vector<mission::ValidationIssue> issues;
    ok &= report("terrain validation, 10,000 waypoints", median(11, [&] {
                     issues.clear();
                     rule.check(big, nullptr, issues);
                 }), 30);
    std::printf("%-52s %9zu issues\n", "  found", issues.size());

#ifdef SORTIE_BENCH_UI
    // Dragging one waypoint of it: each move is followed by the full refresh the view shows.
    mission::RouteModel model;
    model.resetRoute(big);
    ui::TerrainProfileModel view;
    view.setService(&service);
    view.setRouteModel(&model);
    int step = 0;
    ok &= report("profile refresh while dragging (10,000 waypoints)", median(21, [&] {
                     const GeoPoint p = mission::asWaypoint(model.segment(5000))->position;
                     moveWaypointIn(model, 5000, {p.latitude + 1e-5 * ((step++ % 2) ? 1 : -1), p.longitude});
                     view.recomputeNow();
                 }), 16);
    std::printf("%-52s %9d samples\n", "  profile", view.sampleCount());
#endif
    return ok ? 0 : 1;
}
