#pragma once

#include "LocalTangentPlane.h"

#include <optional>
#include <utility>
#include <vector>

namespace sortie::mission {

// Plane geometry on an open polygon (the last vertex connects to the first).
namespace polygon {

double signedArea(const std::vector<PlanePoint> &pts);  // > 0 counter-clockwise, m²
// The first pair of edges (i, j) that touch or cross without being neighbours, or nullopt when
// the polygon is simple. Edge i runs from vertex i to vertex i+1.
std::optional<std::pair<int, int>> firstSelfIntersection(const std::vector<PlanePoint> &pts);
// The x coordinates, sorted, where the horizontal line at y crosses the boundary. Half-open
// rule at vertices, so the count is even and the intervals [x0,x1], [x2,x3], ... are inside.
std::vector<double> crossingsAt(const std::vector<PlanePoint> &pts, double y);

} // namespace polygon
} // namespace sortie::mission
