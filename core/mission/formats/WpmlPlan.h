#pragma once

#include "DjiDroneModels.h"
#include "WpmlSchema.h"

#include <array>
#include <optional>
#include <vector>

// The route as WPML says it: the points to fly and the action groups over them, with heights already
// in the written height mode. Building it is where a route is refused; the documents only print it.
namespace sortie::mission::formats::wpml {

inline MissionError refuse(const QString &message) { return MissionError{QStringLiteral("DJI WPML: ") + message, {}, 0, 0, {}}; }

// One action of a group, with its parameter (seconds, degrees) where it has one.
struct Action
{
    ActuatorFunc func;
    double value = 0.0;
};

// A group of actions over a span of points: fired once on reaching `start` (ReachPoint), or
// repeatedly every `interval` metres/seconds from `start` to `end`.
struct Group
{
    int start = 0;
    int end = 0;
    TriggerType trigger = TriggerType::ReachPoint;
    double interval = 0.0;
    std::vector<Action> actions;
};

struct Point
{
    GeoPoint position;
    double executeHeight = 0.0;   // in the wayline's height mode
    double templateHeight = 0.0;  // in the template's (AMSL for EGM96)
    double speed = 0.0;           // m/s on the leg arriving here (Sortie's convention)
    TurnMode turn = TurnMode::StopStraight;
    bool straight = true;
    double damping = 0.0;
    HeadingMode heading = HeadingMode::FollowWayline;
    std::optional<std::array<double, 3>> poi;  // lat, lon, height
    int segment = -1;
};

struct Plan
{
    std::vector<Point> points;
    std::vector<Group> groups;
    std::vector<Action> startActions;  // wpml:startActionGroup: before the flight to the first point
    FinishAction finish = FinishAction::NoAction;
    QStringList notices;
};

class GeoidAccess;

// Builds the points and action groups of the route, refusing what WPML cannot say. The geoid
// converts AMSL into ellipsoidal heights for the WGS84 height mode.
Result<Plan> planOf(const Route &route, const WpmlExportOptions &options, const DjiDroneModel &model,
                    const DjiPayload &payload, ScanPlanCache *cache, GeoidAccess *geoid);

// The take-off's AMSL altitude the export uses: the option, else the route's home.
std::optional<double> takeoffAltitude(const WpmlExportOptions &options, const Route &route);

} // namespace sortie::mission::formats::wpml
