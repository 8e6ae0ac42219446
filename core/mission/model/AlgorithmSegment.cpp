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

} // namespace sortie::mission
