#pragma once

#include "CoverageSweep.h"
#include "LocalTangentPlane.h"
#include "Photogrammetry.h"
#include "SegmentPlanner.h"

#include <optional>
#include <variant>

// What the tool planners build with: a failure, the parameters every tool reads, a planned point,
// passes over a plane (one, a sweep of a polygon, an offset line) and the camera a GSD asks for.
namespace sortie::mission::toolplanning {

inline constexpr int kMaxPlannedPoints = 200000;  // beyond this a segment is a mistake, not a plan

SegmentPlanOutcome fail(QString message, int point = -1);
QString m1(double v);  // metres (or m/s) to one decimal, for messages

// The segment's own parameters, read once.
struct Common
{
    double speed = 5.0;
    std::optional<double> overshoot, overshootSpeed;
    double direction = 0.0;
};

Common commonOf(const ParameterReader &r, const PlanContext &ctx);

PlannedPoint point(const GeoPoint &p, double height, HeightFrame frame, double speed);

// Passes over a plane: what area scan, photogrammetry, creeping line and corridor share.
struct PassSpec
{
    double height = 0.0;
    HeightFrame frame = HeightFrame::Agl;
    double speed = 0.0;
    double overshoot = 0.0;
    double overshootSpeed = 0.0;
    double trigger = 0.0;        // metres between photos, 0 = no camera series
    bool extraPoints = false;    // a waypoint at every photo position
};

// Appends one pass (a polyline in the plane, flown from its first to its last point).
void appendPass(const LocalTangentPlane &plane, const std::vector<PlanePoint> &line, const PassSpec &spec, SegmentPlan &plan);

// Parallel passes over a polygon; a double grid flies a second sweep across the first. The error, if any.
std::optional<QString> sweepArea(const PlanarPolygon &shape, double spacing, double direction, bool doubleGrid,
                                 const PassSpec &spec, const PlanContext &ctx, SegmentPlan &plan);

// The polyline shifted `offset` metres to its right (negative: left), mitred at the joins.
std::vector<PlanePoint> offsetPolyline(const std::vector<PlanePoint> &line, double offset);

struct CameraSetup
{
    Camera camera;
    photogrammetry::Figures figures;
};

// The camera and figures of a photo tool from its GSD and overlaps, or why there are none.
std::variant<CameraSetup, QString> photoSetup(const ParameterReader &r, const PlanContext &ctx, double speed);
// Records the camera's figures on the plan, warning when the speed outruns its trigger interval.
void noteCamera(const CameraSetup &s, double speed, SegmentPlan &plan);

} // namespace sortie::mission::toolplanning
