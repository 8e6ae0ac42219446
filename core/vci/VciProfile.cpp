#include "VciProfile.h"

#include <cmath>

namespace sortie::vci::profile {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

bool isMode(std::string_view name)
{
    for (std::string_view m : kModes) {
        if (m == name)
            return true;
    }
    return false;
}

std::optional<double> number(const nlohmann::json &object, const char *key)
{
    if (!object.is_object())
        return std::nullopt;
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number())
        return std::nullopt;
    return it->get<double>();
}

nlohmann::json encodeMission(const std::vector<Waypoint> &waypoints)
{
    nlohmann::json list = nlohmann::json::array();
    for (const Waypoint &w : waypoints)
        list.push_back({{"latitude", w.latitude}, {"longitude", w.longitude}, {"altitude", w.altitude}, {"speed", w.speed}});
    return {{"waypoints", std::move(list)}};
}

std::optional<std::vector<Waypoint>> decodeMission(const nlohmann::json &body, std::string *error)
{
    auto fail = [error](std::string why) -> std::optional<std::vector<Waypoint>> {
        if (error)
            *error = std::move(why);
        return std::nullopt;
    };
    if (!body.is_object() || !body.contains("waypoints") || !body["waypoints"].is_array())
        return fail("the body must be an object with a \"waypoints\" array");
    std::vector<Waypoint> out;
    const auto &list = body["waypoints"];
    out.reserve(list.size());
    for (size_t i = 0; i < list.size(); ++i) {
        const auto &w = list[i];
        const std::string at = "waypoints[" + std::to_string(i) + "]";
        if (!w.is_object())
            return fail(at + ": must be an object");
        Waypoint p;
        const auto lat = number(w, "latitude"), lon = number(w, "longitude"), alt = number(w, "altitude");
        if (!lat || std::abs(*lat) > kPi / 2)
            return fail(at + ".latitude: must be a number of radians in [-pi/2, pi/2]");
        if (!lon || std::abs(*lon) > kPi)
            return fail(at + ".longitude: must be a number of radians in [-pi, pi]");
        if (!alt || !std::isfinite(*alt))
            return fail(at + ".altitude: must be a number of metres above home");
        p.latitude = *lat;
        p.longitude = *lon;
        p.altitude = *alt;
        if (w.contains("speed")) {
            const auto speed = number(w, "speed");
            if (!speed || *speed < 0)
                return fail(at + ".speed: must be a number of m/s, 0 or more");
            p.speed = *speed;
        }
        out.push_back(p);
    }
    return out;
}

} // namespace sortie::vci::profile
