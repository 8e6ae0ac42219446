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
    for (const Waypoint &w : waypoints) {
        nlohmann::json point = {{"latitude", w.latitude}, {"longitude", w.longitude}, {"altitude", w.altitude}, {"speed", w.speed}};
        if (w.acceptanceRadius > 0)
            point["acceptanceRadius"] = w.acceptanceRadius;
        if (!w.actions.empty()) {
            nlohmann::json actions = nlohmann::json::array();
            for (const Action &a : w.actions) {
                nlohmann::json action = a.fields.is_object() ? a.fields : nlohmann::json::object();
                action["type"] = a.type;
                actions.push_back(std::move(action));
            }
            point["actions"] = std::move(actions);
        }
        list.push_back(std::move(point));
    }
    return {{"waypoints", std::move(list)}};
}

namespace {

enum class Kind { Number, NonNegative, Angle, Flag, Name };
struct Field
{
    const char *name;
    Kind kind;
    bool required;
    std::array<const char *, 4> names = {}; // the allowed values of a Name
};
struct ActionRule
{
    std::string_view type;
    std::vector<Field> fields;
};

const std::vector<ActionRule> &actionRules()
{
    static const std::vector<ActionRule> rules = {
        {"wait", {{"seconds", Kind::NonNegative, true}}},
        {"heading", {{"heading", Kind::Angle, true}, {"relativeToNext", Kind::Flag, false}}},
        {"poi", {{"latitude", Kind::Angle, true}, {"longitude", Kind::Angle, true}, {"altitude", Kind::Number, true}}},
        {"camera", {{"state", Kind::Name, true, {"single", "start_recording", "stop_recording", "toggle_recording"}}}},
        {"camera_by_time", {{"interval", Kind::NonNegative, true}, {"shots", Kind::NonNegative, false}, {"delay", Kind::NonNegative, false}}},
        {"camera_by_distance", {{"interval", Kind::NonNegative, true}, {"shots", Kind::NonNegative, false}, {"delay", Kind::NonNegative, false}}},
        {"panorama", {{"angle", Kind::Angle, true}, {"step", Kind::Angle, true}, {"stepDelay", Kind::NonNegative, false},
                      {"direction", Kind::Name, false, {"cw", "ccw"}}, {"rate", Kind::NonNegative, false},
                      {"mode", Kind::Name, false, {"photo", "video"}}}},
        {"gimbal", {{"tilt", Kind::Angle, false}, {"roll", Kind::Angle, false}, {"yaw", Kind::Angle, false},
                    {"zoom", Kind::NonNegative, false}}},
        {"land", {}},
    };
    return rules;
}

// Empty when the action object is one of the profile's; otherwise why not, after `at`.
std::string actionProblem(const nlohmann::json &a, const std::string &at, Action *out)
{
    if (!a.is_object())
        return at + ": must be an object";
    const auto type = a.find("type");
    if (type == a.end() || !type->is_string())
        return at + ".type: must name the action";
    const std::string name = type->get<std::string>();
    for (const ActionRule &rule : actionRules()) {
        if (rule.type != name)
            continue;
        out->type = name;
        out->fields = nlohmann::json::object();
        for (const Field &f : rule.fields) {
            const auto v = a.find(f.name);
            const std::string where = at + "." + f.name;
            if (v == a.end()) {
                if (f.required)
                    return where + ": missing";
                continue;
            }
            switch (f.kind) {
            case Kind::Number:
            case Kind::Angle:
                if (!v->is_number() || !std::isfinite(v->get<double>()))
                    return where + (f.kind == Kind::Angle ? ": must be a number of radians" : ": must be a number");
                break;
            case Kind::NonNegative:
                if (!v->is_number() || !(v->get<double>() >= 0))
                    return where + ": must be a number, 0 or more";
                break;
            case Kind::Flag:
                if (!v->is_boolean())
                    return where + ": must be true or false";
                break;
            case Kind::Name: {
                bool known = false;
                for (const char *n : f.names)
                    known = known || (n && v->is_string() && v->get<std::string>() == n);
                if (!known)
                    return where + ": not one of the names the profile lists";
                break;
            }
            }
            out->fields[f.name] = *v;
        }
        return {};
    }
    return at + ".type: \"" + name + "\" is not an action of this profile";
}

} // namespace

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
        if (w.contains("acceptanceRadius")) {
            const auto radius = number(w, "acceptanceRadius");
            if (!radius || *radius < 0)
                return fail(at + ".acceptanceRadius: must be a number of metres, 0 or more");
            p.acceptanceRadius = *radius;
        }
        if (w.contains("actions")) {
            const auto &actions = w["actions"];
            if (!actions.is_array())
                return fail(at + ".actions: must be an array");
            for (size_t k = 0; k < actions.size(); ++k) {
                Action action;
                std::string problem = actionProblem(actions[k], at + ".actions[" + std::to_string(k) + "]", &action);
                if (!problem.empty())
                    return fail(std::move(problem));
                p.actions.push_back(std::move(action));
            }
        }
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace sortie::vci::profile
