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

// What makes that fence: the route's own fence and the zones of `settings` whose box meets
// `routeBox`, their limits placed over `ground`. The zones are the airspace's, and so is the builder
// (airspace::vciFenceFor, core/airspace/fence); a link is handed it (VciVehicleLink::setFenceBuilder)
// as the terrain is handed its DEM opener, so no vehicle room knows what a zone is. A class rather
// than an alias, so that a header can name it by a forward declaration (VehicleFleet.h).
using VciFenceBuild = mission::Result<VciFencePlan>(const mission::Route &route, const FenceSettings &settings,
                                                    const mission::GeoBox &routeBox, const GroundLookup &ground);
struct VciFenceBuilder : std::function<VciFenceBuild>
{
    using std::function<VciFenceBuild>::function;
};

vci::profile::BreachAction profileBreachAction(FenceBreachAction action);

} // namespace sortie::vehicle
