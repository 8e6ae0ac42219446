#pragma once

#include "FlightPath.h"
#include "MissionError.h"
#include "Route.h"

#include <optional>
#include <vector>

namespace sortie::mission {

class ScanPlanCache;

// How a vehicle flies through a waypoint: without stopping (a coordinated turn, no time of its own)
// or stopping, turning, and speeding up again (the acceleration's time, where it is known).
enum class TurnMode { Coordinated, StopAndTurn };

// A steady wind: its speed (m/s) and the direction it blows FROM, degrees clockwise from north.
struct Wind
{
    double speed = 0.0;
    double fromDeg = 0.0;
    bool operator==(const Wind &) const = default;
};

// The figures the time model flies with (docs/endurance.md, "The time model").
struct TimingParameters
{
    double cruiseSpeed = 0.0;   // m/s: the air speed of a leg whose waypoint sets none
    double climbRate = 0.0;     // m/s; 0: a height change takes no time of its own
    double descentRate = 0.0;   // m/s
    std::optional<double> acceleration;  // m/s², horizontal; unset: speed changes take no time
    TurnMode turns = TurnMode::Coordinated;
    Wind wind;
};

// The parameters a route carries itself: its vehicle profile's rates, its initial speed as the
// speed where a waypoint sets none, coordinated turns, no wind. What the route statistics use.
TimingParameters timingOf(const RouteSettings &settings);

// Seconds the vehicle spends in each way of flying, so energy can be priced by phase.
struct PhaseSeconds
{
    double level = 0.0;      // horizontal motion with no height change
    double climb = 0.0;      // height gained (take-off, or on a leg; see TimedLeg::verticalSeconds)
    double descent = 0.0;    // height lost (landing, or on a leg)
    double hover = 0.0;      // holding still: waits, panoramas
    double manoeuvre = 0.0;  // the extra time of speeding up and slowing down at stops
    double total() const { return level + climb + descent + hover + manoeuvre; }
};

// One leg on the timeline: the flight from one point of the flown path to the next, with what
// happens at its ends. Leg n (from 1) runs from path point n-1 to point n, as `sortie-plan
// profile` numbers them; the flight home is the leg after the last. Within a leg, in order: the
// take-off climb straight up at its start point, the holds there (first leg only), the move, the holds at its
// end point, the landing descent there.
struct TimedLeg
{
    int leg = 1;
    bool returnHome = false;
    bool landsAtEnd = false;  // its end point is a landing (a Land waypoint, or home)
    GeoPoint from, to;
    // The heights the move leaves and arrives at (FlownLegs.h: over a take-off on the ground, the
    // next point's; over a landing on the ground, the one it left at); in altitudeType's frame when they match.
    double fromAltitude = 0.0, toAltitude = 0.0;
    AltitudeType altitudeType = AltitudeType::Agl;
    int fromSegment = -1, toSegment = -1;          // route rows, -1 for home

    double start = 0.0;       // seconds from the start of the route
    double duration = 0.0;
    double distance = 0.0;    // horizontal metres
    double heightChange = 0.0;  // metres from fromAltitude to toAltitude (+ up), take-off and landing apart
    double takeoffClimb = 0.0;  // metres climbed from the ground at the start point
    double landingDescent = 0.0; // metres descended to the ground at the end point
    double airSpeed = 0.0;    // m/s while moving
    double groundSpeed = 0.0; // m/s along the track (the wind triangle); = airSpeed without wind

    double takeoffSeconds = 0.0;
    double departHoldSeconds = 0.0;
    double moveSeconds = 0.0;      // the longer of horizontal (with speed changes) and vertical time
    double verticalSeconds = 0.0;  // of moveSeconds: how long the height changes
    double manoeuvreSeconds = 0.0; // of moveSeconds: speeding up and slowing down beyond the cruise time
    double arriveHoldSeconds = 0.0;
    double landingSeconds = 0.0;
    // The air speed while the height changes: the leg's, or less when the vertical motion is the
    // longer and the horizontal is spread over it (scaled by time; exact without wind).
    double verticalAirSpeed = 0.0;

    PhaseSeconds phases() const;
    double end() const { return start + duration; }
};

// Where the vehicle is at a moment of the timeline.
struct TimelinePosition
{
    GeoPoint position;
    double altitude = 0.0;
    AltitudeType altitudeType = AltitudeType::Agl;
    int leg = 0;  // index into legs(), -1 for an empty timeline
};

// A route as timed legs. positionAt is O(log legs) plus one geodesic: cheap enough to sample.
class RouteTimeline
{
public:
    RouteTimeline() = default;
    explicit RouteTimeline(std::vector<TimedLeg> legs);

    const std::vector<TimedLeg> &legs() const { return m_legs; }
    double totalSeconds() const { return m_legs.empty() ? 0.0 : m_legs.back().end(); }
    // The index of the leg flown at `seconds` (clamped to the timeline), -1 when there is none.
    int legAt(double seconds) const;
    TimelinePosition positionAt(double seconds) const;

private:
    std::vector<TimedLeg> m_legs;
};

// The route's flown path as timed legs (area scans expanded), the flight home included where the
// route ends with a return home. An error names the leg that cannot be flown (no speed; a wind its
// air speed cannot make headway against).
Result<RouteTimeline> timeRoute(const Route &route, const TimingParameters &parameters, ScanPlanCache *cache = nullptr);
// The same over a path already expanded (flightPath(route)).
Result<RouteTimeline> timePath(const Route &route, const std::vector<PathPoint> &path, const TimingParameters &parameters);

// Seconds a waypoint's actions hold the vehicle still: waits and panoramas (a wait for the
// operator counts its seconds only; camera and heading actions take no time of their own).
double actionSeconds(const std::vector<WaypointAction> &actions);

// Ground speed along a track (degrees) at an air speed in a wind; nullopt when the vehicle cannot
// make headway there (the cross wind is as fast as the air speed, or the head wind faster).
std::optional<double> groundSpeed(double airSpeed, double trackDeg, const Wind &wind);

} // namespace sortie::mission
