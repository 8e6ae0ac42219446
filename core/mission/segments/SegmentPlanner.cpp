#include "SegmentPlanner.h"

#include "AreaToolPlanners.h"
#include "Geodesy.h"
#include "ToolPlanning.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <QCoreApplication>

namespace sortie::mission {

using namespace toolplanning;

namespace {

// The first figure point that is not a position, or -1.
int firstInvalidPoint(const SegmentFigure &f)
{
    for (size_t i = 0; i < f.points.size(); ++i)
        if (!f.points[i].isValid())
            return int(i);
    return -1;
}

double pointAltitude(const SegmentFigure &f, size_t i)
{
    return i < f.pointAltitudes.size() ? f.pointAltitudes[i] : 0.0;
}

// ---- the point tools and the orbit (the area and outline tools: AreaToolPlanners) ----

SegmentPlanOutcome planPointTool(AlgorithmKind kind, const SegmentFigure &f, const Common &c)
{
    if (f.points.empty())
        return fail(QCoreApplication::translate("SegmentPlanner", "The segment has no point"), 0);
    if (!f.points[0].isValid())
        return fail(QCoreApplication::translate("SegmentPlanner", "Point 1 is not a position on the globe"), 0);
    SegmentPlan plan;
    PlannedPoint p = point(f.points[0], pointAltitude(f, 0), f.pointFrame, c.speed);
    if (kind == AlgorithmKind::TakeOff)
        p.kind = PlannedPoint::Kind::Takeoff;
    if (kind == AlgorithmKind::Landing) {
        p.kind = PlannedPoint::Kind::Landing;
        p.height = 0.0;
        p.frame = HeightFrame::Agl;
    }
    plan.points.push_back(p);
    return {std::move(plan), {}, -1};
}

SegmentPlanOutcome planCircle(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx)
{
    if (f.points.empty())
        return fail(QCoreApplication::translate("SegmentPlanner", "The circle has no centre point"), 0);
    const GeoPoint centre = f.points[0];
    if (!centre.isValid())
        return fail(QCoreApplication::translate("SegmentPlanner", "The circle's centre is not a position on the globe"), 0);
    const double radius = f.parameters.empty() ? 0.0 : f.parameters[0];
    if (!(radius > 0) || !std::isfinite(radius))
        return fail(QCoreApplication::translate("SegmentPlanner", "The circle needs a positive radius (metres, the figure's first parameter)"));
    if (radius > kMaxScanRadiusMeters)
        return fail(QCoreApplication::translate("SegmentPlanner", "The circle's radius of %1 m is over the %2 m a segment may span").arg(m1(radius), m1(kMaxScanRadiusMeters)));
    const int loops = int(r.number(QStringLiteral("loops"), 1.0));
    const bool clockwise = r.boolean(QStringLiteral("flightClockwise"), true);
    const auto given = r.number(QStringLiteral("basePointsQnt"));
    const int perLap = given ? int(*given) : circlePointsPerLap(radius);
    if (size_t(perLap) * size_t(loops) > size_t(kMaxPlannedPoints))
        return fail(QCoreApplication::translate("SegmentPlanner", "loops: %1 laps of %2 points are too many").arg(loops).arg(perLap));

    double start = 0.0;  // bearing of the first point from the centre: towards where the vehicle comes from
    if (ctx.previousPosition && ctx.previousPosition->isValid() && !(*ctx.previousPosition == centre))
        if (const auto inv = geodesicInverse(centre, *ctx.previousPosition))
            start = inv->azimuth1Deg;
    SegmentPlan plan;
    const double step = (clockwise ? 360.0 : -360.0) / perLap;
    const double height = pointAltitude(f, 0);
    for (int k = 0; k <= perLap * loops; ++k)
        plan.points.push_back(point(geodesicDirect(centre, start + step * (k % perLap), radius).point, height, f.pointFrame, c.speed));
    plan.passes = loops;
    plan.notes.push_back(QCoreApplication::translate("SegmentPlanner", "Orbit of %1 m radius: %n lap(s) of %2 points, %3", nullptr, int(loops))
                             .arg(m1(radius)).arg(perLap)
                             .arg(clockwise ? QCoreApplication::translate("SegmentPlanner", "clockwise")
                                            : QCoreApplication::translate("SegmentPlanner", "counter-clockwise")));
    return {std::move(plan), {}, -1};
}

void markUserActions(SegmentPlan &plan, const QString &execution, bool noActionsAtLastPoint)
{
    const bool forwardOnly = execution == QLatin1String("ACTIONS_ON_FORWARD_PASSES");
    const bool startOnly = execution == QLatin1String("ONLY_AT_START");
    for (size_t i = 0; i < plan.points.size(); ++i) {
        PlannedPoint &p = plan.points[i];
        p.userActions = startOnly ? i == 0 : forwardOnly ? p.onPass : true;
    }
    if (noActionsAtLastPoint && plan.points.size() > 1)
        plan.points.back().userActions = false;
}

} // namespace

int circlePointsPerLap(double radius)
{
    if (!(radius > 1.0))
        return 8;
    // sagitta r·(1 − cos(π/n)) ≤ 1 m
    const double n = std::numbers::pi / std::acos(1.0 - 1.0 / radius);
    return std::clamp(int(std::ceil(n)), 8, 360);
}

SegmentPlanOutcome planSegment(const AlgorithmDefinition &algorithm, const SegmentFigure &figure,
                               const ParameterValues &values, const PlanContext &context)
{
    const ParameterReader reader(algorithm, values);
    if (std::vector<QString> problems = reader.problems(); !problems.empty()) {
        SegmentPlanOutcome o;
        o.errors = std::move(problems);
        return o;
    }
    if (const int bad = firstInvalidPoint(figure); bad >= 0)
        return fail(QCoreApplication::translate("SegmentPlanner", "Point %1 is not a position on the globe (latitude and longitude in range)").arg(bad + 1), bad);
    const Common common = commonOf(reader, context);
    if (!(common.speed > 0))
        return fail(QCoreApplication::translate("SegmentPlanner", "speed: the segment needs a positive speed"));

    SegmentPlanOutcome out;
    switch (algorithm.kind) {
    case AlgorithmKind::Waypoint:
    case AlgorithmKind::TakeOff:
    case AlgorithmKind::Landing: out = planPointTool(algorithm.kind, figure, common); break;
    case AlgorithmKind::Circle: out = planCircle(figure, reader, common, context); break;
    case AlgorithmKind::Perimeter: out = planPerimeter(figure, reader, common, context); break;
    case AlgorithmKind::AreaScan:
    case AlgorithmKind::Photogrammetry:
    case AlgorithmKind::CreepingLine: out = planAreaTool(algorithm.kind, figure, reader, common, context); break;
    case AlgorithmKind::Corridor: out = planCorridor(figure, reader, common, context); break;
    case AlgorithmKind::ExpandingSquare: out = planExpandingSquare(figure, reader, common, context); break;
    case AlgorithmKind::FacadeScanner: out = planFacade(figure, reader, common, context); break;
    case AlgorithmKind::Unknown:
        return fail(QCoreApplication::translate("SegmentPlanner", "No planner knows the algorithm '%1'").arg(algorithm.className));
    }
    if (!out.plan)
        return out;
    SegmentPlan &plan = *out.plan;
    plan.altitudeType = reader.selection(QStringLiteral("altitudeType"));
    markUserActions(plan, reader.selection(QStringLiteral("actionExecution")),
                    reader.boolean(QStringLiteral("noActionsAtLastPoint"), false));
    for (size_t i = 1; i < plan.points.size(); ++i)
        plan.length += geodesicDistance(plan.points[i - 1].position, plan.points[i].position);
    return out;
}

} // namespace sortie::mission
