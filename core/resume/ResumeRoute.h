#pragma once

#include "MissionError.h"
#include "Route.h"

#include <QStringList>

#include <optional>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::resume {

// Where a mission stopped half-way (a battery change, low battery, a return home the operator
// ordered, a lost link) and how it goes on.
struct ResumeRequest
{
    enum class From {
        LastPhoto,    // the next photo is due a series interval after the last one: the rest starts there
        LastWaypoint, // the rest starts at the last waypoint the vehicle reached
        Place,        // the rest starts at a place on the path: a battery change the endurance model placed
    };
    From from = From::LastPhoto;
    mission::GeoPoint lastPhoto;  // LastPhoto: where the last photo was taken
    // Place: how far along the path, metres of horizontal flight from the route's start, and where
    // that is (endurance::BatteryChange::at's distance and position): the distance says which pass
    // of a place the path makes twice (home), the position checks it.
    double placeDistance = 0.0;
    mission::GeoPoint place;
    // LastWaypoint: the positions of the mission's waypoints the vehicle reached, in order (what it
    // holds may have more points than the route's path, such as terrain following's: those are
    // passed over). In order, because a path may come back to where it was (a landing at home).
    std::vector<mission::GeoPoint> reached;
    mission::GeoPoint takeoff;  // where the vehicle stands now, after the battery change
    // The height of the flight from the take-off to the resume point, metres in the resume point's
    // altitude frame. None: the higher of the route's safe altitude (AGL) and the resume point's.
    std::optional<double> transitAltitude;
    // How far the last photo may lie from the route's flown path: farther, it is not this route's flight.
    double tolerance = 30.0;
    // How close a reached waypoint must be to a point of the path to be that point.
    double waypointTolerance = 1.0;
};

// The rest of a route as a new one: a take-off where the vehicle stands, the flight to the resume
// point at the transit height, the resume point with the camera as it was there (the photo series by
// distance or time and its interval, the gimbal's attitude, the heading, the point of interest,
// video recording), the rest of the segment it lies in as plain waypoints, then the route's later
// segments as they are (an area scan stays an area scan). The settings are the route's.
struct ResumePlan
{
    mission::Route route;
    int resumedRow = -1;          // the row (of the flown route) the resume point lies in
    mission::GeoPoint resumeAt;   // where the rest starts, and the camera with it
    double offPath = 0.0;         // metres from the last photo, or the last waypoint reached, to the path
    double flownMetres = 0.0;     // along the path from its start to the resume point
    double remainingMetres = 0.0; // from the resume point to the path's end
    QStringList notes;            // for the operator: what the camera does there, what is assumed
};

// The plan, or why there is none (named for the operator): a segment that cannot be expanded here,
// a stop too far from the path or no waypoint of it reached, a path already flown to its end.
mission::Result<ResumePlan> resumeRoute(const mission::Route &flown, const ResumeRequest &request,
                                        mission::ScanPlanCache *cache = nullptr);

} // namespace sortie::resume
