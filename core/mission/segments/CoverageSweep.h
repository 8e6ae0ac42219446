#pragma once

#include "LocalTangentPlane.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::mission {

// Why a polygon cannot be swept. The validator turns these into named rules.
enum class ScanProblem {
    None, TooFewVertices, InvalidVertex, TooLarge, SelfIntersecting, NoArea, InvalidCamera,
    InvalidOverlap, InvalidAltitude, InvalidTurnaround, TooManyTransects, NoTransects
};

constexpr double kMaxScanRadiusMeters = 50000.0;
constexpr int kMaxTransects = 20000;

// A polygon on the plane tangent at its centre (so the antimeridian and the poles need no special case).
struct PlanarPolygon
{
    LocalTangentPlane plane;
    std::vector<PlanePoint> points;  // open ring, as given
    double area = 0.0;               // m²
};

struct PlanarPolygonOutcome
{
    std::optional<PlanarPolygon> polygon;
    ScanProblem problem = ScanProblem::None;
    QString message;
    int vertex = -1;  // the offending vertex (0-based) where there is one
};

// Projects and checks a polygon (degrees; a closed ring is accepted): at least 3 vertices, all valid,
// within 50 km of its centre, simple, with an area.
PlanarPolygonOutcome planarPolygon(std::vector<GeoPoint> polygon);

// One pass of a sweep, in the plane.
struct SweepPass
{
    PlanePoint start;
    PlanePoint end;
    double length = 0.0;
};

struct SweepOutcome
{
    std::vector<SweepPass> passes;  // in flight order
    int cells = 0;
    ScanProblem problem = ScanProblem::None;
    QString message;
    bool ok() const { return problem == ScanProblem::None; }
};

// Lawnmower coverage: lines spaced `spacing` apart along the bearing `directionDeg` (clockwise from north),
// centred across the polygon, split into monotone cells where the sweep meets a concave notch so that
// no pass leaves the polygon. Cells are flown one after another, each as a boustrophedon, entering
// each time the unvisited cell whose entry is nearest (starting near `start` when given).
SweepOutcome sweepPolygon(const std::vector<PlanePoint> &polygon, double spacing, double directionDeg,
                          const std::optional<PlanePoint> &start = std::nullopt);

} // namespace sortie::mission
