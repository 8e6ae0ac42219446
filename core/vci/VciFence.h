#pragma once

#include "VciProfile.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The fence of Sortie's VCI profile (docs/vci-profile.md, "Fence"): inclusion and exclusion areas
// (polygons and circles) with altitude limits, and what the vehicle does when it breaks one. The
// client sends it with the mission; the vehicle keeps it and reports breaches on /fence/status.
// Pure: no Qt. Radians and metres, as everywhere in the profile.
namespace sortie::vci::profile {

// Inclusion: stay inside (several inclusion items are one permitted area, their union). Exclusion:
// keep out of the space between its floor and ceiling.
enum class FenceKind { Inclusion, Exclusion };
// What an altitude limit is measured from: mean sea level, or the home point's ground.
enum class FenceReference { Amsl, Home };
// What the vehicle does on a breach: fly home and land, land where it is, or stop and hover.
enum class BreachAction { Return, Land, Hold };

std::string_view fenceKindName(FenceKind kind);          // "inclusion", "exclusion"
std::string_view fenceReferenceName(FenceReference ref); // "amsl", "home"
std::string_view breachActionName(BreachAction action);  // "return", "land", "hold"
std::optional<BreachAction> breachActionFromName(std::string_view name);

struct FenceLimit
{
    double altitude = 0; // metres above the reference
    FenceReference reference = FenceReference::Amsl;
    bool operator==(const FenceLimit &) const = default;
};

struct FenceVertex
{
    double latitude = 0;  // radians
    double longitude = 0; // radians
    bool operator==(const FenceVertex &) const = default;
};

// One area: a polygon (an open ring of 3 or more vertices, no holes) or a circle (a centre and a
// radius in metres). No floor: from the ground; no ceiling: unlimited.
struct FenceItem
{
    FenceKind kind = FenceKind::Exclusion;
    std::string name; // for reports; may be empty
    std::vector<FenceVertex> polygon;
    std::optional<FenceVertex> center; // set for a circle (then `polygon` is empty)
    double radius = 0;
    std::optional<FenceLimit> floor;
    std::optional<FenceLimit> ceiling;
    bool isCircle() const { return center.has_value(); }
    bool operator==(const FenceItem &) const = default;
};

struct Fence
{
    std::vector<FenceItem> items;
    BreachAction breachAction = BreachAction::Return;
    bool empty() const { return items.empty(); }
    bool operator==(const Fence &) const = default;
};

// What a vehicle takes (beyond them a PUT is refused, naming the limit).
inline constexpr size_t kMaxFenceItems = 256;
inline constexpr size_t kMaxPolygonVertices = 1000;
inline constexpr size_t kMaxFenceVertices = 20000; // over all polygons
inline constexpr size_t kMaxFenceNameLength = 200; // bytes of UTF-8

// {"items":[{"kind":"exclusion","name":"RIX CTR","polygon":[{"latitude":..,"longitude":..},..],
//   "floor":{"altitude":0,"reference":"amsl"},"ceiling":{..}}, {"kind":"inclusion","circle":
//   {"latitude":..,"longitude":..,"radius":m}}], "breachAction":"return"}
nlohmann::json encodeFence(const Fence &fence);
// The fence, or nullopt and an error naming the JSON path ("items[2].polygon[5].latitude: ...") or
// the limit passed ("items: 300 items, more than the 256 a fence may hold"). Keys it does not
// know (a GET's "version") are ignored.
std::optional<Fence> decodeFence(const nlohmann::json &body, std::string *error);
// Why the fence breaks a limit, or empty: what encodeFence's caller checks before sending.
std::string fenceLimitProblem(const Fence &fence);

// /fence/status: is the vehicle inside its fence. `state` is "none" (no fence), "clear" or
// "breached"; `breaches` counts breaches since the fence was set; `item` is the breached item (-1
// when clear), `kind` what was broken ("outside-inclusion", "inside-exclusion"), `action` the
// breach action the vehicle took.
struct FenceStatus
{
    std::string state = "none";
    int breaches = 0;
    int item = -1;
    std::string name;
    std::string kind;
    std::string action;
    int64_t time = 0;
};
nlohmann::json encodeFenceStatus(const FenceStatus &status);
std::optional<FenceStatus> decodeFenceStatus(const nlohmann::json &body);

} // namespace sortie::vci::profile
