#include "SceneFrame.h"

#include <cmath>

namespace sortie::scene3d {

SceneFrame::SceneFrame(const GeoPoint &origin, double baseHeight, double exaggeration)
    : m_plane(origin), m_base(std::isfinite(baseHeight) ? baseHeight : 0.0),
      m_exaggeration(std::isfinite(exaggeration) && exaggeration > 0.0 ? exaggeration : 1.0)
{
}

QVector3D SceneFrame::toScene(const GeoPoint &point, double height) const
{
    const mission::PlanePoint p = m_plane.project(point);
    return toScene(p.x, p.y, height);
}

} // namespace sortie::scene3d
