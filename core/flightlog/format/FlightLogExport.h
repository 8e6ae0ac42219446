#pragma once

#include "FlightLog.h"

#include <QIODevice>
#include <QString>

namespace sortie::flightlog {

enum class ExportFormat { Gpx, Kml, Csv };
std::optional<ExportFormat> exportFormatFromName(const QString &name); // "gpx", "kml", "csv"
QString exportSuffix(ExportFormat format);

// Writes the tracks of some vehicles of a log (all when `vehicles` is empty):
// - GPX 1.1, one <trk> per vehicle, <ele> metres AMSL, <time> UTC;
// - KML 2.2 with one gx:Track per vehicle (absolute altitudes);
// - CSV, a header line first, then one row per time and vehicle and a column per field the log
//   holds (angles in degrees, other values in SI units); a field not sent at that time is empty.
// Returns false with *error when the device cannot be written.
bool exportLog(const FlightLog &log, ExportFormat format, const std::vector<int> &vehicles, QIODevice *out, QString *error);

} // namespace sortie::flightlog
