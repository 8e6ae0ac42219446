#pragma once

#include "JsonCursor.h"
#include "Mission.h"
#include "TerrainProfile.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace sortie::plan {

// The terrain part of sortie-plan's JSON: minClearance, minClearanceAt {leg, distance}, noData
// [{fromDistance, toDistance, leg}], and with samples the profile itself. Legs count from 1,
// distances are metres from the route's start, a missing value is null (never 0).
mission::formats::Json terrainJson(const terrain::ProfileRoute &route, const terrain::TerrainProfile &profile, bool samples);

// A WPL file's navigation items as the profile sees them, with their altitude frames: 0 above the
// geoid, 3 above home's ground, 10 above the ground under the item. Numbered from 1 (home, item 0,
// is not a waypoint but is where frame 3 starts from). nullopt with `error` naming the line.
std::optional<terrain::ProfileRoute> wplProfileRoute(const QByteArray &data, QString *error);

// Every route of a loaded file as the profile sees it; a WPL file is read again for its frames.
std::optional<std::vector<terrain::ProfileRoute>> profileRoutes(const QString &file, const mission::Mission &mission, QString *error);

} // namespace sortie::plan
