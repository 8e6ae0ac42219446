#pragma once

#include "FlightLog.h"
#include "Route.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace sortie::flightlog {

// The flown track of one vehicle against a planned route.
//
// Waypoints are taken in order: a waypoint is reached at the first moment, after the previous
// reached one, that the track passes within its acceptance radius (kDefaultAcceptance when the
// route leaves it to the vehicle), else it is missed. Each track point between the first and the
// last reached waypoint (to the end of the track when the last one was missed) belongs to a leg:
// the nearest of the legs between the two reached waypoints around it; but the approach to the first
// waypoint, inside its acceptance radius until the vehicle is past it, is the flight from where the
// vehicle started and belongs to no leg. Heights are planned as the legs are flown (FlownLegs.h:
// a take-off climbs straight up first, a landing descends straight down after). Per leg: the largest and
// mean cross-track distance (to the leg's segment) and altitude deviation (against the altitude
// planned along the leg, in the route's reference: AGL or AMSL).
struct LegDeviation
{
    int from = 0, to = 1; // waypoint numbers (0-based)
    int samples = 0;      // track points that belong to it
    double maxCrossTrack = 0, meanCrossTrack = 0;       // m
    double maxAltitude = 0, meanAltitude = 0;           // m, absolute; NaN without altitude samples
};

struct WaypointPassage
{
    int index = 0;
    double latitude = 0, longitude = 0; // degrees
    double radius = 0;                  // acceptance radius used, m
    std::optional<int64_t> reachedAt;   // ms since the epoch; nullopt: missed
    double closest = 0;                 // closest horizontal approach, m
};

// A track point that belongs to a leg, with its deviation: what the map's overlay colours.
struct TrackDeviation
{
    double latitude = 0, longitude = 0; // degrees
    int64_t time = 0;
    int leg = 0;            // index into legs
    double crossTrack = 0;  // m
    double altitude = 0;    // m, absolute; NaN when unknown
};

struct RouteComparison
{
    QString routeName;
    QString vehicleName;
    std::vector<WaypointPassage> waypoints;
    std::vector<LegDeviation> legs;
    std::vector<TrackDeviation> track;
    int reached = 0, missed = 0;
    double maxCrossTrack = 0, meanCrossTrack = 0, maxAltitude = 0, meanAltitude = 0;
    int64_t start = 0, end = 0; // the span compared

    QJsonObject toJson() const;
    QString toText() const;
};

inline constexpr double kDefaultAcceptance = 3.0; // m

struct ComparisonResult
{
    std::optional<RouteComparison> comparison;
    QString error; // why the route was refused
};

// Refuses a route that is not this vehicle's: the vehicle is not in the log, has no track, or the
// route lies more than kMatchDistance from anywhere it flew.
inline constexpr double kMatchDistance = 1000.0; // m
ComparisonResult compareRoute(const FlightLog &log, int vehicle, const mission::Route &route);

} // namespace sortie::flightlog
