#pragma once

#include "AreaScan.h"
#include "CoverageSweep.h"

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

struct AreaScanOutcome
{
    std::optional<AreaScanPlan> plan;
    ScanProblem problem = ScanProblem::None;
    QString message;  // for the operator, when problem != None
    bool ok() const { return plan.has_value(); }
};

// Lawnmower coverage of a polygon (sweepPolygon in CoverageSweep.h), lines spaced by the image
// footprint less the side overlap, photos every footprint less the forward overlap.
// Refuses polygons wider than 100 km.
AreaScanOutcome planAreaScan(const AreaScan &scan);

} // namespace sortie::mission
