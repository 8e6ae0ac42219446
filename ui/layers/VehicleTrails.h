#pragma once

#include "TrailPicture.h"
#include "VehicleMark.h"

#include <QHash>

#include <deque>
#include <vector>

class QPainter;

namespace sortie::ui {

class MapViewport;

// Where each vehicle has been, recorded from its reported positions and kept by vehicle id (a
// trail survives its row moving), cut to the newest `length` points, and shown through one
// TrailPicture. A layout strokes only each trail's piece since the last one; trails are drawn
// whole again on a new layout (redrawAll) or once the points cut from their old ends reach a
// sixteenth of `length` (until then the picture still shows them).
class VehicleTrails
{
public:
    int length() const { return m_length; }
    // False when it was that already.
    bool setLength(int points);
    bool isVisible() const { return m_visible; }
    bool setVisible(bool visible);

    // The vehicle's position now: a new trail point unless it has not moved (or has none).
    void record(const VehicleMark &vehicle);
    void clear();
    // The next layout draws every trail whole (a new viewport, new colours, rows changed).
    void redrawAll();
    int pointCount(const QString &vehicleId) const;

    // Projects the trails of `vehicles` (those with a position) for the picture in `view`.
    void layOut(const MapViewport &view, const std::vector<VehicleMark> &vehicles);
    void paint(QPainter &painter);

private:
    struct Trail
    {
        std::deque<QPointF> points; // normalised, oldest first
        qint64 dropped = 0;         // points cut from the front so far
        qint64 drawn = 0;           // points (counted from the first ever) in the picture
    };
    void cut(Trail &trail);

    QHash<QString, Trail> m_trails;
    TrailPicture m_picture;
    bool m_stale = true; // the picture must be drawn whole again
    qint64 m_cutSinceRedraw = 0;
    int m_length = 3000;
    bool m_visible = true;
};

} // namespace sortie::ui
