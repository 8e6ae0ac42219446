#pragma once

#include "GeoPoint.h"

#include <vector>

namespace sortie::terrain {

using mission::GeoPoint;

// One sampled point of a path: where it is, how far from the path's start, on which leg.
struct PathSamplePoint
{
    GeoPoint position;
    double distance = 0.0;  // metres from the path's start
    int leg = 0;            // 0-based: leg i runs from vertex i to vertex i + 1
};

// A polyline of great-circle legs sampled every `step` metres: each leg gives its start vertex and
// the points at step, 2·step, ... before its end; the last leg also gives the final vertex. So
// every vertex is a sample (vertexSample[i] is its index) and no leg is sampled coarser than step.
// Leg lengths are WGS-84 geodesic distances; positions between vertices follow the great circle.
struct SampledPath
{
    std::vector<GeoPoint> vertices;
    double step = 30.0;
    std::vector<double> vertexDistance;  // metres from the start to each vertex
    std::vector<int> vertexSample;       // index in points of each vertex
    std::vector<PathSamplePoint> points;

    double length() const { return vertexDistance.empty() ? 0.0 : vertexDistance.back(); }
    int legCount() const { return vertices.size() < 2 ? 0 : int(vertices.size()) - 1; }
};

// step <= 0 (or not finite) is taken as 30 m. A single vertex gives one sample; none gives none.
SampledPath samplePath(std::vector<GeoPoint> vertices, double step);

// A point a fraction f (0..1) of the way from a to b along the great circle.
GeoPoint greatCircleFraction(const GeoPoint &a, const GeoPoint &b, double f);

} // namespace sortie::terrain
