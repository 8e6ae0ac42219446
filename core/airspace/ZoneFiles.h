#pragma once

#include "MissionError.h"
#include "Zone.h"

#include <QByteArray>
#include <QStringList>

namespace sortie::airspace {

// What a zone file gave: its zones, and each feature left out with the reason ("feature 3
// ('RIX CTR'): the ceiling is below the floor"). A bad feature loses only itself.
struct ZoneFile
{
    std::vector<Zone> zones;
    QStringList problems;
};

// GeoJSON: a FeatureCollection (or one Feature) of Polygon / MultiPolygon, and Point with
// properties.radius (metres) for a circle, plus properties.topRadius for a cone frustum.
// properties: name, kind ("exclusion" | "inclusion", default exclusion), floor and ceiling in
// metres (missing floor: the ground; missing ceiling: unlimited), reference ("AMSL" | "AGL" |
// "HOME", default AMSL), active (default true). Not JSON or not GeoJSON: an error (line/path).
mission::Result<ZoneFile> readGeoJsonZones(const QByteArray &data, const QString &origin = {});

// KML: every Placemark's Polygon (outer and inner boundaries; several in a MultiGeometry make one
// zone) as an exclusion zone over the whole column, named by the Placemark. Malformed XML fails
// with the line; a Placemark with bad coordinates is left out naming it and its line.
mission::Result<ZoneFile> readKmlZones(const QByteArray &data, const QString &origin = {});

// A QGroundControl .plan's geofence: polygons and circles with their inclusion flag.
mission::Result<ZoneFile> readPlanZones(const QByteArray &data, const QString &origin = {});

// A file by its extension: .plan, .geojson / .json, .kml. The error names the file.
mission::Result<ZoneFile> loadZoneFile(const QString &path);

} // namespace sortie::airspace
