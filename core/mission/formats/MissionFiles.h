#pragma once

#include "KmlFormat.h"
#include "Mission.h"
#include "MissionError.h"
#include "ValidationGate.h"
#include "WpmlFormat.h"

#include <QStringList>

#include <optional>

namespace sortie::mission::formats {

enum class FileFormat { Sortie, QgcPlan, Wpl, Kml, Wpml };

// By extension: .sortie, .plan, .waypoints / .wpl / .txt (QGC WPL), .kml, .kmz (DJI WPML).
std::optional<FileFormat> formatForPath(const QString &path);
// Those extensions, without the dot, lower case.
QStringList missionFileExtensions();
QString formatName(FileFormat format);

// A file of the operator's read whole, refused when it holds more than `maxBytes`. At most
// maxBytes + 1 bytes are read, so a pipe or a device, which reports no size, cannot fill memory
// either. Every reader of a whole outside file goes through here (missions, zones, energy profiles).
Result<QByteArray> readFileAtMost(const QString &path, qint64 maxBytes);

struct LoadedMission
{
    Mission mission;
    QStringList notices;
};

// Reads a mission from any importable format. Every error names the file and its line or JSON
// path; nothing is returned half-read, so a failed import leaves the caller's plan as it was.
// Single-route formats give a mission with one route named after the file.
Result<LoadedMission> loadMission(const QString &path);
// A KML polygon, for an area-scan boundary.
Result<ImportedPolygon> loadPolygon(const QString &path);

struct SaveOptions
{
    // Which route to write (0-based). Unset: every route where the format holds several (.sortie,
    // DJI WPML's waylines); for a format that holds one (.plan, WPL, KML), the mission's only route,
    // and a mission of several is refused with the reason rather than cut to its first.
    std::optional<int> routeIndex;
    ValidationOverride override = ValidationOverride::None;
    WpmlExportOptions wpml;  // aircraft, payload and height mode of a DJI WPML (.kmz) export
};

// Validates the route(s) being written (the gate refuses errors unless overridden), encodes, and
// replaces the file atomically. Returns what the format could not represent.
Result<QStringList> saveMission(const Mission &mission, const QString &path, const SaveOptions &options = {});

} // namespace sortie::mission::formats
