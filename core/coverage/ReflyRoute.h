#pragma once

#include "CoverageMap.h"
#include "Route.h"

#include <QStringList>

#include <optional>

namespace sortie::mission {
struct AreaScanPlan;
}

namespace sortie::coverage {

// How the gaps are flown again: the survey's camera, at the height it flew, with the overlap it was
// meant to have, along its legs.
struct ReflyOptions
{
    mission::Camera camera;
    double heightAboveGround = 60;   // m, flown AGL
    double frontOverlapPercent = 80;
    double sideOverlapPercent = 70;
    double speed = 8;                // m/s along the transects
    std::optional<double> legBearing; // degrees; absent: each scan's own best
};

// What the survey the report judged was flown with: its camera, the photos' median height above the
// ground, the measured forward and side overlap (kept within 50-95 % and 30-95 %), the legs' bearing;
// the defaults where the report measured nothing.
ReflyOptions reflyOptionsFor(const CoverageReport &report, const mission::Camera &camera);

// "Re-fly the gaps": a route of one area scan per hole (its scan ring, largest hole first), each
// planned as the vehicle will fly it. A hole whose scan cannot be planned is left out with the
// planner's reason in *notes. nullopt when no hole is left to fly.
std::optional<mission::Route> reflyRoute(const std::vector<Hole> &holes, const ReflyOptions &options, QStringList *notes);

} // namespace sortie::coverage
