#pragma once

#include "AlgorithmCatalog.h"

#include <QVariantList>

namespace sortie::mission {

// The tools the map offers for drawing a segment, one per algorithm of the catalog that has a
// figure to draw (waypoints, take-off and landing are a click, not a tool); the area scan first.
// Each: {algorithm, name, figure ("polygon", "polyline", "circle", "point"), minimumPoints}.
QVariantList drawingToolsOf(const AlgorithmCatalog &catalog);

} // namespace sortie::mission
