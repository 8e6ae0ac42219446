#include "TelemetryField.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace sortie::vehicle {
namespace {

struct FieldInfo
{
    std::string_view name;
    std::string_view unit;
};

constexpr std::array<FieldInfo, kTelemetryFieldCount> kFields = {{
    {"latitude", "deg"}, {"longitude", "deg"}, {"altitudeAmsl", "m"}, {"altitudeAgl", "m"},
    {"roll", "deg"}, {"pitch", "deg"}, {"heading", "deg"}, {"course", "deg"},
    {"groundSpeed", "m/s"}, {"airSpeed", "m/s"}, {"verticalSpeed", "m/s"},
    {"batteryVoltage", "V"}, {"batteryCurrent", "A"}, {"batteryRemaining", ""},
    {"gpsFix", ""}, {"satellites", ""}, {"hdop", ""},
    {"homeLatitude", "deg"}, {"homeLongitude", "deg"}, {"homeAltitudeAmsl", "m"},
    {"armed", ""}, {"mode", ""}, {"missionState", ""}, {"missionCurrent", ""}, {"missionReached", ""}, {"missionCount", ""},
    {"fenceBreach", ""}, {"fenceBreaches", ""},
}};

constexpr std::array<std::string_view, 8> kModes = {"unknown", "manual", "hold", "takeoff", "auto", "guided", "land", "return_home"};
constexpr std::array<std::string_view, 4> kMissionStates = {"idle", "active", "paused", "complete"};

} // namespace

std::string_view fieldName(TelemetryField field)
{
    return size_t(field) < kFields.size() ? kFields[size_t(field)].name : std::string_view("?");
}

std::string_view fieldUnit(TelemetryField field)
{
    return size_t(field) < kFields.size() ? kFields[size_t(field)].unit : std::string_view();
}

bool isAngle(TelemetryField field)
{
    return fieldUnit(field) == "deg";
}

std::optional<TelemetryField> fieldFromName(std::string_view name)
{
    for (size_t i = 0; i < kFields.size(); ++i) {
        if (kFields[i].name == name)
            return TelemetryField(i);
    }
    return std::nullopt;
}

std::string_view modeName(FlightMode mode)
{
    return size_t(mode) < kModes.size() ? kModes[size_t(mode)] : kModes[0];
}

FlightMode modeFromName(std::string_view name)
{
    std::string n(name);
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    std::replace(n.begin(), n.end(), '-', '_');
    for (size_t i = 1; i < kModes.size(); ++i) {
        if (kModes[i] == n)
            return FlightMode(i);
    }
    if (n == "stabilize" || n == "stabilized" || n == "joystick" || n == "acro" || n == "altctl" || n == "posctl")
        return FlightMode::Manual;
    if (n == "loiter" || n == "pause" || n == "paused" || n == "brake" || n == "position_hold")
        return FlightMode::Hold;
    if (n == "mission" || n == "automatic")
        return FlightMode::Auto;
    if (n == "click_go" || n == "offboard" || n == "goto")
        return FlightMode::Guided;
    if (n == "rtl" || n == "rth" || n == "return" || n == "return_to_home" || n == "return_to_launch")
        return FlightMode::ReturnHome;
    if (n == "landing" || n == "emergency_land")
        return FlightMode::Land;
    return FlightMode::Unknown;
}

std::string_view missionStateName(MissionState state)
{
    return size_t(state) < kMissionStates.size() ? kMissionStates[size_t(state)] : kMissionStates[0];
}

std::optional<MissionState> missionStateFromName(std::string_view name)
{
    for (size_t i = 0; i < kMissionStates.size(); ++i) {
        if (kMissionStates[i] == name)
            return MissionState(i);
    }
    return std::nullopt;
}

} // namespace sortie::vehicle
