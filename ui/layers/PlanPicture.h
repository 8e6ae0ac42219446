#pragma once

#include "MapPalette.h"

#include <QColor>
#include <QImage>
#include <QLineF>
#include <QPolygonF>

#include <optional>

class QPainter;

namespace sortie::ui {

// One vehicle's flight plan (legs flown and ahead, waypoints, the active one ringed) drawn once
// into an image and shown again while nothing it shows has changed: the same waypoints laid out
// for the same picture (FlightPlanLayer's paintViewport), the same active waypoint, the same look.
// Telemetry moving the vehicles then costs one image per plan a frame instead of stroking every
// leg (what TrailPicture does for trails).
class PlanPicture
{
public:
    struct Look
    {
        QColor color;
        QColor outline;   // the map palette's: a waypoint's edge and number
        QColor done;      // legs and waypoints behind the vehicle
        QColor attention; // the ring round the active waypoint
        bool current = false;  // the chosen vehicle's plan: bolder legs
        bool numbered = false; // its waypoints carry their numbers
        int active = -1;       // the waypoint flown to; -1: none
        bool complete = false; // every leg flown
        bool operator==(const Look &) const = default;
        // A look in the palette's colours (outline, done, attention), for `color`.
        static Look in(const MapPalette &colours, const QColor &color)
        {
            Look look;
            look.color = color;
            look.outline = colours.outline;
            look.done = colours.terrain;
            look.attention = colours.attention;
            return look;
        }
    };

    // The waypoints in picture pixels; a new layout or new waypoints forget the image.
    bool isLaidOut() const { return m_laidOut; }
    void layOut(QPolygonF points);
    void invalidate();
    const QPolygonF &points() const { return m_points; }

    // Draws the plan, from the image when it is still right; otherwise draws it anew into an
    // image within `clip` (picture pixels) when its pixels fit in `*budget` (taken from it), or
    // straight onto the painter when they do not.
    void paint(QPainter &painter, const Look &look, const QRectF &clip, qint64 *budget);

    // Strokes a plan as the picture shows it (waypoints outside `clip` are left out).
    static void draw(QPainter &painter, const QPolygonF &points, const Look &look, const QRectF &clip);

    // The part of a segment inside `rect` (Liang–Barsky), or nothing. A dashed pen costs by the
    // length it strokes, visible or not: lines are cut to the picture before they are drawn.
    static std::optional<QLineF> clipped(const QLineF &line, const QRectF &rect);

    // How many plans were drawn anew (into an image or straight) since construction: for tests.
    int redraws() const { return m_redraws; }

private:
    QPolygonF m_points;
    QImage m_image;
    QPointF m_origin;
    Look m_look;
    bool m_laidOut = false;
    bool m_valid = false;
    int m_redraws = 0;
};

} // namespace sortie::ui
