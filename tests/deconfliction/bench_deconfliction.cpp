// Deconfliction of 20 routes of 500 waypoints each, all 190 pairs: ten lawnmower strips running
// east and ten running north over the same 5 x 5 km near Riga, all at 60 m and 8 m/s, starting 30 s
// apart, so every eastern strip crosses every northern one and some crossings are flown at once.
// Timed: the 20 timelines; the search (pieces, sweep, exact solution, merging); both together.
// Target (issue 24): all pairs under 50 ms.
#include "BenchClock.h"
#include "ConflictSearch.h"
#include "LocalTangentPlane.h"
#include "Route.h"
#include "RouteTiming.h"

#include <QLoggingCategory>

#include <cstdio>

using namespace sortie::deconfliction;
using namespace sortie::mission;
using namespace sortie::test;

namespace {
constexpr int kRoutes = 20;
constexpr int kWaypoints = 500;

// Strip k: five rows of 100 points 50 m apart, 200 m wide, east-west for even k, north-south for odd.
Route stripRoute(int k, const LocalTangentPlane &plane)
{
    Route r;
    r.settings.name = QStringLiteral("strip %1").arg(k + 1);
    r.settings.initialSpeed = 8;
    const double offset = (k / 2) * 500.0 - 2500;
    for (int i = 0; i < kWaypoints; ++i) {
        const int row = i / 100, col = (row % 2) ? 99 - i % 100 : i % 100;
        const double along = col * 50.0 - 2500, across = offset + row * 50.0;
        Waypoint w;
        w.position = k % 2 ? plane.unproject({across, along}) : plane.unproject({along, across});
        w.altitude = 60;
        w.speed = 8;
        r.segments.push_back(w);
    }
    return r;
}

bool report(const char *what, Timing t, double targetMs)
{
    const Verdict v = judge(t, targetMs);
    std::printf("%-44s %8.3f ms wall, %8.3f ms CPU, worst %8.3f ms", what, t.wallMs, t.cpuMs, t.worstMs);
    if (targetMs > 0)
        std::printf("  (target < %.0f ms)%s", targetMs, v.note);
    std::printf("\n");
    return v.met;
}
} // namespace

int main()
{
    QLoggingCategory::setFilterRules(QStringLiteral("sortie.*.debug=false"));  // the search's one line per run
    std::printf("Sortie deconfliction benchmark (%d routes x %d waypoints, all pairs; median of repeated runs; load average %.2f on %u cores)\n",
                kRoutes, kWaypoints, loadAverage(), std::thread::hardware_concurrency());
    const LocalTangentPlane plane({56.95, 24.1});
    std::vector<Route> routes;
    std::vector<std::vector<PathPoint>> paths;
    for (int k = 0; k < kRoutes; ++k) {
        routes.push_back(stripRoute(k, plane));
        paths.push_back(flightPath(routes.back()));
    }
    TimingParameters parameters;
    parameters.cruiseSpeed = 8;
    parameters.climbRate = 3;
    parameters.descentRate = 2;

    std::vector<ScheduledFlight> flights(kRoutes);
    const auto timeAll = [&] {
        for (int k = 0; k < kRoutes; ++k) {
            flights[size_t(k)].timeline = timePath(routes[size_t(k)], paths[size_t(k)], parameters).value();
            flights[size_t(k)].start = 30.0 * k;
        }
    };
    bool ok = true;
    report("timelines (20 x 500 waypoints)", median(21, timeAll), 0);
    ConflictReport found;
    ok &= report("search, all pairs", median(21, [&] { found = findConflicts(flights); }), 50);
    ok &= report("timelines and search", median(21, [&] {
        timeAll();
        found = findConflicts(flights);
    }), 50);
    std::printf("%-44s %d pairs, %lld pieces, %lld piece pairs overlapping in time, %lld solved, %zu conflicts\n", "  found",
                found.pairs, found.pieces, found.overlapping, found.solved, found.conflicts.size());
    ConflictReport one;
    ok &= report("search, one route against the other 19", median(21, [&] { one = findConflicts(flights, {{}, 0}); }), 50);
    std::printf("%-44s %d pairs, %lld solved, %zu conflicts\n", "  found", one.pairs, one.solved, one.conflicts.size());
    std::printf("%s\n", ok ? "all targets met" : "TARGET MISSED");
    return ok ? 0 : 1;
}
