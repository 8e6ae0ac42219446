#include "DrawingTools.h"

#include <QCoreApplication>

#include <algorithm>

namespace sortie::mission {

QString DrawingTool::hint(int clicks) const
{
    if (!valid)
        return {};
    if (figure == FigureType::Polyline)
        return QCoreApplication::translate("MissionPage", "Click the centre line (%1 so far)").arg(clicks);
    if (figure == FigureType::Polygon)
        return QCoreApplication::translate("MissionPage", "Click the corners of the area (%1 so far)").arg(clicks);
    return QCoreApplication::translate("MissionPage", "Click where it goes");
}

std::vector<DrawingTool> drawingToolsOf(const AlgorithmCatalog &catalog)
{
    std::vector<DrawingTool> tools;
    for (const AlgorithmDefinition &d : catalog.algorithms()) {
        if (d.kind == AlgorithmKind::Waypoint || d.kind == AlgorithmKind::TakeOff || d.kind == AlgorithmKind::Landing)
            continue;  // a click on the map adds those
        DrawingTool tool;
        tool.valid = true;
        tool.algorithm = d.className;
        tool.name = d.displayName;
        tool.figure = d.figure;
        tool.oneClick = d.figure != FigureType::Polygon && d.figure != FigureType::Polyline;
        tool.closed = d.figure != FigureType::Polyline;
        tool.minimumPoints = std::max(1, d.minimumPoints);
        if (d.kind == AlgorithmKind::AreaScan)
            tools.insert(tools.begin(), std::move(tool));
        else
            tools.push_back(std::move(tool));
    }
    return tools;
}

} // namespace sortie::mission
