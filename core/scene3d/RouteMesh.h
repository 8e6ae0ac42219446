#pragma once

#include "FlownPath.h"
#include "HeightGrid.h"
#include "SceneMesh.h"

#include <QColor>

#include <vector>

namespace sortie::scene3d {

struct RouteStyle
{
    QColor colour{30, 110, 230};
    double width = 6.0;        // metres: the tube's side
    double markerSize = 15.0;  // metres: a waypoint marker's half height
    float curtainAlpha = 0.22f;
};

// A waypoint as drawn: the route row its leg ends at (what selecting it selects) and where it is.
struct WaypointMark
{
    int row = -1;
    QVector3D position;
};

struct RouteMesh
{
    Mesh path;     // the flown path as a square tube, and a marker (an octahedron) at each waypoint: opaque
    Mesh curtain;  // the curtain from the path down to the ground: translucent
    std::vector<WaypointMark> waypoints;
    std::vector<QVector3D> points;  // the path's points in the scene, in order (take-off climb, legs, landing)
    int unknownHeights = 0;         // points left out: no height in any reference the scene can place
};

// The flown path the checks compute (airspace::flownPath: climbs, terrain following, take-off and
// landing, the flight home) in the scene's frame. A point's height is its AMSL one, else its height
// above the ground plus the grid's ground there. The curtain's foot follows the grid's ground every
// grid step (the lowest known ground where the grid has none).
RouteMesh buildRoute(const airspace::FlownPath &path, const SceneFrame &frame, const HeightGrid &grid, const RouteStyle &style = {});

// A square tube of side `width` along a polyline, and an octahedron: the shapes routes and markers are made of.
void addTube(Mesh &mesh, const std::vector<QVector3D> &points, float width, const QVector4D &colour);
void addOctahedron(Mesh &mesh, const QVector3D &centre, float halfWidth, float halfHeight, const QVector4D &colour);

} // namespace sortie::scene3d
