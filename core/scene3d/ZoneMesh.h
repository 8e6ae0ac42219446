#pragma once

#include "HeightGrid.h"
#include "SceneMesh.h"
#include "Zone.h"

#include <QColor>

#include <optional>
#include <vector>

namespace sortie::scene3d {

struct ZoneStyle
{
    QColor colour{220, 50, 50};
    float alpha = 0.3f;
    int circleSegments = 72;
    double sceneTop = 1000.0;  // metres AMSL an unlimited ceiling is drawn up to (no lid then)
    std::optional<double> homeGround;  // the route's home ground for limits above home; none: the frame's base
};

struct ZoneMesh
{
    Mesh mesh;
    // The zone's outline as drawn, on the plane (east, north metres): its boundary vertices.
    std::vector<mission::PlanePoint> outline;
    bool hasLid = false;    // a ceiling was given
    bool hasFloor = false;  // a floor was given (none: from the ground, no bottom drawn)
};

// A zone as a volume: a prism for polygons (its walls, a floor and a lid; a hole's walls without its
// own cap), a cylinder for a circle and a cone frustum for a funnel, between its floor and its
// ceiling in their references — AMSL as it is, AGL following the grid's ground under each wall
// vertex (edges cut every grid step), above home from `homeGround`. No floor: from the ground.
ZoneMesh buildZone(const airspace::Zone &zone, const SceneFrame &frame, const HeightGrid &grid, const ZoneStyle &style = {});

// Ear clipping of a simple polygon (no holes), its triangles as index triples into `ring`.
std::vector<std::uint32_t> triangulate(const std::vector<mission::PlanePoint> &ring);

} // namespace sortie::scene3d
