#pragma once

#include "Route.h"
#include "WpmlDocumentReader.h"

// What a wayline's action groups mean in Sortie's route: actions on reaching a waypoint, photo
// series between two, the start actions before the first. What has no equivalent is named in a
// notice, once, with its wayline and waypoint.
namespace sortie::mission::formats::wpml {

// "waypoint 3", "waypoints 1-4, 7".
QString waypointList(const std::vector<int> &numbers);

// Adds the actions of the wayline's points (in `byIndex` order) and its start group to `route`.
// `prefix` names the wayline ("wayline 2"); poiAltitude converts a point-of-interest height.
Result<void> readActions(const ReadFolder &wayline, const std::vector<const ReadPoint *> &byIndex, Route &route,
                         const QString &prefix, const QString &file, QStringList *notices);

} // namespace sortie::mission::formats::wpml
