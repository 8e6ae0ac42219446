#pragma once

#include "GeoPoint.h"
#include "LocalTangentPlane.h"

#include <QVector3D>

namespace sortie::scene3d {

using mission::GeoPoint;

// The scene's frame: a local east-north-up frame on the plane tangent to WGS-84 at the scene's
// origin, given as the 3D views draw it (Y up, as Qt Quick 3D and glTF): x metres east, y metres up
// above `baseHeight` times the vertical exaggeration, z metres south (so -z is north and the frame
// is right-handed). Heights are metres above the EGM96 geoid, as the elevation service gives them.
class SceneFrame
{
public:
    explicit SceneFrame(const GeoPoint &origin = {}, double baseHeight = 0.0, double exaggeration = 1.0);

    const GeoPoint &origin() const { return m_plane.origin(); }
    const mission::LocalTangentPlane &plane() const { return m_plane; }
    double baseHeight() const { return m_base; }
    double exaggeration() const { return m_exaggeration; }

    // east and north metres on the tangent plane, a height above the geoid
    QVector3D toScene(double east, double north, double height) const
    {
        return QVector3D(float(east), float((height - m_base) * m_exaggeration), float(-north));
    }
    QVector3D toScene(const GeoPoint &point, double height) const;
    mission::PlanePoint toPlane(const GeoPoint &point) const { return m_plane.project(point); }
    double sceneY(double height) const { return (height - m_base) * m_exaggeration; }
    double heightOf(double sceneY) const { return sceneY / m_exaggeration + m_base; }
    // The place a scene point stands over (its height taken off).
    GeoPoint toGeo(const QVector3D &scene) const { return m_plane.unproject({scene.x(), -scene.z()}); }

private:
    mission::LocalTangentPlane m_plane;
    double m_base;
    double m_exaggeration;
};

} // namespace sortie::scene3d
