#pragma once

#include "ZoneFiles.h"

namespace sortie::airspace {

// The zones the operator drew, kept across restarts as GeoJSON (the format ZoneFiles reads, so the
// file can also be loaded elsewhere as a zone file): polygons, circles (Point + radius), name, kind,
// floor, ceiling, their one reference, active. Written atomically (QSaveFile).
bool writeCustomZones(const QString &path, const std::vector<Zone> &zones, QString *error);
// Read back as drawn zones (source ServerCustom, origin "drawn on the map").
mission::Result<ZoneFile> readCustomZones(const QString &path);
// The GeoJSON text itself (tests, the writer).
QByteArray customZonesJson(const std::vector<Zone> &zones);

} // namespace sortie::airspace
