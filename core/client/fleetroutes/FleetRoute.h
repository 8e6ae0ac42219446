#pragma once

#include "Route.h"

#include <QDateTime>
#include <QString>

#include <optional>

namespace sortie::client {

// Where a route given to a vehicle stands.
enum class FleetRouteState {
    Planned,  // the open route, chosen for a vehicle, not (or not as it is now) uploaded
    Uploaded, // the vehicle holds it (the upload succeeded); not flying it
    Flying,   // the vehicle reports the mission active or paused
    Flown,    // the vehicle reported the mission complete after flying it
};

// "planned", "uploaded", "flying", "flown".
QString fleetRouteStateName(FleetRouteState state);

// How far a vehicle is through the route it flies (Flying; Flown keeps the last).
struct FleetRouteProgress
{
    int waypoint = 0;                   // 1-based: the waypoint flown to ("waypoint n of m")
    int count = 0;                      // waypoints of the mission the vehicle holds
    double elapsedSeconds = qQNaN();    // since startedAt
    double remainingSeconds = qQNaN();  // MissionProgress::timeLeft; NaN when unknown (no position)
};

// One route given to a vehicle, as FleetRoutes::routes() hands it out (for 4D deconfliction:
// what flies where, when).
struct FleetRoute
{
    QString vehicleId;            // the fleet's vehicleId ("HCI:7", "VCI:vci-1")
    mission::Route route;         // Planned: the open route now; otherwise a copy as it was uploaded
    FleetRouteState state = FleetRouteState::Planned;
    QDateTime uploadedAt;         // UTC; invalid while planned
    // UTC: when this client first saw the vehicle flying the route (joining mid-flight, that is
    // later than the take-off). Invalid before it flies: a route that has not started has no
    // start time; whoever needs one assumes it (now, or a time the operator gives).
    QDateTime startedAt;
    double flightSeconds = qQNaN(); // the time model's total (timeRoute, timingOf); NaN: cannot be timed
    std::optional<FleetRouteProgress> progress; // Flying and Flown only
    // Uploaded after flying part of it (landed, sent home, disarmed): the progress when it stopped,
    // what a resume starts from. Cleared when it flies again.
    std::optional<FleetRouteProgress> stoppedShort;
};

} // namespace sortie::client
