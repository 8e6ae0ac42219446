#pragma once

#include "GeoPoint.h"
#include "ServerOrigin.h"
#include "WaypointAction.h"

#include <vector>

namespace sortie::mission {

// What the vehicle does at the point: fly through it, take off there (climb vertically to the
// altitude) or land there.
enum class WaypointRole { Pass, Takeoff, Land };

struct Waypoint
{
    GeoPoint position;
    double altitude = 50.0;  // metres, in altitudeType's reference
    AltitudeType altitudeType = AltitudeType::Agl;
    double speed = 5.0;      // m/s, ground speed on the leg that arrives at this point
    TurnType turnType = TurnType::StopAndTurn;
    double acceptanceRadius = 0.0;  // metres; 0 = the vehicle's default
    WaypointRole role = WaypointRole::Pass;
    std::vector<WaypointAction> actions;
    ServerOrigin origin;  // the server's SegmentDefinition this came from, if any

    bool operator==(const Waypoint &) const = default;
};

QString turnTypeName(TurnType type);  // "StopAndTurn", "Straight", "Spline", "BankTurn"
bool parseTurnType(const QString &name, TurnType *out);
QString roleName(WaypointRole role);  // "waypoint", "takeoff", "land"
bool parseRole(const QString &name, WaypointRole *out);

} // namespace sortie::mission
