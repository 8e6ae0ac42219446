#pragma once

#include "MissionError.h"
#include "VciFence.h"
#include "VehicleTypes.h"

#include <QStringList>

#include <functional>
#include <optional>

namespace sortie::mission {
struct GeoBox;
struct GeoPoint;
struct Route;
} // namespace sortie::mission

namespace sortie::vehicle {

// The fence a VCI vehicle gets with a route (docs/vci-profile.md, "Fence"; docs/airspace.md, "On
// the vehicle"), and what the operator should know about how it was made.
struct VciFencePlan
{
    vci::profile::Fence fence;
    QStringList notices;
};

// The ground (m AMSL) under a point, or nullopt where no terrain source knows it.
using GroundLookup = std::function<std::optional<double>(const mission::GeoPoint &)>;

// The route's own fence (whole-column polygons and circles) and the active zones of
// `settings.zones` whose box meets `routeBox`, in the profile's form:
// - shapes: a polygon's outer ring; an inclusion zone's holes become exclusion items with its limits,
//   an exclusion zone's holes are closed (it only grows); a cone frustum becomes the circle of its
//   widest radius when it keeps out, of its narrowest when it keeps in;
// - limits: AMSL and above-home as they are; AGL through the ground under the zone (its vertices, a
//   circle's centre and 8 points on its edge), on the safe side: an exclusion zone from the lowest
//   ground plus its floor to the highest plus its ceiling, an inclusion zone the other way round.
//   With no ground, an exclusion zone's AGL limit is dropped (it then reaches the ground or has no
//   top) and an inclusion zone is refused, naming it;
// - more than the profile's limits (items, vertices) is refused, naming the limit.
mission::Result<VciFencePlan> vciFenceFor(const mission::Route &route, const FenceSettings &settings, const mission::GeoBox &routeBox,
                                          const GroundLookup &ground = {});

vci::profile::BreachAction profileBreachAction(FenceBreachAction action);

} // namespace sortie::vehicle
