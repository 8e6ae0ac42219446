#include "SortieMigrations.h"

#include <functional>
#include <vector>

namespace sortie::mission::formats {

namespace {
// Schema 1, the first draft: routes were plain waypoint lists
// ({"waypoints": [{"lat", "lon", "alt", "altitudeType"}], "speed"}), with no area scans, actions
// or per-waypoint speeds. Schema 2 has typed segments.
void v1ToV2(Json &doc)
{
    Json &mission = doc["mission"];
    if (!mission.is_object() || !mission["routes"].is_array())
        throw JsonPathError{"/mission/routes", QStringLiteral("schema 1 document without a routes array")};
    for (size_t r = 0; r < mission["routes"].size(); ++r) {
        Json &route = mission["routes"][r];
        const std::string at = "/mission/routes/" + std::to_string(r);
        if (!route.is_object() || !route["waypoints"].is_array())
            throw JsonPathError{at + "/waypoints", QStringLiteral("schema 1 route without a waypoints array")};
        const Json speed = route.contains("speed") ? route["speed"] : Json(5.0);
        Json segments = Json::array();
        for (size_t i = 0; i < route["waypoints"].size(); ++i) {
            const Json &w = route["waypoints"][i];
            if (!w.is_object() || !w.contains("lat") || !w.contains("lon") || !w.contains("alt"))
                throw JsonPathError{at + "/waypoints/" + std::to_string(i), QStringLiteral("schema 1 waypoint needs lat, lon and alt")};
            segments.push_back({{"type", "waypoint"}, {"latitude", w["lat"]}, {"longitude", w["lon"]},
                                {"altitude", w["alt"]}, {"altitudeType", w.contains("altitudeType") ? w["altitudeType"] : Json("AGL")}, {"speed", speed}});
        }
        route.erase("waypoints");
        route.erase("speed");
        route["initialSpeed"] = speed;
        route["segments"] = std::move(segments);
    }
}

// Schema 3 names an area scan's parameters the way UgCS does (the wire names of the facts file),
// under "parameters": altitude -> height, groundSampleDistanceCm -> groundSampleDistance,
// frontOverlapPercent -> overlapForward, sideOverlapPercent -> overlapSide, directionDeg ->
// directionAngle, turnaroundMeters -> overshoot; and adds sideDistance (0: from the camera).
// Segments of other algorithms ("algorithm") are new in schema 3.
void v2ToV3(Json &doc)
{
    static const std::pair<const char *, const char *> kRenames[] = {
        {"altitude", "height"}, {"groundSampleDistanceCm", "groundSampleDistance"}, {"altitudeType", "altitudeType"},
        {"frontOverlapPercent", "overlapForward"}, {"sideOverlapPercent", "overlapSide"}, {"directionDeg", "directionAngle"},
        {"turnaroundMeters", "overshoot"}, {"speed", "speed"}};
    Json &routes = doc["mission"]["routes"];
    if (!routes.is_array())
        throw JsonPathError{"/mission/routes", QStringLiteral("schema 2 document without a routes array")};
    for (size_t r = 0; r < routes.size(); ++r) {
        Json &segments = routes[r]["segments"];
        if (!segments.is_array())
            continue;  // the reader names what is missing
        for (Json &segment : segments) {
            // Compared as JSON: a "type" that is no string is the reader's to name, not a throw here.
            if (!segment.is_object() || !segment.contains("type") || segment["type"] != "areaScan")
                continue;
            Json parameters = Json::object();
            for (const auto &[from, to] : kRenames) {
                if (segment.contains(from)) {
                    parameters[to] = segment[from];
                    segment.erase(from);
                }
            }
            parameters["sideDistance"] = 0.0;
            segment["parameters"] = std::move(parameters);
        }
    }
}

const std::vector<std::function<void(Json &)>> &steps()
{
    static const std::vector<std::function<void(Json &)>> s{v1ToV2, v2ToV3};  // steps()[i] lifts i+1 to i+2
    return s;
}
}

void migrateSortie(Json &doc, int from)
{
    for (int v = from; v < kSortieSchemaVersion; ++v)
        steps()[size_t(v - 1)](doc);
    doc["schemaVersion"] = kSortieSchemaVersion;
}

} // namespace sortie::mission::formats
