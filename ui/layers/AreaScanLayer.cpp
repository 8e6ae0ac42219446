#include "AreaScanLayer.h"

#include "MapView.h"
#include "WebMercator.h"

#include <QGuiApplication>
#include <QPainter>
#include <QStyleHints>

#include <cmath>

namespace sortie::ui {

AreaScanLayer::AreaScanLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::NoButton);
    auto redraw = [this] {
        polish();
        repaint();
    };
    connect(&m_polygon, &ModelCoordinates::changed, this, redraw);
    connect(&m_transects, &ModelCoordinates::changed, this, redraw);
}

void AreaScanLayer::setPolygonModel(QAbstractItemModel *model)
{
    if (model == m_polygon.model())
        return;
    m_polygon.setModel(model);
    emit modelsChanged();
}

void AreaScanLayer::setTransectModel(QAbstractItemModel *model)
{
    if (model == m_transects.model())
        return;
    m_transects.setModel(model);
    emit modelsChanged();
}

namespace {
std::vector<QGeoCoordinate> toCoordinates(const QVariantList &list)
{
    std::vector<QGeoCoordinate> out;
    for (const QVariant &v : list) {
        const QGeoCoordinate c = v.value<QGeoCoordinate>();
        if (c.isValid())
            out.push_back(c);
    }
    return out;
}
} // namespace

void AreaScanLayer::setPolygon(const QVariantList &coordinates)
{
    m_polygonList = coordinates;
    m_ownPolygon.assign(toCoordinates(coordinates));
    m_polygon.setModel(&m_ownPolygon);
    emit modelsChanged();
}

void AreaScanLayer::setPath(const QVariantList &coordinates)
{
    m_pathList = coordinates;
    m_ownPath.assign(toCoordinates(coordinates));
    m_transects.setModel(&m_ownPath);
    emit modelsChanged();
}

void AreaScanLayer::setEditable(bool editable)
{
    if (editable == m_editable)
        return;
    m_editable = editable;
    setAcceptedMouseButtons(editable ? Qt::LeftButton | Qt::RightButton : Qt::NoButton);
    emit editableChanged();
}

void AreaScanLayer::setClosed(bool closed)
{
    if (closed == m_closed)
        return;
    m_closed = closed;
    emit shapeChanged();
    polish();
    repaint();
}

void AreaScanLayer::setRadius(double meters)
{
    const double r = std::isfinite(meters) && meters > 0 ? meters : 0.0;
    if (r == m_radius)
        return;
    m_radius = r;
    emit shapeChanged();
    polish();
    repaint();
}

double AreaScanLayer::metersPerUnit() const
{
    if (m_polygon.points().empty())
        return 0.0;
    const QGeoCoordinate centre = WebMercator::unproject(m_polygon.points().front());
    return 2 * M_PI * WebMercator::kEarthRadius * std::cos(centre.latitude() * M_PI / 180.0);
}

QPointF AreaScanLayer::radiusHandlePosition() const
{
    const double r = m_pressRadius ? m_dragRadius : m_radius;
    const double unit = metersPerUnit();
    if (!(r > 0) || !(unit > 0))
        return {std::nan(""), std::nan("")};
    return viewport().toScreen(m_polygon.points().front() + QPointF(r / unit, 0));
}

double AreaScanLayer::radiusAt(QPointF position) const
{
    const MapViewport view = viewport();
    const QPointF d = view.toNormalised(position) - m_polygon.points().front();
    return std::hypot(d.x(), d.y()) * metersPerUnit();
}

void AreaScanLayer::setColor(const QColor &color)
{
    if (color == m_color)
        return;
    m_color = color;
    emit colorChanged();
    repaint();
}

