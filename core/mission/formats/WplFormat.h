#pragma once

#include "MavlinkMission.h"

#include <QByteArray>

namespace sortie::mission::formats {

// QGC WPL 110 waypoint files (QGroundControl and Mission Planner): a "QGC WPL 110" line, then one
// tab-separated item per line: index, current, frame, command, param1-4, latitude, longitude,
// altitude, autocontinue. Item 0 is the home position (altitude AMSL). Pure: bytes in, bytes out.
// Speeds before any DO_CHANGE_SPEED are the WPL default of 5 m/s.
constexpr double kWplDefaultSpeed = 5.0;

// The file's items as written (home apart, each item with its line), checked as readWpl checks them:
// for a reader that needs what a route does not keep, such as each item's altitude frame.
struct WplItems
{
    std::optional<HomePosition> home;  // item 0
    std::vector<MavlinkItem> items;    // items 1..n
};
Result<WplItems> readWplItems(const QByteArray &data);
Result<ImportedRoute> readWpl(const QByteArray &data);
// Without a home position the first point is written as home at 0 m AMSL, with a notice.
QByteArray writeWpl(const Route &route, QStringList *notices = nullptr, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission::formats
