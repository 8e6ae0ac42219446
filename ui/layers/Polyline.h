#pragma once

#include <QPolygonF>

namespace sortie::ui {

// Douglas-Peucker: keeps the points a polyline needs to stay within `tolerance` pixels of
// itself. A survey line of a hundred waypoints, or a trail circling for minutes, is drawn with a
// few points, which looks the same and costs far less.
QPolygonF simplifyPolyline(const QPolygonF &polyline, double tolerance);

} // namespace sortie::ui
