#pragma once

#include "MissionError.h"
#include "Route.h"

#include <QByteArray>
#include <QStringList>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::mission::formats {

struct ImportedPolygon
{
    QString name;                  // the Placemark's name, if any
    std::vector<GeoPoint> polygon; // open ring (the closing vertex removed)
    QStringList notices;
};

// The first polygon in a KML document: a Polygon's outer boundary, or a closed LineString.
// Malformed XML, a missing polygon or bad coordinates fail with the line number. Pure.
Result<ImportedPolygon> readKmlPolygon(const QByteArray &data);

// The route for Google Earth: the flown path as LineStrings with altitudes (one per run of the
// same altitude type: relativeToGround for AGL, absolute for AMSL), a point per waypoint, and
// each area scan's polygon.
QByteArray writeKmlRoute(const Route &route, ScanPlanCache *cache = nullptr);

} // namespace sortie::mission::formats
