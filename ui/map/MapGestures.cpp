#include "MapGestures.h"

#include "MapView.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTouchEvent>
#include <QWheelEvent>
#include <QStyleHints>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
constexpr double kWheelZoomPerNotch = 0.5;
constexpr double kKeyPanPixels = 80.0;
} // namespace

MapGestures::MapGestures(MapView &view)
    : m_view(view)
{
}

bool MapGestures::dragged(QPointF from, QPointF to)
{
    return (to - from).manhattanLength() >= QGuiApplication::styleHints()->startDragDistance();
}

void MapGestures::setGesture(Gesture gesture)
{
    const bool wasPanning = isPanning();
    m_gesture = gesture;
    if (wasPanning != isPanning())
        emit m_view.panningChanged();
}

void MapGestures::setSelectionRect(const QRectF &rect)
{
    if (rect == m_selectionRect)
        return;
    m_selectionRect = rect;
    emit m_view.selectionRectChanged();
}

void MapGestures::mousePress(QMouseEvent *event)
{
    if (!m_view.isInteractive() || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    m_view.forceActiveFocus(Qt::MouseFocusReason);
    m_pressPos = m_lastPos = event->position();
    m_pressModifiers = event->modifiers();
    setGesture(Gesture::Pending);
    event->accept();
}

void MapGestures::mouseMove(QMouseEvent *event)
{
    const QPointF pos = event->position();
    m_view.setCursorPosition(pos);
    if (m_gesture == Gesture::Pending) {
        if (!dragged(m_pressPos, pos))
            return;
        setGesture(m_pressModifiers & Qt::ShiftModifier ? Gesture::Select : Gesture::Pan);
    }
    if (m_gesture == Gesture::Pan) {
        m_view.panBy(pos.x() - m_lastPos.x(), pos.y() - m_lastPos.y());
    } else if (m_gesture == Gesture::Select) {
        setSelectionRect(QRectF(m_pressPos, pos).normalized());
    }
    m_lastPos = pos;
}

void MapGestures::mouseRelease(QMouseEvent *event)
{
    const Gesture gesture = m_gesture;
    setGesture(Gesture::None);
    if (gesture == Gesture::Pending) {
        emit m_view.clicked(m_view.toCoordinate(event->position()), int(m_pressModifiers));
    } else if (gesture == Gesture::Select) {
        const QRectF rect = m_selectionRect;
        setSelectionRect({});
        emit m_view.areaSelected(rect, int(m_pressModifiers));
    }
}

void MapGestures::mouseUngrab()
{
    setGesture(Gesture::None);
    setSelectionRect({});
}

void MapGestures::wheel(QWheelEvent *event)
{
    if (!m_view.isInteractive()) {
        event->ignore();
        return;
    }
    const double notches = event->angleDelta().y() / 120.0;
    m_view.zoomAroundPoint(event->position(), m_view.zoomLevel() + notches * kWheelZoomPerNotch);
    event->accept();
}

void MapGestures::keyPress(QKeyEvent *event)
{
    if (!m_view.isInteractive()) {
        event->ignore();
        return;
    }
    const double step = kKeyPanPixels * (event->modifiers() & Qt::ShiftModifier ? 4 : 1);
    switch (event->key()) {
    case Qt::Key_Left: m_view.panBy(step, 0); break;
    case Qt::Key_Right: m_view.panBy(-step, 0); break;
    case Qt::Key_Up: m_view.panBy(0, step); break;
    case Qt::Key_Down: m_view.panBy(0, -step); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: m_view.zoomIn(); break;
    case Qt::Key_Minus:
    case Qt::Key_Underscore: m_view.zoomOut(); break;
    default: event->ignore(); return;
    }
    event->accept();
}

void MapGestures::touch(QTouchEvent *event)
{
    if (!m_view.isInteractive()) {
        event->ignore();
        return;
    }
    const auto &points = event->points();
    if (event->type() == QEvent::TouchEnd || event->type() == QEvent::TouchCancel || points.isEmpty()) {
        // A tap is a click, as with the mouse.
        if (m_gesture == Gesture::Pending && event->type() == QEvent::TouchEnd && !points.isEmpty())
            emit m_view.clicked(m_view.toCoordinate(points[0].position()), int(m_pressModifiers));
        setGesture(Gesture::None);
        event->accept();
        return;
    }
    if (points.size() >= 2) {
        const QPointF a = points[0].position();
        const QPointF b = points[1].position();
        const QPointF centre = (a + b) / 2.0;
        const double distance = std::max(1.0, std::hypot(a.x() - b.x(), a.y() - b.y()));
        const bool started = m_gesture != Gesture::Pinch || points[0].state() == QEventPoint::Pressed
                             || points[1].state() == QEventPoint::Pressed;
        if (started) {
            setGesture(Gesture::Pinch);
            m_pinchStartDistance = distance;
            m_pinchStartZoom = m_view.zoomLevel();
        } else {
            // One move of the fingers is one change of the view: pan and zoom together.
            MapViewport next = m_view.viewport();
            next.panByPixels(centre - m_pinchLastCentre);
            next.zoomAround(centre, std::clamp(m_pinchStartZoom + std::log2(distance / m_pinchStartDistance),
                                               m_view.minimumZoomLevel(), m_view.maximumZoomLevel()));
            m_view.setViewport(next);
        }
        m_pinchLastCentre = centre;
    } else {
        const QPointF pos = points[0].position();
        if (m_gesture == Gesture::Pinch) {
            setGesture(Gesture::Pan); // one finger lifted: go on panning, never a tap
        } else if (m_gesture == Gesture::None || points[0].state() == QEventPoint::Pressed) {
            m_pressPos = pos;
            m_pressModifiers = event->modifiers();
            setGesture(Gesture::Pending);
        } else if (m_gesture == Gesture::Pending && dragged(m_pressPos, pos)) {
            setGesture(Gesture::Pan);
        }
        if (m_gesture == Gesture::Pan)
            m_view.panBy(pos.x() - m_lastPos.x(), pos.y() - m_lastPos.y());
        m_lastPos = pos;
    }
    event->accept();
}

} // namespace sortie::ui
