#pragma once

#include "FlightPath.h"

#include <cstddef>
#include <vector>

namespace sortie::mission {

// What joins the points of a flown path: the one rule every consumer (profile, terrain clearance,
// time model, statistics, airspace, sortie-sim's processing and flight, VCI missions) flies by.
// A multicopter takes off straight up and lands straight down: a take-off on the ground climbs
// vertically at its point to the height of the point after it before it moves, and a landing on the
// ground is reached at the height the leg left at, then descended to vertically. A take-off or
// landing point above the ground climbs from (descends to) the ground at its own height.

// A point as the rule sees it.
struct VerticalPoint
{
    WaypointRole role = WaypointRole::Pass;
    bool onGround = false;  // its height is the ground's (0 or less above the ground under it)
};

// One leg. Leg n (from 1) runs from point n-1 to point n, as `sortie-plan profile` numbers them; a
// lone point is leg 1, going nowhere. Heights are named by the point whose height they are, to be
// taken at this leg's end (each consumer converts heights in its own frames and through its own
// ground): a take-off climbs to the next point's height over the take-off point.
struct LegShape
{
    int leg = 1;
    size_t from = 0, to = 0;    // points; equal for a lone point
    size_t departHeight = 0;    // the height the leg leaves `from` at: `from`'s, or a take-off's next point's
    size_t arriveHeight = 0;    // the height it reaches `to` at: `to`'s, or for a landing the departure height
    bool climbAtStart = false;  // take-off: straight up at `from`, from the ground to the departure height
    bool descentAtEnd = false;  // landing: straight down at `to`, from the arrival height to the ground
    bool climbAtEnd = false;    // a take-off at the last point, which no leg leaves: straight up there
    bool moves() const { return from != to; }
};

std::vector<LegShape> flownLegs(const std::vector<VerticalPoint> &points);

// The same over a flown path (flightPath): a take-off or landing is on the ground at 0 m AGL or less.
std::vector<LegShape> flownLegs(const std::vector<PathPoint> &path);
bool onGround(double altitude, AltitudeType type);

} // namespace sortie::mission
