#pragma once

#include "GeoZone.h"
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

// UAS geographical zones (ED-269, ED-318) as zones: one exclusion zone per volume, each knowing
// its geographical zone and volume. A zone with a volume that cannot be checked (a ring crossing
// itself) is left out whole, naming it; its other volumes alone would understate it.
ZoneFile zonesOfGeoZones(const ed::GeoZoneFile &file, const QString &origin = {});

// A file: ED-269 and ED-318 by content (whatever its extension); then by its extension: .plan,
// .geojson / .json, .kml. The error names the file.
mission::Result<ZoneFile> loadZoneFile(const QString &path);
// The same over bytes already read (`name`: the file's name, for its extension and the origin).
mission::Result<ZoneFile> readZoneData(const QByteArray &data, const QString &name);

} // namespace sortie::airspace
