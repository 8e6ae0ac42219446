#pragma once

#include "GeoPoint.h"
#include "Geodesy.h"

#include <vector>

namespace sortie::mission {

struct PlanePoint
{
    double x = 0.0;  // metres east of the origin
    double y = 0.0;  // metres north of the origin
};

// Orthographic projection onto the plane tangent to WGS-84 at an origin. It is built from ECEF
// vectors, so it has no seam at the antimeridian and no singularity at the poles. Distances in
// the plane are shortened by cos(d/R): 3e-7 at 5 km, 3e-5 at 50 km from the origin.
class LocalTangentPlane
{
public:
    explicit LocalTangentPlane(const GeoPoint &origin);

    // The centre of a set of points, taken as the mean of their ECEF vectors (no antimeridian seam).
    static GeoPoint centroidOf(const std::vector<GeoPoint> &points);

    PlanePoint project(const GeoPoint &p) const;
    // The ellipsoid point that projects to p; NaN coordinates beyond the horizon.
    GeoPoint unproject(const PlanePoint &p) const;
    const GeoPoint &origin() const { return m_originGeo; }

private:
    GeoPoint m_originGeo;
    Ecef m_origin;
    double m_east[3], m_north[3], m_up[3];
};

} // namespace sortie::mission
