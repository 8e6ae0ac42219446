// The map's drawing tools, read from the algorithm catalog.
#include "DrawingTools.h"

#include <QVariantMap>

#include <algorithm>

namespace sortie::mission {

QVariantList drawingToolsOf(const AlgorithmCatalog &catalog)
{
    QVariantList tools;
    for (const AlgorithmDefinition &d : catalog.algorithms()) {
        if (d.kind == AlgorithmKind::Waypoint || d.kind == AlgorithmKind::TakeOff || d.kind == AlgorithmKind::Landing)
            continue;  // a click on the map adds those
        const QString figure = d.figure == FigureType::Polygon ? QStringLiteral("polygon")
                             : d.figure == FigureType::Polyline ? QStringLiteral("polyline")
                             : d.figure == FigureType::Circle ? QStringLiteral("circle") : QStringLiteral("point");
        const QVariantMap tool{{QStringLiteral("algorithm"), d.className}, {QStringLiteral("name"), d.displayName},
                               {QStringLiteral("figure"), figure}, {QStringLiteral("minimumPoints"), std::max(1, d.minimumPoints)}};
        if (d.kind == AlgorithmKind::AreaScan)
            tools.prepend(tool);
        else
            tools.append(tool);
    }
    return tools;
}

} // namespace sortie::mission
