// The polygon check a new area figure passes: valid corners that enclose an area.
#include "EnclosedArea.h"

#include "LocalTangentPlane.h"
#include "PolygonGeometry.h"

#include <cmath>

namespace sortie::mission {

bool enclosesArea(const std::vector<GeoPoint> &polygon)
{
    if (polygon.size() < 3)
        return false;
    for (const GeoPoint &g : polygon)
        if (!g.isValid())
            return false;
    const LocalTangentPlane plane(LocalTangentPlane::centroidOf(polygon));
    std::vector<PlanePoint> pts;
    pts.reserve(polygon.size());
    for (const GeoPoint &g : polygon)
        pts.push_back(plane.project(g));
    return std::abs(polygon::signedArea(pts)) >= 1.0;
}

} // namespace sortie::mission
