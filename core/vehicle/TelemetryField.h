#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace sortie::vehicle {

// Every telemetry value the client knows, whatever protocol brought it. Units are SI, angles in
// radians (as HCI and Sortie's VCI profile send them), times in ms since the epoch. Values are
// doubles; booleans are 0/1 and enumerations their number (FlightMode, MissionState, GPS fix).
enum class TelemetryField : uint8_t {
    Latitude,          // rad, WGS-84
    Longitude,         // rad
    AltitudeAmsl,      // m above mean sea level
    AltitudeAgl,       // m above the home point's ground
    Roll,              // rad, right wing down positive
    Pitch,             // rad, nose up positive
    Heading,           // rad from north, clockwise: where the nose points
    Course,            // rad from north, clockwise: where it travels
    GroundSpeed,       // m/s
    AirSpeed,          // m/s
    VerticalSpeed,     // m/s, up positive
    BatteryVoltage,    // V
    BatteryCurrent,    // A
    BatteryRemaining,  // 0..1
    GpsFix,            // 0 none, 2 2D, 3 3D, 4 RTK float, 5 RTK fixed
    Satellites,        // count
    Hdop,              // horizontal dilution of precision
    HomeLatitude,      // rad
    HomeLongitude,     // rad
    HomeAltitudeAmsl,  // m
    Armed,             // 0 or 1
    Mode,              // FlightMode
    MissionState,      // MissionState
    MissionCurrent,    // index of the waypoint being flown to, -1 for none
    MissionReached,    // waypoints reached so far
    MissionCount,      // waypoints in the mission on board
    Count_
};

inline constexpr size_t kTelemetryFieldCount = size_t(TelemetryField::Count_);

// "latitude", "groundSpeed", ... the names QML and logs use.
std::string_view fieldName(TelemetryField field);
std::string_view fieldUnit(TelemetryField field); // "rad", "m", "m/s", "V", "A", "", ...
std::optional<TelemetryField> fieldFromName(std::string_view name);

enum class FlightMode : uint8_t { Unknown, Manual, Hold, Takeoff, Auto, Guided, Land, ReturnHome };
std::string_view modeName(FlightMode mode); // "manual", "hold", ..., "return_home"; "unknown"
// Understands Sortie's VCI names and the usual autopilot spellings ("loiter", "rtl", "mission", ...).
FlightMode modeFromName(std::string_view name);

enum class MissionState : uint8_t { Idle, Active, Paused, Complete };
std::string_view missionStateName(MissionState state);
std::optional<MissionState> missionStateFromName(std::string_view name);

} // namespace sortie::vehicle
