#pragma once

#include "AlgorithmSegment.h"
#include "Route.h"
#include "SegmentPlanner.h"

namespace sortie::mission {

// The segment planner (SegmentPlanner.h) applied to the plan model's values.

class AlgorithmCatalog;

// What planning a segment of this route locally knows: the profile's cameras, the route's speed.
PlanContext planContextOf(const RouteSettings &settings);

// The figure the segment planner takes.
SegmentFigure plannerFigure(const AlgorithmSegment &segment);
// What the segment flies, planned the way sortie-sim processes it; an outcome with an error when
// no definition in `catalog` describes the algorithm.
SegmentPlanOutcome planAlgorithmSegment(const AlgorithmSegment &segment, const AlgorithmCatalog &catalog,
                                        const PlanContext &context = {});

} // namespace sortie::mission
