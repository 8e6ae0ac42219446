#include "VciFence.h"

#include <algorithm>
#include <cmath>

namespace sortie::vci::profile {

namespace {

constexpr double kPi = 3.14159265358979323846;
using nlohmann::json;

// A failure with its path, as decodeMission reports one.
struct Failure
{
    std::string why;
};

const json *member(const json &object, const char *key)
{
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

double angle(const json &object, const char *key, double limit, const std::string &at)
{
    const json *v = member(object, key);
    if (!v || !v->is_number() || !(std::abs(v->get<double>()) <= limit))
        throw Failure{at + "." + key + (limit < 2 ? ": must be a number of radians in [-pi/2, pi/2]" : ": must be a number of radians in [-pi, pi]")};
    return v->get<double>();
}

FenceVertex vertex(const json &v, const std::string &at)
{
    if (!v.is_object())
        throw Failure{at + ": must be an object with latitude and longitude"};
    return {angle(v, "latitude", kPi / 2, at), angle(v, "longitude", kPi, at)};
}

std::optional<FenceLimit> limit(const json &item, const char *key, const std::string &at)
{
    const json *v = member(item, key);
    if (!v || v->is_null())
        return std::nullopt;
    const std::string where = at + "." + key;
    if (!v->is_object())
        throw Failure{where + ": must be an object with altitude and reference"};
    const json *altitude = member(*v, "altitude");
    if (!altitude || !altitude->is_number() || !std::isfinite(altitude->get<double>()))
        throw Failure{where + ".altitude: must be a number of metres"};
    const json *reference = member(*v, "reference");
    FenceLimit out{altitude->get<double>(), FenceReference::Amsl};
    if (!reference || !reference->is_string())
        throw Failure{where + ".reference: must be \"amsl\" or \"home\""};
    const std::string name = reference->get<std::string>();
    if (name == "home")
        out.reference = FenceReference::Home;
    else if (name != "amsl")
        throw Failure{where + ".reference: \"" + name + "\" is not \"amsl\" or \"home\" (AGL limits are converted by the client)"};
    return out;
}

FenceItem item(const json &v, const std::string &at, size_t *vertices)
{
    if (!v.is_object())
        throw Failure{at + ": must be an object"};
    FenceItem out;
    const json *kind = member(v, "kind");
    if (!kind || !kind->is_string() || (kind->get<std::string>() != "inclusion" && kind->get<std::string>() != "exclusion"))
        throw Failure{at + ".kind: must be \"inclusion\" or \"exclusion\""};
    out.kind = kind->get<std::string>() == "inclusion" ? FenceKind::Inclusion : FenceKind::Exclusion;
    if (const json *name = member(v, "name")) {
        if (!name->is_string())
            throw Failure{at + ".name: must be a string"};
        out.name = name->get<std::string>();
        if (out.name.size() > kMaxFenceNameLength)
            throw Failure{at + ".name: longer than " + std::to_string(kMaxFenceNameLength) + " bytes"};
    }
    const json *polygon = member(v, "polygon");
    const json *circle = member(v, "circle");
    if (bool(polygon) == bool(circle))
        throw Failure{at + ": must have either a \"polygon\" or a \"circle\""};
    if (polygon) {
        if (!polygon->is_array() || polygon->size() < 3)
            throw Failure{at + ".polygon: must be an array of 3 or more vertices"};
        if (polygon->size() > kMaxPolygonVertices)
            throw Failure{at + ".polygon: " + std::to_string(polygon->size()) + " vertices, more than the "
                          + std::to_string(kMaxPolygonVertices) + " a polygon may have"};
        *vertices += polygon->size();
        if (*vertices > kMaxFenceVertices)
            throw Failure{at + ".polygon: the fence has more than the " + std::to_string(kMaxFenceVertices) + " vertices it may have"};
        for (size_t i = 0; i < polygon->size(); ++i)
            out.polygon.push_back(vertex((*polygon)[i], at + ".polygon[" + std::to_string(i) + "]"));
    } else {
        if (!circle->is_object())
            throw Failure{at + ".circle: must be an object with latitude, longitude and radius"};
        out.center = vertex(*circle, at + ".circle");
        const json *radius = member(*circle, "radius");
        if (!radius || !radius->is_number() || !(radius->get<double>() > 0) || !std::isfinite(radius->get<double>()))
            throw Failure{at + ".circle.radius: must be a number of metres above 0"};
        out.radius = radius->get<double>();
    }
    out.floor = limit(v, "floor", at);
    out.ceiling = limit(v, "ceiling", at);
    if (out.floor && out.ceiling && out.floor->reference == out.ceiling->reference && !(out.ceiling->altitude > out.floor->altitude))
        throw Failure{at + ".ceiling: must be above the floor"};
    return out;
}

json limitJson(const FenceLimit &l)
{
    return {{"altitude", l.altitude}, {"reference", std::string(fenceReferenceName(l.reference))}};
}

json vertexJson(const FenceVertex &v)
{
    return {{"latitude", v.latitude}, {"longitude", v.longitude}};
}

} // namespace

std::string_view fenceKindName(FenceKind kind)
{
    return kind == FenceKind::Inclusion ? "inclusion" : "exclusion";
}

std::string_view fenceReferenceName(FenceReference ref)
{
    return ref == FenceReference::Home ? "home" : "amsl";
}

std::string_view breachActionName(BreachAction action)
{
    switch (action) {
    case BreachAction::Return: return "return";
    case BreachAction::Land: return "land";
    case BreachAction::Hold: return "hold";
    }
    return "return";
}

std::optional<BreachAction> breachActionFromName(std::string_view name)
{
    for (BreachAction a : {BreachAction::Return, BreachAction::Land, BreachAction::Hold})
        if (breachActionName(a) == name)
            return a;
    return std::nullopt;
}

json encodeFence(const Fence &fence)
{
    json items = json::array();
    for (const FenceItem &i : fence.items) {
        json item = {{"kind", std::string(fenceKindName(i.kind))}};
        if (!i.name.empty())
            item["name"] = i.name;
        if (i.center) {
            json circle = vertexJson(*i.center);
            circle["radius"] = i.radius;
            item["circle"] = std::move(circle);
        } else {
            json polygon = json::array();
            for (const FenceVertex &v : i.polygon)
                polygon.push_back(vertexJson(v));
            item["polygon"] = std::move(polygon);
        }
        if (i.floor)
            item["floor"] = limitJson(*i.floor);
        if (i.ceiling)
            item["ceiling"] = limitJson(*i.ceiling);
        items.push_back(std::move(item));
    }
    return {{"items", std::move(items)}, {"breachAction", std::string(breachActionName(fence.breachAction))}};
}

std::optional<Fence> decodeFence(const json &body, std::string *error)
{
    try {
        if (!body.is_object())
            throw Failure{"the body must be an object with an \"items\" array"};
        const json *items = member(body, "items");
        if (!items || !items->is_array())
            throw Failure{"items: must be an array (empty for no fence)"};
        if (items->size() > kMaxFenceItems)
            throw Failure{"items: " + std::to_string(items->size()) + " items, more than the " + std::to_string(kMaxFenceItems)
                          + " a fence may hold"};
        Fence fence;
        if (const json *action = member(body, "breachAction")) {
            const auto a = action->is_string() ? breachActionFromName(action->get<std::string>()) : std::nullopt;
            if (!a)
                throw Failure{"breachAction: must be \"return\", \"land\" or \"hold\""};
            fence.breachAction = *a;
        }
        size_t vertices = 0;
        for (size_t i = 0; i < items->size(); ++i)
            fence.items.push_back(item((*items)[i], "items[" + std::to_string(i) + "]", &vertices));
        return fence;
    } catch (const Failure &f) {
        if (error)
            *error = f.why;
        return std::nullopt;
    }
}

std::string fenceLimitProblem(const Fence &fence)
{
    if (fence.items.size() > kMaxFenceItems)
        return std::to_string(fence.items.size()) + " fence items, more than the " + std::to_string(kMaxFenceItems) + " a vehicle takes";
    size_t vertices = 0;
    for (const FenceItem &i : fence.items) {
        if (i.polygon.size() > kMaxPolygonVertices)
            return "fence item '" + i.name + "' has " + std::to_string(i.polygon.size()) + " vertices, more than the "
                   + std::to_string(kMaxPolygonVertices) + " a vehicle takes";
        vertices += i.polygon.size();
    }
    if (vertices > kMaxFenceVertices)
        return std::to_string(vertices) + " fence vertices, more than the " + std::to_string(kMaxFenceVertices) + " a vehicle takes";
    return {};
}

json encodeFenceStatus(const FenceStatus &s)
{
    json out = {{"state", s.state}, {"breaches", s.breaches}, {"item", s.item}, {"time", s.time}};
    if (!s.name.empty())
        out["name"] = s.name;
    if (!s.kind.empty())
        out["kind"] = s.kind;
    if (!s.action.empty())
        out["action"] = s.action;
    return out;
}

std::optional<FenceStatus> decodeFenceStatus(const json &body)
{
    if (!body.is_object())
        return std::nullopt;
    const json *state = member(body, "state");
    if (!state || !state->is_string())
        return std::nullopt;
    FenceStatus s;
    s.state = state->get<std::string>();
    const auto text = [&body](const char *key) {
        const json *v = member(body, key);
        return v && v->is_string() ? v->get<std::string>() : std::string();
    };
    const auto integer = [&body](const char *key, int64_t fallback) {
        const json *v = member(body, key);
        return v && v->is_number() && std::isfinite(v->get<double>()) && std::abs(v->get<double>()) < 9e15 ? int64_t(v->get<double>()) : fallback;
    };
    s.breaches = int(std::clamp<int64_t>(integer("breaches", 0), 0, 1 << 30));
    s.item = int(std::clamp<int64_t>(integer("item", -1), -1, 1 << 30));
    s.time = integer("time", 0);
    s.name = text("name");
    s.kind = text("kind");
    s.action = text("action");
    return s;
}

} // namespace sortie::vci::profile
