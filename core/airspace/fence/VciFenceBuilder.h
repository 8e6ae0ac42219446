#pragma once

#include "AirspaceCheck.h"
#include "VciFencePlan.h"

namespace sortie::airspace {

// The airspace's zones as the fence is made of them (vehicle::FenceSettings::zones, opaque to the
// vehicle and the client): a ZoneSet, so the builder takes its box query and index as they are.
class FenceZoneSet final : public ZoneSet, public vehicle::FenceZones
{
public:
    using ZoneSet::ZoneSet;
};

// The zone set `settings` carries, or nullptr when it carries none (or zones the airspace did not make).
const ZoneSet *fenceZonesOf(const vehicle::FenceSettings &settings);

// The fence a VCI vehicle gets with a route, a vehicle::VciFenceBuilder: the route's own fence
// (whole-column polygons and circles) and the active zones of `settings.zones` whose box meets
// `routeBox`, in the profile's form:
// - shapes: a polygon's outer ring; an inclusion zone's holes become exclusion items with its limits,
//   an exclusion zone's holes are closed (it only grows); a cone frustum becomes the circle of its
//   widest radius when it keeps out, of its narrowest when it keeps in;
// - limits: AMSL and above-home as they are; AGL through the ground under the zone (its vertices, a
//   circle's centre and 8 points on its edge), on the safe side: an exclusion zone from the lowest
//   ground plus its floor to the highest plus its ceiling, an inclusion zone the other way round.
//   With no ground, an exclusion zone's AGL limit is dropped (it then reaches the ground or has no
//   top) and an inclusion zone is refused, naming it;
// - more than the profile's limits (items, vertices) is refused, naming the limit.
mission::Result<vehicle::VciFencePlan> vciFenceFor(const mission::Route &route, const vehicle::FenceSettings &settings,
                                                   const mission::GeoBox &routeBox, const vehicle::GroundLookup &ground = {});

} // namespace sortie::airspace
