#pragma once

#include "VehicleTypes.h"

#include <QString>

#include <vector>

namespace com::ugcs::ucs::proto {
class ProcessedRoute;
class Route;
class Vehicle;
} // namespace com::ugcs::ucs::proto

namespace sortie::vehicle {

// A MissionItem list as the HCI Route a UgCS server processes and uploads: one Waypoint-algorithm
// segment per item (a point at its AGL altitude, its speed as the segment's "speed" parameter), the
// vehicle's profile attached so the server checks its limits. Pure.
com::ugcs::ucs::proto::Route hciRouteFor(const com::ugcs::ucs::proto::Vehicle &vehicle, const std::vector<MissionItem> &items,
                                         const QString &name);

// Empty when every segment was processed; otherwise what the server said about the first one that
// was not ("Waypoint 3: Altitude 900 m is above ...").
QString hciProcessingProblem(const com::ugcs::ucs::proto::ProcessedRoute &route);

} // namespace sortie::vehicle
