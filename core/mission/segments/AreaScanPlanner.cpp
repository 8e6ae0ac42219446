#include "AreaScanPlanner.h"

#include "Photogrammetry.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::mission {

namespace {
AreaScanOutcome refuse(ScanProblem problem, QString message)
{
    AreaScanOutcome o;
    o.problem = problem;
    o.message = std::move(message);
    return o;
}
}

AreaScanOutcome planAreaScan(const AreaScan &scan)
{
    const AreaScanParameters &params = scan.parameters;
    PlanarPolygonOutcome projected = planarPolygon(scan.polygon);
    if (!projected.polygon && (projected.problem == ScanProblem::TooFewVertices || projected.problem == ScanProblem::InvalidVertex))
        return refuse(projected.problem, projected.message);

    const Camera &cam = params.camera;
    if (!cam.isValid())
        return refuse(ScanProblem::InvalidCamera, QCoreApplication::translate("AreaScanPlanner", "The camera needs a positive sensor size, focal length and image size."));
    for (double o : {params.frontOverlapPercent, params.sideOverlapPercent})
        if (!(o >= 0 && o <= 95))
            return refuse(ScanProblem::InvalidOverlap, QCoreApplication::translate("AreaScanPlanner", "Overlaps must be between 0 and 95 %."));
    const double altitude = scanAltitude(params);
    if (!(altitude > 0) || !std::isfinite(altitude))
        return refuse(ScanProblem::InvalidAltitude, QCoreApplication::translate("AreaScanPlanner", "The scan altitude (or ground sample distance) must be positive."));
    if (!(params.turnaroundMeters >= 0) || !std::isfinite(params.turnaroundMeters))
        return refuse(ScanProblem::InvalidTurnaround, QCoreApplication::translate("AreaScanPlanner", "The turnaround distance must not be negative."));
    if (!projected.polygon)
        return refuse(projected.problem, projected.message);
    const PlanarPolygon &shape = *projected.polygon;

    AreaScanPlan plan;
    plan.altitude = altitude;
    plan.groundSampleDistanceCm = scanGroundSampleDistanceCm(params);
    plan.transectSpacing = params.sideDistanceMeters > 0 ? params.sideDistanceMeters
                                                         : photogrammetry::passSpacing(footprintAcrossMeters(params), params.sideOverlapPercent);
    plan.triggerDistance = photogrammetry::triggerDistance(footprintAlongMeters(params), params.frontOverlapPercent);
    plan.areaSquareMeters = shape.area;

    const SweepOutcome sweep = sweepPolygon(shape.points, plan.transectSpacing, params.directionDeg);
    if (!sweep.ok())
        return refuse(sweep.problem, sweep.message);
    plan.cells = sweep.cells;

    const double turn = params.turnaroundMeters;
    for (const SweepPass &s : sweep.passes) {
        Transect t;
        t.start = shape.plane.unproject(s.start);
        t.end = shape.plane.unproject(s.end);
        t.length = s.length;
        t.photos = photogrammetry::photosOnPass(t.length, plan.triggerDistance);
        plan.photoCount += t.photos;
        if (turn > 0 && s.length > 0) {
            const double ux = (s.end.x - s.start.x) / s.length, uy = (s.end.y - s.start.y) / s.length;
            plan.path.push_back(shape.plane.unproject({s.start.x - ux * turn, s.start.y - uy * turn}));
            plan.path.push_back(t.start);
            plan.path.push_back(t.end);
            plan.path.push_back(shape.plane.unproject({s.end.x + ux * turn, s.end.y + uy * turn}));
        } else {
            plan.path.push_back(t.start);
            plan.path.push_back(t.end);
        }
        plan.transects.push_back(t);
    }
    for (size_t i = 1; i < plan.path.size(); ++i)
        plan.pathLength += geodesicDistance(plan.path[i - 1], plan.path[i]);
    return AreaScanOutcome{std::move(plan), ScanProblem::None, {}};
}

} // namespace sortie::mission
