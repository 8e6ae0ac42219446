#pragma once

#include <QMetaType>
#include <QString>

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

// One waypoint of the mission a vehicle carries, in the form both links upload and download.
struct MissionItem
{
    double latitude = 0;  // rad
    double longitude = 0; // rad
    double altitude = 0;  // m above the home point
    double speed = 0;     // m/s towards it; 0: the vehicle's default

    bool operator==(const MissionItem &) const = default;
};

// The outcome of a command: ok, or a message an operator understands.
struct CommandResult
{
    bool ok = true;
    QString message;

    static CommandResult success() { return {}; }
    static CommandResult failure(QString why) { return {false, std::move(why)}; }
};

} // namespace sortie::vehicle

Q_DECLARE_METATYPE(sortie::vehicle::VehicleIdentity)
Q_DECLARE_METATYPE(sortie::vehicle::CommandResult)
