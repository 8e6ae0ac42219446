#include "SegmentPlanning.h"

#include "AlgorithmCatalog.h"

namespace sortie::mission {

PlanContext planContextOf(const RouteSettings &settings)
{
    PlanContext context;
    context.cameras = settings.profile.cameras;
    if (settings.initialSpeed > 0)
        context.defaultSpeed = settings.initialSpeed;
    return context;
}

SegmentFigure plannerFigure(const AlgorithmSegment &segment)
{
    SegmentFigure f;
    f.type = segment.figure;
    for (const FigurePoint &p : segment.points) {
        f.points.push_back(p.position);
        f.pointAltitudes.push_back(p.altitude);
    }
    if (!segment.points.empty())
        f.pointFrame = segment.points.front().altitudeType == AltitudeType::Amsl ? HeightFrame::Amsl : HeightFrame::Agl;
    f.parameters = segment.figureParameters;
    return f;
}

SegmentPlanOutcome planAlgorithmSegment(const AlgorithmSegment &segment, const AlgorithmCatalog &catalog, const PlanContext &context)
{
    const AlgorithmDefinition *def = catalog.byClassName(segment.algorithm);
    if (!def) {
        SegmentPlanOutcome out;
        out.errors.push_back(QStringLiteral("Sortie has no description of %1; the server plans it.").arg(segment.algorithm));
        return out;
    }
    return planSegment(*def, plannerFigure(segment), segment.parameters, context);
}

} // namespace sortie::mission
