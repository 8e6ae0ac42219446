#pragma once

#include <QPointF>
#include <QRectF>

class QKeyEvent;
class QMouseEvent;
class QTouchEvent;
class QWheelEvent;

namespace sortie::ui {

class MapView;

// What the operator's hands do to a map: a drag pans, Shift+drag draws a selection rectangle,
// a press and release without a drag (or a tap) is a click, the wheel zooms around the cursor,
// arrows pan (Shift: farther), +/- zoom, two fingers pinch-zoom around themselves. It moves the
// view through its public API and reports through the view's signals (clicked, areaSelected,
// panningChanged, selectionRectChanged). Nothing happens while the view is not interactive.
class MapGestures
{
public:
    explicit MapGestures(MapView &view);

    bool isPanning() const { return m_gesture == Gesture::Pan; }
    QRectF selectionRect() const { return m_selectionRect; }

    void mousePress(QMouseEvent *event);
    void mouseMove(QMouseEvent *event);
    void mouseRelease(QMouseEvent *event);
    void mouseUngrab();
    void wheel(QWheelEvent *event);
    void keyPress(QKeyEvent *event);
    void touch(QTouchEvent *event);

private:
    enum class Gesture { None, Pending, Pan, Select, Pinch };
    void setGesture(Gesture gesture);
    void setSelectionRect(const QRectF &rect);
    // The press moved far enough to be a drag, not a click.
    static bool dragged(QPointF from, QPointF to);

    MapView &m_view;
    Gesture m_gesture = Gesture::None;
    QPointF m_pressPos;
    QPointF m_lastPos;
    Qt::KeyboardModifiers m_pressModifiers;
    QRectF m_selectionRect;
    double m_pinchStartDistance = 0;
    double m_pinchStartZoom = 0;
    QPointF m_pinchLastCentre;
};

} // namespace sortie::ui
