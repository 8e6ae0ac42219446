#pragma once

#include "RouteFence.h"
#include "Segment.h"
#include "ServerOrigin.h"

#include <QDateTime>
#include <QString>

#include <map>

#include <optional>
#include <vector>

namespace sortie::mission {

// The limits of the vehicle a route is planned for. 0 means "unknown": the rule is not checked.
struct VehicleProfile
{
    QString name;
    double maxHorizontalSpeed = 0.0;  // m/s
    double climbRate = 3.0;           // m/s, used to estimate flight time
    double descentRate = 2.0;         // m/s
    double safeTerrainDistance = 10.0;  // metres: the least clearance above the ground on any leg
    // The profile's camera payloads (read from the server; a segment's `camera` names one by id or
    // name, and one without `camera` flies the first). Empty: only the built-in cameras.
    std::vector<ProfileCamera> cameras;
    bool operator==(const VehicleProfile &) const = default;
};

enum class FailsafeReason { RcLost, GpsLost, LowBattery, DatalinkLost };
enum class FailsafeAction { GoHome, Land, Wait, Continue, NotAvailable };

struct Failsafe
{
    FailsafeReason reason = FailsafeReason::RcLost;
    FailsafeAction action = FailsafeAction::GoHome;
    bool operator==(const Failsafe &) const = default;
};

// Where the vehicle starts (QGroundControl's planned home, a WPL file's first line). Altitude AMSL.
struct HomePosition
{
    GeoPoint position;
    double altitudeAmsl = 0.0;
    bool operator==(const HomePosition &) const = default;
};

enum class EndAction { None, ReturnHome };

// Everything about a route except its segments: what a route-settings edit changes.
struct RouteSettings
{
    QString name;
    VehicleProfile profile;
    double safeAltitude = 20.0;   // metres AGL: the lowest altitude a waypoint should use
    double maxAltitude = 120.0;   // metres AGL: no waypoint may be higher
    double initialSpeed = 5.0;    // m/s
    double maxSpeed = 10.0;       // m/s
    double cornerRadius = 0.0;    // metres; 0 = none
    double takeoffHeight = 0.0;   // metres
    std::vector<Failsafe> failsafes;
    std::optional<HomePosition> home;
    EndAction endAction = EndAction::None;
    // Whether the server's route processing refuses the route where it crosses an aerodrome's or
    // a custom no-fly zone (HCI Route.checkAerodromeNfz / checkCustomNfz). Off unless set: the
    // schema gives them no default, and a server reads an absent flag as false.
    bool checkAerodromeNfz = false;
    bool checkCustomNfz = false;
    // When the flight is planned to start (UTC); none: whenever it is checked, that is now. UAS
    // geographical zones count when they apply between this and the route's end by the time model.
    std::optional<QDateTime> plannedStart;
    // The authorisations the operator recorded: a geographical zone's identifier -> the reference
    // the authority gave. They turn a REQ_AUTHORISATION zone from an error into a warning naming
    // the reference, and the upload review shows them.
    std::map<QString, QString> authorisations;
    bool operator==(const RouteSettings &) const = default;
};

struct Route
{
    RouteSettings settings;
    std::vector<Segment> segments;
    RouteFence fence;  // a .plan's geofence and rally points, kept for writing back (core/airspace checks them)
    ServerOrigin origin;
    bool operator==(const Route &) const = default;
};

} // namespace sortie::mission
