#pragma once

#include "AreaScan.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::mission {

// One photo pass, flown from start to end with the camera triggering every triggerDistance.
struct Transect
{
    GeoPoint start;
    GeoPoint end;
    double length = 0.0;  // metres
    int photos = 0;
};

struct AreaScanPlan
{
    std::vector<Transect> transects;  // in flight order
    // The path the vehicle flies: for each transect the turnaround point before it, its start,
    // its end and the turnaround point after it (turnaround points only when the distance is > 0).
    std::vector<GeoPoint> path;
    double altitude = 0.0;            // metres, the scan's altitude type
    double groundSampleDistanceCm = 0.0;
    double transectSpacing = 0.0;     // metres between neighbouring transects
    double triggerDistance = 0.0;     // metres between photos along a transect
    int photoCount = 0;
    double pathLength = 0.0;          // metres, turnarounds and connections included
    double areaSquareMeters = 0.0;
    int cells = 0;                    // monotone pieces a concave polygon was split into
};

// Why a scan cannot be planned. The validator turns these into named rules.
enum class ScanProblem {
    None, TooFewVertices, InvalidVertex, TooLarge, SelfIntersecting, NoArea, InvalidCamera,
    InvalidOverlap, InvalidAltitude, InvalidTurnaround, TooManyTransects, NoTransects
};

struct AreaScanOutcome
{
    std::optional<AreaScanPlan> plan;
    ScanProblem problem = ScanProblem::None;
    QString message;  // for the operator, when problem != None
    bool ok() const { return plan.has_value(); }
};

// Lawnmower coverage of a polygon. The polygon is projected on the plane tangent at its centre
// (so the antimeridian and the poles need no special case), swept by lines spaced by the image
// footprint less the side overlap, and split into monotone cells where the sweep meets a concave
// notch, so that no transect leaves the polygon. Cells are flown one after another, each as a
// boustrophedon, choosing the nearest entry each time. Refuses polygons wider than 100 km.
AreaScanOutcome planAreaScan(const AreaScan &scan);

constexpr double kMaxScanRadiusMeters = 50000.0;
constexpr int kMaxTransects = 20000;

} // namespace sortie::mission
