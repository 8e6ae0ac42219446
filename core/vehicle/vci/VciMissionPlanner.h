#pragma once

#include "MissionError.h"
#include "VehicleTypes.h"

#include <QStringList>

#include <optional>
#include <vector>

namespace sortie::mission {
struct Route;
class ScanPlanCache;
} // namespace sortie::mission

namespace sortie::terrain {
class ElevationService;
} // namespace sortie::terrain

namespace sortie::vehicle {

// What turns a route's heights into heights above home, the only ones a VCI vehicle flies
// (docs/vci-profile.md): an AGL height is above the ground under its own point, an AMSL one above
// the sea, so both need the home's altitude and AGL needs the ground there too.
struct VciHeights
{
    terrain::ElevationService *elevation = nullptr;  // the ground under each point; nullptr: unknown
    std::optional<double> homeAmsl;                  // the vehicle's home (its /telemetry/home), m AMSL
};

// A route as a VCI vehicle will fly it.
struct VciMission
{
    std::vector<MissionItem> items;
    QStringList notices;  // for the operator: heights flown above home for want of the ground
    QString waitingFor;   // not empty: some ground is still being fetched from these sources; plan
                          // again when the ElevationService signals changed()
};

// A route as the list of waypoints a VCI vehicle flies by itself (it has no server to process it).
// Three steps, each in its own file: every segment expanded into points as sortie-sim's ProcessRoute
// plans it (VciRoutePoints: area scans and photo tools as passes with the camera triggering by
// distance, orbits, corridors, ..., the segment's own actions where the plan runs them; actions in
// the VCI profile's words, VciMissionActions); heights made relative to home (VciMissionBuilder,
// VciHeights); area tools flown AGL following the ground within their tolerance (VciTerrainFollow). Where the ground or the home is unknown an
// AGL height is flown above home, with a notice. Refused, naming the segment, when something has
// no such form: an AMSL height without the home's altitude, an action only a UgCS server performs,
// a segment that cannot be planned.
mission::Result<VciMission> vciMissionFor(const mission::Route &route, const VciHeights &heights = {},
                                          mission::ScanPlanCache *cache = nullptr);

} // namespace sortie::vehicle
