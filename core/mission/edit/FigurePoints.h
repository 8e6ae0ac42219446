#pragma once

#include "Segment.h"

#include <vector>

namespace sortie::mission {

// The points of a figure an operator edits, whatever segment holds them: an area scan's corners or
// another algorithm's figure points. The editor's vertex gestures work through it, so they read the
// same for every figure.
struct FigurePoints
{
    std::vector<GeoPoint> *corners = nullptr;        // an area scan
    std::vector<FigurePoint> *points = nullptr;      // any other algorithm
    FigureType figure = FigureType::Polygon;

    int size() const { return corners ? int(corners->size()) : points ? int(points->size()) : 0; }
    // The fewest points the figure keeps: a polygon 3, a polyline 2, a point or circle 1.
    int minimum() const { return figure == FigureType::Polygon ? 3 : figure == FigureType::Polyline ? 2 : 1; }
    bool movable() const { return corners || points; }
    bool growable() const { return figure == FigureType::Polygon || figure == FigureType::Polyline; }
    void set(int i, const GeoPoint &p);
    // A new figure point copies its predecessor's altitude (the first point's, at the front).
    void insert(int i, const GeoPoint &p);
    void erase(int i);
};

// The editable points of `s`; none (size 0) for a waypoint.
FigurePoints figurePointsOf(Segment &s);

} // namespace sortie::mission
