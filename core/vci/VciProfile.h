#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Sortie's VCI resource profile (docs/vci-profile.md): the URIs a vehicle offers, and the one body
// that needs more than a field lookup, the mission's waypoint list. Shared by the client and the
// simulated vehicles. SI units; angles in radians; times in ms since the epoch. Pure: no Qt.
namespace sortie::vci::profile {

inline constexpr std::string_view kVehicle = "/vehicle";
inline constexpr std::string_view kPosition = "/telemetry/position";
inline constexpr std::string_view kAttitude = "/telemetry/attitude";
inline constexpr std::string_view kSpeed = "/telemetry/speed";
inline constexpr std::string_view kBattery = "/telemetry/battery";
inline constexpr std::string_view kGps = "/telemetry/gps";
inline constexpr std::string_view kHome = "/telemetry/home";
inline constexpr std::string_view kArmed = "/state/armed";
inline constexpr std::string_view kMode = "/state/mode";
inline constexpr std::string_view kTakeoff = "/command/takeoff";
inline constexpr std::string_view kLand = "/command/land";
inline constexpr std::string_view kReturnHome = "/command/return-home";
inline constexpr std::string_view kGoto = "/command/goto";
inline constexpr std::string_view kMission = "/mission";
inline constexpr std::string_view kMissionProgress = "/mission/progress";
inline constexpr std::string_view kParameters = "/parameters";
inline constexpr std::string_view kParameterPrefix = "/parameters/";
inline constexpr std::string_view kFence = "/fence";              // VciFence.h
inline constexpr std::string_view kFenceStatus = "/fence/status"; // is the vehicle inside its fence
inline constexpr std::string_view kCameraPhoto = "/camera/photo"; // the last photo taken (VciPhoto.h)

// Sent at the vehicle's telemetry rate while subscribed.
inline constexpr std::array<std::string_view, 6> kTelemetry = {kPosition, kAttitude, kSpeed, kBattery, kGps, kHome};
// Sent when they change while subscribed (and once right after SUBSCRIBE).
inline constexpr std::array<std::string_view, 7> kState = {kArmed, kMode, kMission, kMissionProgress, kFence, kFenceStatus, kCameraPhoto};
// Of those, the ones also repeated at least every kStatusRepeatMs, so a silent vehicle shows as stale.
inline constexpr std::array<std::string_view, 4> kStatus = {kArmed, kMode, kMissionProgress, kFenceStatus};
inline constexpr int kStatusRepeatMs = 1000;

// The flight modes, as /state/mode names them.
inline constexpr std::array<std::string_view, 7> kModes = {"manual", "hold", "takeoff", "auto", "guided", "land", "return_home"};
bool isMode(std::string_view name);

// Something done at a waypoint once it is reached (docs/vci-profile.md, "Mission actions"): `type`
// names it, `fields` is the rest of its JSON object (numbers in SI units and radians, names).
struct Action
{
    std::string type;
    nlohmann::json fields = nlohmann::json::object();
};

// The action types of the profile, in the order the document lists them.
inline constexpr std::array<std::string_view, 9> kActionTypes = {"wait", "heading", "poi", "camera", "camera_by_time",
                                                                  "camera_by_distance", "panorama", "gimbal", "land"};

struct Waypoint
{
    double latitude = 0;  // radians
    double longitude = 0; // radians
    double altitude = 0;  // metres above the home point
    double speed = 0;     // m/s towards this waypoint; 0: the vehicle's default
    double acceptanceRadius = 0; // metres; 0: the vehicle's default
    std::vector<Action> actions;
};

// {"waypoints":[{"latitude":..,"longitude":..,"altitude":..,"speed":..,"acceptanceRadius":..,
//  "actions":[{"type":"wait","seconds":5}, ...]}, ...]}
nlohmann::json encodeMission(const std::vector<Waypoint> &waypoints);
// The waypoints, or nullopt and an error that names the JSON path ("waypoints[2].latitude: ...").
std::optional<std::vector<Waypoint>> decodeMission(const nlohmann::json &body, std::string *error);

// A number from an object field, or nullopt when absent or not a number.
std::optional<double> number(const nlohmann::json &object, const char *key);

} // namespace sortie::vci::profile
