#pragma once

#include "MavlinkMission.h"

#include <QByteArray>

namespace sortie::mission::formats {

// QGroundControl .plan files (JSON, "fileType": "Plan"): simple mission items (waypoint,
// take-off, land, return, speed change, delay, ROI, camera) and survey complex items, which
// become area scans. Items are read in both of QGroundControl's layouts (7 params, or 4 params
// plus "coordinate"); written in the current one. The geofence and rally points go into the
// route's fence (a bad one is left out with a notice naming it) and are written back as they came.
// Pure: bytes in, bytes out.
Result<ImportedRoute> readQgcPlan(const QByteArray &data);
// Only the geofence and rally points of a .plan (its mission is not read, so a plan with a fence
// and no items is fine): what core/airspace reads zones from.
Result<RouteFence> readQgcPlanFence(const QByteArray &data, QStringList *notices = nullptr);
// Area scans that cannot be planned are left out with a notice.
QByteArray writeQgcPlan(const Route &route, QStringList *notices = nullptr, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission::formats
