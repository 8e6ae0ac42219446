#pragma once

#include "GeoPoint.h"
#include "Route.h"

#include <QString>

#include <vector>

namespace com::ugcs::ucs::proto { class ProcessedRoute; }

namespace sortie::mission {

// The plan the vehicle will fly, as the UgCS server processed it (ProcessRouteResponse): every
// waypoint with its absolute altitude and the ground under it, per segment with the server's
// status, estimates and messages.
enum class AltitudeFrame { Wgs84, Agl, Rangefinder, SmartAgl };
enum class ProcessingStatus { Modified, Invalid, Marked, Processed };

struct ProcessedWaypoint
{
    GeoPoint position;
    double altitudeAmsl = 0.0;     // wgs84Altitude: where the vehicle flies
    double groundElevation = 0.0;  // elevation of the ground below
    AltitudeFrame frame = AltitudeFrame::Wgs84;
    TurnType turnType = TurnType::StopAndTurn;
    double acceptanceRadius = 0.0;
    double speed = 0.0;            // ground speed of the last speed change before it, 0 if none
    WaypointRole role = WaypointRole::Pass;
    int segment = 0;               // index into ProcessedPlan::segments
    bool connection = false;       // part of the server's connection into the segment
};

struct ProcessedMessage
{
    bool error = false;  // MS_ERROR; warnings and information otherwise
    QString text;
};

struct ProcessedSegment
{
    QString uuid;              // the SegmentDefinition's uuid
    int routeRow = -1;         // the matching row of the edited route, -1 if none matches
    ProcessingStatus status = ProcessingStatus::Modified;
    double estimatedDistance = 0.0;  // metres
    double estimatedTime = 0.0;      // seconds
    std::vector<ProcessedMessage> messages;
    int firstWaypoint = 0;
    int waypointCount = 0;
    int actionCount = 0;       // camera, wait, heading, ... actions in the segment
};

struct ProcessedPlan
{
    std::vector<ProcessedSegment> segments;
    std::vector<ProcessedWaypoint> waypoints;
    double estimatedDistance = 0.0;
    double estimatedTime = 0.0;

    bool flyable() const;  // every segment RPS_PROCESSED
};

// route, when given, is the edited route: segments are matched to its rows by uuid.
ProcessedPlan processedPlanFromHci(const com::ugcs::ucs::proto::ProcessedRoute &processed, const Route *route = nullptr);

} // namespace sortie::mission
