#include "FlightPath.h"

#include "AlgorithmCatalog.h"
#include "ScanPlanCache.h"
#include "SegmentPlanning.h"

#include <cmath>

namespace sortie::mission {

std::vector<PathPoint> flightPath(const Route &route, ScanPlanCache *cache)
{
    std::vector<PathPoint> path;
    path.reserve(route.segments.size());
    for (size_t i = 0; i < route.segments.size(); ++i) {
        const Segment &s = route.segments[i];
        if (const Waypoint *w = asWaypoint(s)) {
            PathPoint p{w->position, w->altitude, w->altitudeType, w->speed, 0.0, w->role, int(i)};
            for (const auto &a : w->actions)
                if (const auto *wait = std::get_if<WaitAction>(&a))
                    p.holdSeconds += wait->seconds;
            path.push_back(p);
            continue;
        }
        if (const AlgorithmSegment *a = asAlgorithmSegment(s)) {
            // Planned the way the server (and sortie-sim) processes it.
            PlanContext context = planContextOf(route.settings);
            if (!path.empty())
                context.previousPosition = path.back().position;
            const SegmentPlanOutcome o = planAlgorithmSegment(*a, AlgorithmCatalog::builtIn(), context);
            if (o.ok()) {
                for (const PlannedPoint &p : o.plan->points) {
                    const WaypointRole role = p.kind == PlannedPoint::Kind::Takeoff ? WaypointRole::Takeoff
                                            : p.kind == PlannedPoint::Kind::Landing ? WaypointRole::Land : WaypointRole::Pass;
                    path.push_back({p.position, p.height, p.frame == HeightFrame::Amsl ? AltitudeType::Amsl : AltitudeType::Agl,
                                    p.speed > 0 ? p.speed : route.settings.initialSpeed, 0.0, role, int(i)});
                }
                continue;
            }
        }
        const std::optional<AreaScan> planned = isAreaScan(s) ? scanOf(s) : std::nullopt;
        if (!planned) {
            // A segment the client cannot plan flies through its figure's points until the server
            // processes it.
            const double altitude = altitudeOf(s), speed = speedOf(s);
            for (const GeoPoint &g : figureOf(s))
                path.push_back({g, std::isnan(altitude) ? 0.0 : altitude, altitudeTypeOf(s), std::isnan(speed) ? route.settings.initialSpeed : speed,
                                0.0, WaypointRole::Pass, int(i)});
            continue;
        }
        const AreaScan &scan = *planned;
        AreaScanOutcome scratch;
        const AreaScanOutcome &o = scanOutcome(scan, cache, scratch);
        const double speed = scan.parameters.speed;
        if (!o.ok()) {
            if (!scan.polygon.empty())
                path.push_back({scan.polygon.front(), scanAltitude(scan.parameters), scan.parameters.altitudeType, speed, 0.0,
                                WaypointRole::Pass, int(i)});
            continue;
        }
        for (const GeoPoint &g : o.plan->path)
            path.push_back({g, o.plan->altitude, scan.parameters.altitudeType, speed, 0.0, WaypointRole::Pass, int(i)});
    }
    return path;
}

} // namespace sortie::mission
