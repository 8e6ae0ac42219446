#pragma once

#include "ClosestApproach.h"
#include "GeoPoint.h"
#include "LocalTangentPlane.h"
#include "RouteTiming.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::deconfliction {

// Where a flying vehicle is now, its altitude in the flights' common frame.
struct FlightPosition
{
    mission::GeoPoint position;
    double altitude = 0.0;
};

// A route's timeline placed on the clock all flights share (seconds; the caller picks its zero).
// Altitudes are the timeline's numbers, taken as one common frame for every flight: the caller
// converts them first when the routes' frames differ.
struct ScheduledFlight
{
    QString name;
    mission::RouteTimeline timeline;
    double start = 0.0;  // clock seconds when the timeline's second `flown` is reached
    // A flying vehicle: seconds of its timeline already flown at `start` (the clock's "now"); what
    // came before is not flown again. 0 for a route not yet flown.
    double flown = 0.0;
    // A flying vehicle's position at `start`: it flies straight from there to the end of the piece
    // of its timeline it is on, in that piece's remaining time. Unset: it is where its timeline says.
    std::optional<FlightPosition> now;

    // Clock seconds of the timeline's second t.
    double clockAt(double timelineSeconds) const { return start + timelineSeconds - flown; }
};

// For a flying vehicle on leg `legIndex` (an index into timeline.legs()) at `position`: the seconds
// of the timeline it has flown, taking the point of the leg's move nearest to it (clamped to the
// leg's ends) and the time model's even progress over the move. nullopt for no such leg.
std::optional<double> flownAlongLeg(const mission::RouteTimeline &timeline, int legIndex, const mission::GeoPoint &position);

// A stretch of one flight in which it moves in a straight line at constant velocity (or holds
// still), in local metres: a take-off climb, a hold, a move (or the part of it while the height
// changes, and the level rest), a landing descent.
struct MotionPiece
{
    int flight = 0;   // index into the flights searched
    int leg = 0;      // the timed leg's number (TimedLeg::leg, as `sortie-plan profile` counts)
    double begin = 0.0, end = 0.0;  // clock seconds
    LocalState at;    // position at `begin` and the velocity
    // The space the piece sweeps (metres, plane and altitude).
    double minEast = 0.0, maxEast = 0.0, minNorth = 0.0, maxNorth = 0.0, minUp = 0.0, maxUp = 0.0;

    // The state at clock second t (on the piece's line; t need not be inside it).
    LocalState stateAt(double t) const;
};

// The flight cut into its pieces in time order, projected on `plane`. A move's height changes at
// the time model's rates (docs/endurance.md); where they give it no time of its own (no climb or
// descent rate), it changes evenly over the move rather than at once. Pieces of no duration are
// left out, and so is everything before the flight's `flown` second.
std::vector<MotionPiece> motionPieces(const ScheduledFlight &flight, int flightIndex, const mission::LocalTangentPlane &plane);

} // namespace sortie::deconfliction
