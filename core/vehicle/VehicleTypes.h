#pragma once

#include <QMetaType>
#include <QtNumeric>
#include <QString>
#include <QStringList>
#include <QVariantMap>

#include <memory>
#include <vector>

namespace sortie::vehicle {

// Who a vehicle is, as its link reports it.
struct VehicleIdentity
{
    QString id;        // stable: the VCI /vehicle id, or the HCI Vehicle object id
    QString name;      // what the operator calls it
    QString type;      // "multicopter", "fixed_wing", ... as reported
    QString autopilot; // firmware family or platform, as reported
    QString protocol;  // "VCI" or "HCI": the one place the client may show which

    bool operator==(const VehicleIdentity &) const = default;
};

// Something the vehicle does at a waypoint, in the words of Sortie's VCI profile
// (docs/vci-profile.md, "Mission actions"): `type` is "wait", "heading", "poi", "camera",
// "camera_by_time", "camera_by_distance", "panorama", "gimbal" or "land"; `parameters` hold its numbers and
// names exactly as the profile sends them (SI units, radians): only a VCI mission carries actions, and
// the VCI planner and link are the only code that reads or writes them.
struct MissionAction
{
    QString type;
    QVariantMap parameters;

    bool operator==(const MissionAction &) const = default;
};

// One waypoint of the mission a vehicle carries, in the form both links upload and download.
struct MissionItem
{
    double latitude = 0;         // deg (the links convert to what their protocol sends)
    double longitude = 0;        // deg
    double altitude = 0;         // m above the home point
    double speed = 0;            // m/s towards it; 0: the vehicle's default
    double acceptanceRadius = 0; // m: how close counts as reached; 0: the vehicle's default
    std::vector<MissionAction> actions; // in order, once the waypoint is reached

    bool operator==(const MissionItem &) const = default;
};

// The outcome of a command: ok, or a message an operator understands. `cancelled` marks a
// failure the operator asked for.
struct CommandResult
{
    bool ok = true;
    QString message;
    bool cancelled = false;

    static CommandResult success() { return {}; }
    static CommandResult failure(QString why) { return {false, std::move(why)}; }
    static CommandResult cancel() { return {false, QStringLiteral("cancelled"), true}; }
};

// A link's own form of a prepared mission (the UgCS server's processed route, for HCI). Only the
// link that prepared it reads it.
struct NativeMission
{
    virtual ~NativeMission() = default;
};

// A route made ready for one vehicle (VehicleLink::prepareMission): what the vehicle will fly, and
// what the processing said that the operator should read before it goes up.
struct PreparedMission
{
    std::vector<MissionItem> items;
    QStringList notices;
    std::shared_ptr<const NativeMission> native;
};

// What a vehicle does when it breaks its fence: fly home and land, land where it is, or hover.
enum class FenceBreachAction { Return, Land, Hold };

// What a vehicle's fence is made of beside the route's own: the airspace's zones, opaque here and to
// the client. Only the fence builder a link is handed reads them (VciFencePlan.h).
class FenceZones
{
public:
    virtual ~FenceZones() = default;
};

// What goes up with a route to a vehicle that keeps a fence (VehicleLink::Fence): the route's own
// fence (Route::fence) joined by the active zones of `zones` whose box meets the route's, and the
// breach action. Links whose vehicle keeps none ignore it.
struct FenceSettings
{
    std::shared_ptr<const FenceZones> zones; // null: the route's own fence only
    FenceBreachAction breachAction = FenceBreachAction::Return;
};

// A photo the vehicle's camera took, as its link reports it: when (the vehicle's clock), where and
// how it stood. A value the vehicle did not report is NaN, never 0.
struct CameraPhoto
{
    qint64 sequence = 0;   // 1, 2, 3 ... as the vehicle counts them: a gap says photos were not heard of
    qint64 time = 0;       // ms since the epoch, the vehicle's clock
    double latitude = qQNaN(), longitude = qQNaN(); // degrees
    double altitudeAmsl = qQNaN();
    double altitudeAgl = qQNaN();  // m above the ground under it
    double roll = qQNaN(), pitch = qQNaN(), yaw = qQNaN(); // degrees, yaw = heading
    double gimbalTilt = qQNaN();   // degrees: 90 looks straight down, 0 ahead (UgCS's convention)
};

// The stages of an upload inside a link, for progress.
enum class UploadStep { Locking, Sending, Releasing };

} // namespace sortie::vehicle

Q_DECLARE_METATYPE(sortie::vehicle::VehicleIdentity)
Q_DECLARE_METATYPE(sortie::vehicle::CommandResult)
Q_DECLARE_METATYPE(sortie::vehicle::CameraPhoto)
