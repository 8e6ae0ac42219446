#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace sortie::vehicle {

// Every telemetry value the client knows, whatever protocol brought it. Units are SI except angles,
// which are degrees: HCI and Sortie's VCI profile send radians, and the links convert once, at their
// edge (HciTelemetryMapper, VciTelemetryMapper), so nothing past a link converts. Times in ms since
// the epoch. Values are doubles; booleans are 0/1 and enumerations their number (FlightMode,
// MissionState, GPS fix).
enum class TelemetryField : uint8_t {
    Latitude,          // deg, WGS-84
    Longitude,         // deg
    AltitudeAmsl,      // m above mean sea level
    AltitudeAgl,       // m above the home point's ground
    Roll,              // deg, right wing down positive
    Pitch,             // deg, nose up positive
    Heading,           // deg from north, clockwise: where the nose points
    Course,            // deg from north, clockwise: where it travels
    GroundSpeed,       // m/s
    AirSpeed,          // m/s
    VerticalSpeed,     // m/s, up positive
    BatteryVoltage,    // V
    BatteryCurrent,    // A
    BatteryRemaining,  // 0..1
    GpsFix,            // 0 none, 2 2D, 3 3D, 4 RTK float, 5 RTK fixed
    Satellites,        // count
    Hdop,              // horizontal dilution of precision
    HomeLatitude,      // deg
    HomeLongitude,     // deg
    HomeAltitudeAmsl,  // m
    Armed,             // 0 or 1
    Mode,              // FlightMode
    MissionState,      // MissionState
    MissionCurrent,    // index of the waypoint being flown to, -1 for none
    MissionReached,    // waypoints reached so far
    MissionCount,      // waypoints in the mission on board
    FenceBreach,       // 1 while the vehicle is outside its fence (VCI /fence/status), else 0
    FenceBreaches,     // breaches since the fence was set
    Count_
};

inline constexpr size_t kTelemetryFieldCount = size_t(TelemetryField::Count_);

// "latitude", "groundSpeed", ... the names QML and logs use.
std::string_view fieldName(TelemetryField field);
std::string_view fieldUnit(TelemetryField field); // "deg", "m", "m/s", "V", "A", "", ...
// Latitudes, longitudes, attitude, heading and course: the fields in degrees.
bool isAngle(TelemetryField field);

// The one conversion, for the links' edges (the protocols speak radians). π spelled out: moc reads
// this header and cannot parse <numbers>.
inline constexpr double kPi = 3.14159265358979323846;
constexpr double degreesFromRadians(double radians) { return radians * (180.0 / kPi); }
constexpr double radiansFromDegrees(double degrees) { return degrees * (kPi / 180.0); }
std::optional<TelemetryField> fieldFromName(std::string_view name);

enum class FlightMode : uint8_t { Unknown, Manual, Hold, Takeoff, Auto, Guided, Land, ReturnHome };
std::string_view modeName(FlightMode mode); // "manual", "hold", ..., "return_home"; "unknown"
// Understands Sortie's VCI names and the usual autopilot spellings ("loiter", "rtl", "mission", ...).
FlightMode modeFromName(std::string_view name);

enum class MissionState : uint8_t { Idle, Active, Paused, Complete };
std::string_view missionStateName(MissionState state);
std::optional<MissionState> missionStateFromName(std::string_view name);

} // namespace sortie::vehicle
