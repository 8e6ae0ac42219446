#pragma once

#include "AlgorithmDefinition.h"
#include "Camera.h"
#include "GeoPoint.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::mission {

// What a segment flies, computed from its algorithm, figure and parameter values: the one planner the
// client's live preview and sortie-sim's ProcessRoute both call. Pure functions over plain values.

enum class HeightFrame { Agl, Amsl };

// A segment's figure as the wire carries it (Figure), positions in degrees.
struct SegmentFigure
{
    FigureType type = FigureType::Point;
    std::vector<GeoPoint> points;        // a polygon may be closed (first point repeated) or open
    std::vector<double> pointAltitudes;  // per point, metres in pointFrame; may be empty
    HeightFrame pointFrame = HeightFrame::Agl;
    std::vector<double> parameters;      // Figure.parameters: a circle's radius (m) first
};

struct PlanContext
{
    std::vector<ProfileCamera> cameras;        // the vehicle profile's cameras, first = default
    double defaultSpeed = 5.0;                 // m/s: the previous segment's, else the profile's
    std::optional<GeoPoint> previousPosition;  // where the vehicle comes from: orbits and sweeps start near it
};

// A camera command at a planned point; the simulator turns them into the processed actions.
struct CameraCommand
{
    enum class Kind {
        FaceDown,         // camera control, tilt 90°
        FaceHeading,      // camera level, vehicle heading `value` degrees (facade)
        StartSeries,      // camera series by distance, one photo every `value` metres
        StopSeries,       // end of the series (by distance, interval 0)
    };
    Kind kind = Kind::StartSeries;
    double value = 0.0;
    bool operator==(const CameraCommand &) const = default;
};

struct PlannedPoint
{
    enum class Kind { Waypoint, Takeoff, Landing };
    GeoPoint position;
    double height = 0.0;                // metres in `frame`
    HeightFrame frame = HeightFrame::Agl;
    double speed = 0.0;                 // m/s on the leg arriving here
    Kind kind = Kind::Waypoint;
    bool onPass = false;                // on a photo pass (area tools): where forward-pass actions go
    bool overshoot = false;             // an overshoot point beyond a pass end
    bool userActions = false;           // the segment's own actions run here (actionExecution, noActionsAtLastPoint)
    std::vector<CameraCommand> camera;
};

struct SegmentPlan
{
    std::vector<PlannedPoint> points;
    double length = 0.0;           // metres along the points
    int passes = 0;                // photo or scan passes
    int photos = 0;                // photos the camera series take
    double height = 0.0;           // flight height of area tools (m)
    double gsdCm = 0.0;            // photogrammetry and corridor
    double passSpacing = 0.0;      // metres between passes
    double triggerDistance = 0.0;  // metres between photos
    std::optional<Camera> camera;  // the camera the plan used
    // The segment's altitudeType as given. The photo tools (photogrammetry, corridor) plan their GSD
    // height above the ground photographed (points in Agl); AMSL asks for one constant altitude that
    // height above the lowest ground under the area, which terrain post-processing applies.
    QString altitudeType;
    std::vector<QString> warnings;
    std::vector<QString> notes;    // the calculated figures, for the route log
};

struct SegmentPlanOutcome
{
    std::optional<SegmentPlan> plan;
    std::vector<QString> errors;   // each names the parameter or the point at fault
    int wrongPoint = -1;           // the figure point at fault, when there is one
    bool ok() const { return plan.has_value(); }
};

// Plans one segment. Parameter values out of their definition's range, a figure with too few or bad
// points, or a photo tool without a usable camera give errors and no plan. Circle: points on the
// radius (Figure.parameters[0]) for `loops` laps in the `flightClockwise` sense; perimeter: along the
// polygon's edges through its vertices; area scan / photogrammetry / creeping line: parallel passes
// along `directionAngle`, `sideDistance` (or the side overlap) apart, extended by `overshoot`;
// corridor: passes offset from the centre line within `width`; expanding square: a square spiral
// to `searchRadius`; facade: passes over the wall A–B at `distanceToFacade`; take-off, landing and
// waypoint: the point itself.
SegmentPlanOutcome planSegment(const AlgorithmDefinition &algorithm, const SegmentFigure &figure,
                               const ParameterValues &values, const PlanContext &context);

// The number of points an orbit of `radius` gets per lap when basePointsQnt is not set: enough that a
// chord strays at most 1 m from the circle, between 8 and 360.
int circlePointsPerLap(double radius);

} // namespace sortie::mission
