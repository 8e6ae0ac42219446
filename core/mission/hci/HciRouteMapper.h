#pragma once

#include "Mission.h"
#include "MissionError.h"

#include <QStringList>

namespace com::ugcs::ucs::proto {
class Mission;
class Route;
}

namespace sortie::mission {

// UgCS algorithm classes of the segments Sortie edits. The waypoint class is in the SDK; the
// others are Sortie's choice, documented in docs/missions.md.
inline constexpr const char *kWaypointAlgorithm = "com.ugcs.ucs.service.routing.impl.WaypointAlgorithm";
inline constexpr const char *kAreaScanAlgorithm = "com.ugcs.ucs.service.routing.impl.AreaScanAlgorithm";
inline constexpr const char *kTakeoffAlgorithm = "com.ugcs.ucs.service.routing.impl.TakeOffAlgorithm";
inline constexpr const char *kLandingAlgorithm = "com.ugcs.ucs.service.routing.impl.LandingAlgorithm";

struct HciRouteImport
{
    Route route;
    QStringList notices;
};

// HCI Route <-> Route. Reading keeps the protobuf each value came from (HciOrigin); writing starts
// from a copy of it and writes only the fields whose value changed, so everything else (ids,
// versions, uuids, references, fields this schema does not know) goes back exactly as it came.
// A segment of any other algorithm (photogrammetry, circle, perimeter, corridor, one Sortie does
// not know) becomes an AlgorithmSegment: kept, editable as name/value parameters, and written
// back byte for byte while it is not edited.
Result<HciRouteImport> routeFromHci(const com::ugcs::ucs::proto::Route &route);
com::ugcs::ucs::proto::Route routeToHci(const Route &route);

Result<Mission> missionFromHci(const com::ugcs::ucs::proto::Mission &mission, QStringList *notices = nullptr);
com::ugcs::ucs::proto::Mission missionToHci(const Mission &mission);

} // namespace sortie::mission
