#pragma once

#include "VehicleTypes.h"

#include <QGeoCoordinate>
#include <QtGlobal>

#include <vector>

namespace sortie::vehicle {

// How far a vehicle is through the mission it carries: which waypoint it flies to, how far and
// how long the rest is. Pure arithmetic over great-circle legs, for the fly view and for tests.
struct MissionProgress
{
    int active = -1;                  // index of the waypoint being flown to; -1: none
    int count = 0;                    // waypoints in the mission
    double distanceToActive = qQNaN(); // m, from the position to the active waypoint
    double bearingToActive = qQNaN();  // deg from north, clockwise
    double distanceLeft = qQNaN();    // m: to the active waypoint, then along the remaining legs
    double timeLeft = qQNaN();        // s, each leg at its planned speed (else the given speed)

    bool isFlying() const { return active >= 0 && active < count; }
    bool isComplete() const { return count > 0 && active >= count; }

    // `active` as the vehicle reports it (TelemetryField::MissionCurrent); `speed` is used for
    // legs without a planned speed: the vehicle's ground speed when it moves, else `cruiseSpeed`.
    static MissionProgress compute(const std::vector<MissionItem> &mission, int active, const QGeoCoordinate &position,
                                   double groundSpeed, double cruiseSpeed = 5.0);
};

QGeoCoordinate coordinateOf(const MissionItem &item);
// Bearing from one point to another, degrees from north in [0, 360); NaN when either is invalid.
double bearingBetween(const QGeoCoordinate &from, const QGeoCoordinate &to);

} // namespace sortie::vehicle
