#pragma once

#include "FlightTrace.h"

#include <vector>

namespace sortie::endurance::fit {

// What a vehicle was doing at a sample, as far as its energy goes.
enum class Phase { Ground, Hover, Level, Climb, Descent, Transition };

const char *phaseName(Phase phase);

// Where one way of flying ends and another begins. Speeds in m/s, heights in m, times in s.
struct PhaseThresholds
{
    double airborneAbove = 1.0;      // lower is on the ground (disarmed, where the height is unknown)
    double stillBelow = 0.3;         // ground speed of a hover
    double levelVerticalBelow = 0.2; // |vertical speed| of hover and level flight
    double levelFasterThan = 1.0;    // ground speed of level flight
    double verticalFasterThan = 0.5; // |vertical speed| of a climb or descent ...
    double verticalGroundBelow = 0.5;// ... flown straight up or down
    double trimSeconds = 2.0;        // dropped at each end of a run: the vehicle is still changing
    double minRunSeconds = 2.0;      // what is left of a run must span this long
    double maxGapSeconds = 3.0;      // a longer gap between samples ends a run
};

Phase classify(const PowerSample &sample, const PhaseThresholds &t = {});

// A stretch of samples in one phase, with its transitions trimmed: [first, last] index the trace.
struct PhaseRun
{
    Phase phase = Phase::Transition;
    size_t first = 0, last = 0;
};

// The hover, level, climb and descent runs of a trace (ground and transitions are left out),
// each trimmed at both ends and long enough to use, in time order.
std::vector<PhaseRun> segmentPhases(const std::vector<PowerSample> &samples, const PhaseThresholds &t = {});

} // namespace sortie::endurance::fit
