#pragma once

#include "MavlinkMission.h"

#include <QByteArray>

namespace sortie::mission::formats {

// QGroundControl .plan files (JSON, "fileType": "Plan"): simple mission items (waypoint,
// take-off, land, return, speed change, delay, ROI, camera) and survey complex items, which
// become area scans. Items are read in both of QGroundControl's layouts (7 params, or 4 params
// plus "coordinate"); written in the current one. Geofence and rally points are not imported
// (a notice says so when present). Pure: bytes in, bytes out.
Result<ImportedRoute> readQgcPlan(const QByteArray &data);
// Area scans that cannot be planned are left out with a notice.
QByteArray writeQgcPlan(const Route &route, QStringList *notices = nullptr, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission::formats
