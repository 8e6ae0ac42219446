#pragma once

#include <optional>

namespace sortie::deconfliction {

// The separation two vehicles keep: closer than `horizontal` metres across AND `vertical` metres in
// height is a conflict (docs/deconfliction.md). The defaults are the issue's; the client's settings
// may change them.
struct Separation
{
    double horizontal = 20.0;
    double vertical = 15.0;
};

// A vehicle moving in a straight line at constant velocity, in local metres (east, north, up) and
// metres per second: a piece of a planned flight, or a vehicle or ADS-B target as reported now.
struct LocalState
{
    double east = 0.0, north = 0.0, up = 0.0;
    double vEast = 0.0, vNorth = 0.0, vUp = 0.0;
};

struct TimeInterval
{
    double begin = 0.0;
    double end = 0.0;
};

// How close two vehicles come over a horizon. `time` is when the horizontal distance is smallest
// (ties, as when neither moves across, go to the smaller height difference, then the earlier time):
// within the conflict when there is one, else over the whole horizon.
struct Approach
{
    double time = 0.0;        // seconds from the states' moment
    double horizontal = 0.0;  // metres apart across at `time`
    double vertical = 0.0;    // metres apart in height at `time` (not signed)
    std::optional<TimeInterval> conflict;  // seconds from the states' moment where the separation is lost
};

// The closest approach of two constant-velocity states over [0, horizonSeconds]. Exact: the
// horizontal distance squared is a quadratic in time and the height difference linear, so the
// conflict is the overlap of a quadratic's and a linear inequality's intervals. No sampling.
Approach closestApproach(const LocalState &a, const LocalState &b, double horizonSeconds, const Separation &separation = {});

// The same for b's motion relative to a's (b − a), which is what the conflict search solves.
Approach relativeApproach(const LocalState &relative, double horizonSeconds, const Separation &separation);

} // namespace sortie::deconfliction
