#include "AlgorithmSegment.h"

#include "AlgorithmCatalog.h"

namespace sortie::mission {

AlgorithmKind AlgorithmSegment::kind() const
{
    return algorithmKindOf(algorithm);
}

const QString *AlgorithmSegment::value(QStringView name) const
{
    for (const ParameterValue &v : parameters)
        if (v.name == name)
            return &v.value;
    return nullptr;
}

void AlgorithmSegment::setValue(const QString &name, const QString &text)
{
    for (ParameterValue &v : parameters) {
        if (v.name == name) {
            v.value = text;
            return;
        }
    }
    parameters.push_back({name, text});
}

QString algorithmLabel(const AlgorithmSegment &segment)
{
    if (const AlgorithmDefinition *d = AlgorithmCatalog::builtIn().byClassName(segment.algorithm); d && !d->displayName.isEmpty())
        return d->displayName;
    const qsizetype dot = segment.algorithm.lastIndexOf(QLatin1Char('.'));
    QString name = segment.algorithm.mid(dot + 1);
    if (name.endsWith(QLatin1String("Algorithm")))
        name.chop(9);
    return name.isEmpty() ? QStringLiteral("Unknown segment") : name;
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
