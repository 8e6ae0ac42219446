#pragma once

#include "TelemetryBlockCodec.h"
#include "VehicleTypes.h"

#include <QString>

#include <memory>
#include <vector>

namespace sortie::flightlog {

// What the recorder hands the writer thread each flush: everything seen since the last one.
// Vehicles are named by a key that stays the same for the session ("HCI:12", "VCI:emu-1").
struct RecordedVehicle
{
    QString key;
    vehicle::VehicleIdentity identity;
};

// Something that happened, for the timeline's jump list and `sortie-log info`.
struct RecordedEvent
{
    QString vehicleKey; // empty: the session's, not one vehicle's
    int64_t time = 0;   // ms since the epoch
    QString kind;       // "link", "armed", "disarmed", "mode", "command", "upload", "session"
    QString text;
    int ok = -1;        // commands: 1 done, 0 failed; -1 otherwise
};

struct RecordedMission
{
    QString vehicleKey;
    int64_t time = 0;
    std::vector<vehicle::MissionItem> items;
};

struct RecordedSamples
{
    QString vehicleKey;
    BlockFields fields;
};

struct RecordingChunk
{
    std::vector<RecordedVehicle> vehicles; // new ones and changed identities
    std::vector<RecordedSamples> samples;
    std::vector<RecordedEvent> events;
    std::vector<RecordedMission> missions;

    bool empty() const { return vehicles.empty() && samples.empty() && events.empty() && missions.empty(); }
};

} // namespace sortie::flightlog
