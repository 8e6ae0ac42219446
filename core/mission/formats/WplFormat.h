#pragma once

#include "MavlinkMission.h"

#include <QByteArray>

namespace sortie::mission::formats {

// QGC WPL 110 waypoint files (QGroundControl and Mission Planner): a "QGC WPL 110" line, then one
// tab-separated item per line: index, current, frame, command, param1-4, latitude, longitude,
// altitude, autocontinue. Item 0 is the home position (altitude AMSL). Pure: bytes in, bytes out.
// Speeds before any DO_CHANGE_SPEED are the WPL default of 5 m/s.
constexpr double kWplDefaultSpeed = 5.0;

Result<ImportedRoute> readWpl(const QByteArray &data);
// Without a home position the first point is written as home at 0 m AMSL, with a notice.
QByteArray writeWpl(const Route &route, QStringList *notices = nullptr, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission::formats
