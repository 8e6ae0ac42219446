#pragma once

#include "AlgorithmCatalog.h"

#include <QMetaType>
#include <QString>

#include <vector>

namespace sortie::mission {

// A tool the map offers for drawing a segment: an algorithm of the catalog with a figure to draw.
// What the map needs of the figure is said here, not compared by name in QML: whether one click
// places it (a point, a circle's centre), whether its outline closes (an area, not a centre line),
// how many clicks it needs, and what to tell the operator while drawing. `valid` is false for "no tool".
struct DrawingTool
{
    Q_GADGET
    Q_PROPERTY(bool valid MEMBER valid)
    Q_PROPERTY(QString algorithm MEMBER algorithm)  // the class name, for RouteEditor::addSegment
    Q_PROPERTY(QString name MEMBER name)
    Q_PROPERTY(bool oneClick MEMBER oneClick)
    Q_PROPERTY(bool closed MEMBER closed)
    Q_PROPERTY(int minimumPoints MEMBER minimumPoints)

public:
    bool valid = false;
    QString algorithm, name;
    bool oneClick = false;
    bool closed = true;
    int minimumPoints = 1;
    FigureType figure = FigureType::Point;

    // "Click the corners of the area (3 so far)": the hint while `clicks` points are drawn.
    Q_INVOKABLE QString hint(int clicks) const;
    bool operator==(const DrawingTool &) const = default;
};

// The catalog's tools: waypoints, take-off and landing are a click, not a tool; the area scan first.
std::vector<DrawingTool> drawingToolsOf(const AlgorithmCatalog &catalog);

} // namespace sortie::mission