QPolygonF AreaScanLayer::project(const std::vector<QPointF> &points, int displaced, QPointF offset,
                                 const MapViewport &view)
{
    QPolygonF out;
    out.reserve(qsizetype(points.size()));
    QPointF anchor;
    bool first = true;
    for (size_t i = 0; i < points.size(); ++i) {
        if (std::isnan(points[i].x()))
            continue;
        const QPointF p = int(i) == displaced ? points[i] + offset : points[i];
        if (first) {
            out.append(view.toScreen(p));
            anchor = view.toNormalised(out.back());
            first = false;
        } else {
            anchor = nearestCopy(anchor, p);
            out.append(view.toScreenUnwrapped(anchor));
        }
    }
    return out;
}

void AreaScanLayer::updatePolish()
{
    // While dragging, the vertex shows where the pointer is, whether or not the model has caught up.
    const bool shown = m_dragging && m_pressVertex >= 0 && m_pressVertex < int(m_polygon.points().size());
    const QPointF displacement = shown ? m_pressPoint + m_dragOffset - m_polygon.points()[size_t(m_pressVertex)] : QPointF();
    m_drawnPolygon = project(m_polygon.points(), shown ? m_pressVertex : -1, displacement, paintViewport());
    m_drawnTransects = project(m_transects.points(), -1, {}, paintViewport());
}

void AreaScanLayer::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    if (m_radius > 0 && !m_drawnPolygon.isEmpty()) {
        const QPointF handle = radiusHandlePosition();
        const double r = std::hypot(handle.x() - m_drawnPolygon.front().x(), handle.y() - m_drawnPolygon.front().y());
        QColor fill = m_color;
        fill.setAlpha(40);
        painter->setPen(QPen(m_color, 2.0, Qt::DashLine));
        painter->setBrush(fill);
        painter->drawEllipse(m_drawnPolygon.front(), r, r);
        painter->setPen(QPen(colours().outline, 1.5));
        painter->setBrush(m_color.darker(120));
        painter->drawEllipse(handle, 6, 6);
    }
    if (!m_closed && m_drawnPolygon.size() >= 2) {
        painter->setPen(QPen(m_color, 3.0));
        painter->setBrush(Qt::NoBrush);
        painter->drawPolyline(m_drawnPolygon);
    } else if (m_drawnPolygon.size() >= 3) {
        QColor fill = m_color;
        fill.setAlpha(50);
        painter->setPen(QPen(m_color, 2.0, Qt::DashLine));
        painter->setBrush(fill);
        painter->drawPolygon(m_drawnPolygon);
    } else if (m_drawnPolygon.size() == 2) {
        painter->setPen(QPen(m_color, 2.0, Qt::DashLine));
        painter->drawPolyline(m_drawnPolygon);
    }
    if (m_drawnTransects.size() >= 2) {
        painter->setPen(QPen(colours().halo, 3.5));
        painter->setBrush(Qt::NoBrush);
        painter->drawPolyline(m_drawnTransects);
        painter->setPen(QPen(m_color.darker(140), 1.8));
        painter->drawPolyline(m_drawnTransects);
    }
    painter->setPen(QPen(colours().outline, 1.5));
    painter->setBrush(m_color.darker(120));
    for (const QPointF &vertex : std::as_const(m_drawnPolygon))
        painter->drawRect(QRectF(vertex - QPointF(5, 5), QSizeF(10, 10)));
}

