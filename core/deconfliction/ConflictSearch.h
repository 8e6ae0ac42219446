#pragma once

#include "ClosestApproach.h"
#include "ScheduledFlight.h"

#include <optional>
#include <vector>

namespace sortie::deconfliction {

// One vehicle at a conflict's closest approach: what a map draws.
struct ConflictSide
{
    int leg = 0;  // its timed leg then (TimedLeg::leg, as `sortie-plan profile` counts)
    mission::GeoPoint position;
    double altitude = 0.0;  // in the flights' common frame
};

// An interval in which two flights are closer than the separation both across and in height.
struct Conflict
{
    int first = 0, second = 0;       // indices into the flights searched, first < second
    TimeInterval interval;           // clock seconds
    // The closest approach within the interval: where the horizontal distance is smallest (ties to
    // the smaller height difference, then the earlier time), and both separations then.
    double time = 0.0;
    double horizontal = 0.0;
    double vertical = 0.0;
    ConflictSide firstAt, secondAt;
};

struct ConflictQuery
{
    Separation separation;
    // Only the pairs this flight is in (the route being uploaded against the others); unset: every pair. An index
    // outside the flights searches no pair.
    std::optional<int> against;
};

struct ConflictReport
{
    int pairs = 0;                   // pairs of flights searched
    std::vector<Conflict> conflicts; // by first flight, second flight, then time
    // What the search did, for the benchmark: motion pieces, piece pairs overlapping in time, and
    // of those the ones whose boxes met and were solved exactly.
    long long pieces = 0, overlapping = 0, solved = 0;
};

// Every conflict between the flights (or between `query.against` and the rest). The flights are
// cut into straight-line pieces in one tangent plane around their centre; a sweep over time keeps
// the pieces in the air at each moment, a box test (grown by the separation) drops pairs that are
// far apart, and each remaining pair is solved exactly over the time both are on it
// (relativeApproach). Touching windows of the same two flights merge into one conflict.
ConflictReport findConflicts(const std::vector<ScheduledFlight> &flights, const ConflictQuery &query = {});

} // namespace sortie::deconfliction
