// The endurance figures of the shared 10,000-waypoint route (tests/mission/BenchRoute.h): the
// timeline alone, the whole estimate (time, energy, changes, point of no return), and sampling the
// timeline's position. Target: the estimate under 5 ms.
#include "BenchClock.h"
#include "BenchRoute.h"
#include "EnduranceEstimate.h"

#include <cstdio>

using namespace sortie::endurance;
using namespace sortie::mission;
using namespace sortie::test;

namespace {
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
    constexpr int kWaypoints = 10000;
    std::printf("Sortie endurance benchmark (%d waypoints; median of repeated runs; load average %.2f on %u cores)\n", kWaypoints,
                loadAverage(), std::thread::hardware_concurrency());
    Route route = benchRoute(kWaypoints);
    route.settings.home = HomePosition{std::get<Waypoint>(route.segments.front()).position, 0};
    route.settings.endAction = EndAction::ReturnHome;
    EnergyProfile profile;
    profile.name = QStringLiteral("bench");
    profile.batteryWh = 500;
    profile.cruiseSpeed = 10;
    profile.climbRate = 3;
    profile.descentRate = 2;
    profile.hoverPowerW = 400;
    profile.cruisePowerW = 350;
    profile.climbPowerW = 550;
    profile.descentPowerW = 250;
    profile.acceleration = 2;
    const std::vector<PathPoint> path = flightPath(route);

    bool ok = true;
    RouteTimeline timeline;
    ok &= report("timeline (from the flown path)", median(21, [&] {
        timeline = timePath(route, path, timingFor(profile, {})).value();
    }), 0);
    const FlightConditions windy{Wind{5, 250}, TurnMode::StopAndTurn};
    EnduranceEstimate calm, wind;
    ok &= report("estimate: time and energy, no wind", median(21, [&] { calm = estimateEndurance(route, profile).value(); }), 5);
    ok &= report("estimate: 5 m/s wind, stop and turn", median(21, [&] { wind = estimateEndurance(route, profile, windy).value(); }), 5);
    std::printf("%-44s %8.0f s, %.1f Wh, %d batteries, %zu changes, PNR %s\n", "  calm", calm.flightTimeSeconds, calm.energyWh,
                calm.batteriesNeeded, calm.changes.size(), calm.pointOfNoReturn ? "found" : "none");
    std::printf("%-44s %8.0f s, %.1f Wh, %d batteries\n", "  windy", wind.flightTimeSeconds, wind.energyWh, wind.batteriesNeeded);
    double sink = 0;
    const int samples = 10000;
    const Timing sampling = median(9, [&] {
        for (int i = 0; i < samples; ++i)
            sink += timeline.positionAt(timeline.totalSeconds() * i / samples).altitude;
    });
    report("positionAt x 10,000", sampling, 0);
    std::printf("%-44s %8.3f us each (%g)\n", "  one position", sampling.wallMs * 1000 / samples, sink > 0 ? 1.0 : 0.0);
    std::printf("%s\n", ok ? "all targets met" : "TARGET MISSED");
    return ok ? 0 : 1;
}