int AreaScanLayer::vertexAt(QPointF position, qreal radius) const
{
    const MapViewport view = viewport();
    int best = -1;
    double bestDistance = radius;
    const std::vector<QPointF> &points = m_polygon.points();
    for (size_t i = 0; i < points.size(); ++i) {
        if (std::isnan(points[i].x()))
            continue;
        const QPointF s = view.toScreen(points[i]);
        const double d = std::hypot(s.x() - position.x(), s.y() - position.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

int AreaScanLayer::edgeAt(QPointF position, qreal tolerance) const
{
    const QPolygonF polygon = project(m_polygon.points(), -1, {}, viewport());
    if (polygon.size() < 2 || polygon.size() != m_polygon.count())
        return -1;
    int best = -1;
    double bestDistance = tolerance;
    for (qsizetype i = 0; i < polygon.size() - (m_closed ? 0 : 1); ++i) {
        const QPointF a = polygon[i];
        const QPointF b = polygon[(i + 1) % polygon.size()];
        const QPointF ab = b - a;
        const double length2 = QPointF::dotProduct(ab, ab);
        const double t = length2 > 0 ? std::clamp(QPointF::dotProduct(position - a, ab) / length2, 0.0, 1.0) : 0.0;
        const QPointF nearest = a + t * ab;
        const double d = std::hypot(position.x() - nearest.x(), position.y() - nearest.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

QGeoCoordinate AreaScanLayer::dragTarget() const
{
    return WebMercator::unproject(m_pressPoint + m_dragOffset);
}

void AreaScanLayer::mousePressEvent(QMouseEvent *event)
{
    const int vertex = vertexAt(event->position());
    if (event->button() == Qt::RightButton) {
        if (vertex < 0) {
            event->ignore();
            return;
        }
        event->accept();
        emit vertexRemoveRequested(vertex);
        return;
    }
    const QPointF handle = radiusHandlePosition();
    m_pressRadius = !std::isnan(handle.x()) && std::hypot(handle.x() - event->position().x(), handle.y() - event->position().y()) <= 10;
    if (m_pressRadius) {
        m_dragRadius = m_radius;
        m_pressPos = event->position();
        event->accept();
        return;
    }
    m_pressVertex = vertex;
    m_pressEdge = m_pressVertex < 0 ? edgeAt(event->position()) : -1;
    if (m_pressVertex < 0 && m_pressEdge < 0) {
        event->ignore();
        return;
    }
    m_pressPos = event->position();
    m_pressPoint = m_pressVertex >= 0 ? m_polygon.points()[size_t(m_pressVertex)] : QPointF();
    m_dragOffset = {};
    event->accept();
}

void AreaScanLayer::mouseMoveEvent(QMouseEvent *event)
{
    if (map())
        map()->setCursorPosition(event->position());
    if (m_pressRadius) {
        m_dragRadius = radiusAt(event->position());
        polish();
        repaint();
        emit radiusMoved(m_dragRadius, mission::EditStep::Continuing);
        return;
    }
    if (m_pressVertex < 0)
        return;
    if (!m_dragging
        && (event->position() - m_pressPos).manhattanLength() < QGuiApplication::styleHints()->startDragDistance())
        return;
    m_dragging = true;
    const MapViewport view = viewport();
    m_dragOffset = view.toNormalised(event->position()) - view.toNormalised(m_pressPos);
    polish();
    repaint();
    emit vertexMoved(m_pressVertex, dragTarget(), mission::EditStep::Continuing);
}

void AreaScanLayer::mouseReleaseEvent(QMouseEvent *event)
{
    if (std::exchange(m_pressRadius, false)) {
        const double r = radiusAt(event->position());
        polish();
        repaint();
        emit radiusMoved(r, mission::EditStep::Done);
        return;
    }
    const int vertex = std::exchange(m_pressVertex, -1);
    const int edge = std::exchange(m_pressEdge, -1);
    if (m_dragging && vertex >= 0) {
        m_dragging = false;
        const QGeoCoordinate coordinate = dragTarget();
        polish();
        repaint();
        emit vertexMoved(vertex, coordinate, mission::EditStep::Done);
    } else if (edge >= 0) {
        emit edgeClicked(edge, viewport().screenToGeo(event->position()), int(event->modifiers()));
    }
}

void AreaScanLayer::mouseUngrabEvent()
{
    if (std::exchange(m_pressRadius, false))
        emit radiusMoved(m_dragRadius, mission::EditStep::Done);
    const int vertex = std::exchange(m_pressVertex, -1);
    m_pressEdge = -1;
    if (m_dragging) {
        m_dragging = false;
        polish();
        repaint();
        emit vertexMoved(vertex, dragTarget(), mission::EditStep::Done);  // closes the gesture where it got to
    }
}

} // namespace sortie::ui
