#pragma once

#include "ToolPlanning.h"

// The planners of the tools that fly over a figure's area or along its outline: perimeter, area scan,
// photogrammetry and creeping line, corridor, expanding square, facade. planSegment picks one.
namespace sortie::mission::toolplanning {

SegmentPlanOutcome planPerimeter(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx);
// AreaScan, Photogrammetry or CreepingLine.
SegmentPlanOutcome planAreaTool(AlgorithmKind kind, const SegmentFigure &f, const ParameterReader &r, const Common &c,
                                const PlanContext &ctx);
SegmentPlanOutcome planCorridor(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx);
SegmentPlanOutcome planExpandingSquare(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx);
SegmentPlanOutcome planFacade(const SegmentFigure &f, const ParameterReader &r, const Common &c, const PlanContext &ctx);

} // namespace sortie::mission::toolplanning
