#pragma once

#include "GeoPoint.h"

#include <optional>
#include <vector>

namespace sortie::mission {

// A geofence and rally points as a QGroundControl .plan carries them beside its mission. The
// mission model only keeps them (so a .plan read and written again loses nothing); what they mean
// for a flown path is core/airspace's (zonesOfFence). No altitude limits: a .plan fence is the
// whole column above its shape.
struct FencePolygon
{
    std::vector<GeoPoint> vertices;  // open ring
    bool inclusion = true;           // true: stay inside; false: keep out
    bool operator==(const FencePolygon &) const = default;
};

struct FenceCircle
{
    GeoPoint center;
    double radius = 0.0;  // metres
    bool inclusion = true;
    bool operator==(const FenceCircle &) const = default;
};

// A point with a height as the .plan has it (QGroundControl: metres above home).
struct FencePoint
{
    GeoPoint position;
    double altitude = 0.0;
    bool operator==(const FencePoint &) const = default;
};

struct RouteFence
{
    std::vector<FencePolygon> polygons;
    std::vector<FenceCircle> circles;
    std::optional<FencePoint> breachReturn;  // where to go on a breach
    std::vector<FencePoint> rallyPoints;      // safe places to return to instead of home

    bool empty() const { return polygons.empty() && circles.empty() && !breachReturn && rallyPoints.empty(); }
    bool operator==(const RouteFence &) const = default;
};

} // namespace sortie::mission
