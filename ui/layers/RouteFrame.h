#pragma once

#include "MapViewport.h"

#include <QPolygonF>

#include <vector>

namespace sortie::ui {

// What a route looks like on screen for one viewport: the legs inside the view as polylines
// and the waypoint markers to draw, each either labelled with its number or a plain dot (when
// markers would overlap). Built on the GUI thread, drawn by RoutePainter: drawing never reads
// the model. While waypoints are dragged, they and their legs form a separate "moving" part,
// rebuilt alone on every mouse move while the rest stays drawn in the layer's picture.
struct RouteFrame
{
    enum MarkerFlag : quint8 { Labelled = 1, Selected = 2, Current = 4 };
    struct Marker
    {
        QPointF position;
        int row = 0;
        quint8 flags = 0;
        quint8 marks = 0;  // the waypoint's action marks (RouteModel::ActionMark), drawn on labelled markers
    };

    std::vector<QPolygonF> legs;
    std::vector<Marker> markers; // in drawing order: selected and current last, on top
    std::vector<QPolygonF> movingLegs;
    std::vector<Marker> movingMarkers;
    int visibleWaypoints = 0; // markers inside Input::visibleArea
    int labelledWaypoints = 0;

    struct Input
    {
        const std::vector<QPointF> *points = nullptr; // normalised, NaN when unknown
        const std::vector<bool> *selected = nullptr;  // may be shorter than points
        const std::vector<quint8> *marks = nullptr;   // may be shorter than points
        int current = -1;
        std::vector<int> draggedRows;                 // drawn displaced by dragOffset
        QPointF dragOffset;                           // normalised
        double markerRadius = 9.0;
        QRectF visibleArea;                           // counted as visible; empty: the viewport
    };
    static RouteFrame build(const Input &input, const MapViewport &viewport);
    // Rebuilds only the moving part (the drag offset changed, nothing else).
    void updateMoving(const Input &input, const MapViewport &viewport);
};

} // namespace sortie::ui
