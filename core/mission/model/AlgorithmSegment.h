#pragma once

#include "AlgorithmDefinition.h"
#include "GeoPoint.h"
#include "ServerOrigin.h"
#include "WaypointAction.h"

#include <vector>

namespace sortie::mission {

// A point of a figure with the altitude it carries on the wire.
struct FigurePoint
{
    GeoPoint position;
    double altitude = 0.0;  // metres, in altitudeType's reference
    AltitudeType altitudeType = AltitudeType::Agl;
    bool operator==(const FigurePoint &) const = default;
};

// A segment of any UgCS traverse algorithm other than a waypoint or an area scan — photogrammetry,
// circle, perimeter, corridor, expanding square, creeping line, facade scanner, or one a newer
// server has and Sortie does not know — held the way the server describes it: its algorithm's
// class name, its figure and its parameters as wire name/value text. Editors and planners read
// it through the algorithm's definition (AlgorithmCatalog, or the server's own description); a
// parameter no definition names is kept as it came and edited as raw text. Nothing is dropped.
struct AlgorithmSegment
{
    QString algorithm;                     // the full class name (SegmentDefinition.algorithmClassName)
    FigureType figure = FigureType::Point;
    std::vector<FigurePoint> points;       // polygons open: the wire's closing point is not kept
    std::vector<double> figureParameters;  // Figure.parameters: a circle's radius (m)
    ParameterValues parameters;            // wire names and text, in the order received
    std::vector<WaypointAction> actions;
    ServerOrigin origin;

    AlgorithmKind kind() const;
    // The value text of a parameter, or nullptr when the segment does not carry it.
    const QString *value(QStringView name) const;
    // Sets (or adds, at the end) a parameter's text.
    void setValue(const QString &name, const QString &text);
    bool operator==(const AlgorithmSegment &) const = default;
};

// "Circle", "Photogrammetry", or the class's short name for an algorithm Sortie does not know.
QString algorithmLabel(const AlgorithmSegment &segment);

} // namespace sortie::mission
