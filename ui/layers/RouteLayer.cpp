#include "RouteLayer.h"

#include "MapView.h"
#include "WebMercator.h"

#include <QGuiApplication>
#include <QPainter>
#include <QStyleHints>

#include <cmath>

namespace sortie::ui {

namespace {

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double length2 = QPointF::dotProduct(ab, ab);
    const double t = length2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    const QPointF nearest = a + t * ab;
    return std::hypot(p.x() - nearest.x(), p.y() - nearest.y());
}

} // namespace

RouteLayer::RouteLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::NoButton);
    m_overlay = createOverlay([this](QPainter &painter) {
        m_painter.paintMoving(painter, m_frame, m_style, m_overlay->position());
    });
    m_overlay->setVisible(false);
    connect(&m_points, &ModelCoordinates::changed, this, &RouteLayer::pointsChanged);
}

void RouteLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_points.model())
        return;
    if (m_points.model())
        disconnect(m_points.model(), &QAbstractItemModel::dataChanged, this, nullptr);
    m_points.setModel(model);
    if (model) {
        // Actions change without moving anything: ModelCoordinates does not report those.
        connect(model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex &topLeft, const QModelIndex &bottomRight, const QList<int> &roles) {
                    const int id = m_points.roleId(m_marksRole);
                    if (id >= 0 && (roles.isEmpty() || roles.contains(id))) {
                        reloadMarks(topLeft.row(), bottomRight.row());
                        m_frameStale = true;
                        polish();
                    }
                });
    }
    emit modelChanged();
}

void RouteLayer::setActionMarksRole(const QString &role)
{
    if (role.toUtf8() == m_marksRole)
        return;
    m_marksRole = role.toUtf8();
    reloadMarks(0, m_points.count() - 1);
    m_frameStale = true;
    polish();
    emit modelChanged();
}

void RouteLayer::reloadMarks(int first, int last)
{
    m_marks.resize(size_t(m_points.count()), 0);
    const int id = m_points.roleId(m_marksRole);
    QAbstractItemModel *model = m_points.model();
    for (int row = std::max(first, 0); row <= last && row < m_points.count(); ++row)
        m_marks[size_t(row)] = id >= 0 && model ? quint8(model->index(row, 0).data(id).toInt()) : quint8(0);
}

void RouteLayer::setLatitudeRole(const QString &role)
{
    m_points.setRoleNames(role.toUtf8(), m_points.longitudeRole());
    emit modelChanged();
}

void RouteLayer::setLongitudeRole(const QString &role)
{
    m_points.setRoleNames(m_points.latitudeRole(), role.toUtf8());
    emit modelChanged();
}

void RouteLayer::setSelectionModel(QItemSelectionModel *selection)
{
    if (selection == m_selection)
        return;
    if (m_selection)
        disconnect(m_selection, nullptr, this, nullptr);
    m_selection = selection;
    if (m_selection) {
        connect(m_selection, &QItemSelectionModel::selectionChanged, this, &RouteLayer::reloadSelection);
        connect(m_selection, &QItemSelectionModel::currentChanged, this, &RouteLayer::reloadSelection);
        connect(m_selection, &QItemSelectionModel::modelChanged, this, &RouteLayer::reloadSelection);
    }
    reloadSelection();
    emit selectionModelChanged();
}

void RouteLayer::setEditable(bool editable)
{
    if (editable == m_editable)
        return;
    m_editable = editable;
    setAcceptedMouseButtons(editable ? Qt::LeftButton : Qt::NoButton);
    emit editableChanged();
}

void RouteLayer::setColor(const QColor &color)
{
    if (color == m_style.leg)
        return;
    m_style.leg = color;
    m_style.marker = color.darker(130);
    emit colorChanged();
    repaint();
    m_overlay->update();
}

void RouteLayer::pointsChanged(int first, int last)
{
    if (int(m_marks.size()) != m_points.count())
        reloadMarks(0, m_points.count() - 1);  // rows came or went
    else
        reloadMarks(first, last);
    reloadSelection();
}

void RouteLayer::reloadSelection()
{
    m_selected.assign(size_t(m_points.count()), false);
    m_current = -1;
    if (m_selection && m_selection->model() == m_points.model()) {
        for (const QItemSelectionRange &range : m_selection->selection()) {
            for (int row = range.top(); row <= range.bottom() && row < m_points.count(); ++row)
                m_selected[size_t(row)] = true;
        }
        m_current = m_selection->currentIndex().isValid() ? m_selection->currentIndex().row() : -1;
    }
    m_frameStale = true;
    polish();
}

void RouteLayer::onViewportChanged()
{
    m_frameStale = true;
    MapLayer::onViewportChanged();
}

void RouteLayer::updatePolish()
{
    RouteFrame::Input input;
    input.points = &m_points.points();
    input.selected = &m_selected;
    input.marks = &m_marks;
    input.current = m_current;
    input.markerRadius = m_style.markerRadius;
    if (m_dragging) {
        input.draggedRows = m_dragRows;
        input.dragOffset = m_dragOffset;
    }
    const MapViewport view = paintViewport();
    if (m_frameStale || !m_dragging) {
        // Counted as visible: inside the map when laid out (the picture reaches beyond it).
        input.visibleArea = QRectF(QPointF(pictureMargin(), pictureMargin()), viewport().size());
        m_frame = RouteFrame::build(input, view);
        m_frameStale = false;
        repaint();
    } else {
        m_frame.updateMoving(input, view);
    }
    placeOverlay();
    emit frameChanged();
}

// The overlay covers only the moving part: the scene graph recomposites just that area.
void RouteLayer::placeOverlay()
{
    const QRect bounds = RoutePainter::movingBounds(m_frame, m_style).toAlignedRect();
    m_overlay->setVisible(!bounds.isEmpty());
    if (bounds.isEmpty())
        return;
    m_overlay->setPosition(bounds.topLeft());
    m_overlay->setSize(bounds.size());
    m_overlay->update();
}

void RouteLayer::paint(QPainter *painter)
{
    // The halo and the numbers follow the theme; the legs are the colour the view gives.
    m_style.halo = colours().halo;
    m_style.text = colours().markText;
    m_painter.paintStill(*painter, m_frame, m_style);
}

int RouteLayer::waypointAt(QPointF position, qreal radius) const
{
    const MapViewport view = viewport();
    const std::vector<QPointF> &points = m_points.points();
    int best = -1;
    double bestDistance = radius;
    for (size_t row = 0; row < points.size(); ++row) {
        if (std::isnan(points[row].x()))
            continue;
        const QPointF s = view.toScreen(points[row]);
        const double d = std::hypot(s.x() - position.x(), s.y() - position.y());
        // Ties go to the later waypoint, which is drawn on top.
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(row);
        }
    }
    return best;
}

int RouteLayer::legAt(QPointF position, qreal tolerance) const
{
    const MapViewport view = viewport();
    const std::vector<QPointF> &points = m_points.points();
    int best = -1;
    double bestDistance = tolerance;
    for (size_t i = 1; i < points.size(); ++i) {
        if (std::isnan(points[i - 1].x()) || std::isnan(points[i].x()))
            continue;
        const QPointF a = view.toScreen(points[i - 1]);
        const QPointF b = view.toScreenUnwrapped(nearestCopy(view.toNormalised(a), points[i]));
        const double d = distanceToSegment(position, a, b);
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i - 1);
        }
    }
    return best;
}

QList<int> RouteLayer::waypointsIn(const QRectF &rect) const
{
    const MapViewport view = viewport();
    const std::vector<QPointF> &points = m_points.points();
    QList<int> rows;
    for (size_t row = 0; row < points.size(); ++row) {
        if (!std::isnan(points[row].x()) && rect.contains(view.toScreen(points[row])))
            rows.append(int(row));
    }
    return rows;
}

void RouteLayer::selectInRect(const QRectF &rect, int modifiers)
{
    if (!m_selection || m_selection->model() != m_points.model() || !model())
        return;
    QItemSelection selection;
    const QList<int> rows = waypointsIn(rect);
    for (qsizetype i = 0; i < rows.size();) {
        qsizetype j = i;
        while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1)
            ++j;
        selection.select(model()->index(rows[i], 0), model()->index(rows[j], 0));
        i = j + 1;
    }
    const auto mode = (Qt::KeyboardModifiers(modifiers) & Qt::ControlModifier) ? QItemSelectionModel::Select
                                                                                 : QItemSelectionModel::ClearAndSelect;
    m_selection->select(selection, mode | QItemSelectionModel::Rows);
}

QPointF RouteLayer::waypointPosition(int row) const
{
    if (!m_points.isValid(row))
        return {};
    return viewport().toScreen(m_points.points()[size_t(row)]);
}

void RouteLayer::fitToMap(qreal margin)
{
    if (!map())
        return;
    double south = 90, north = -90, west = 180, east = -180;
    bool any = false;
    for (const QPointF &p : m_points.points()) {
        if (std::isnan(p.x()))
            continue;
        const QGeoCoordinate c = WebMercator::unproject(p);
        south = std::min(south, c.latitude());
        north = std::max(north, c.latitude());
        west = std::min(west, c.longitude());
        east = std::max(east, c.longitude());
        any = true;
    }
    if (any)
        map()->fitBounds(south, west, north, east, margin);
}

QPointF RouteLayer::normalisedAt(QPointF screen) const
{
    return viewport().toNormalised(screen);
}

void RouteLayer::pressWaypoint(int row, Qt::KeyboardModifiers modifiers)
{
    if (!m_selection || m_selection->model() != m_points.model() || !model())
        return;
    const QModelIndex index = model()->index(row, 0);
    using Flag = QItemSelectionModel::SelectionFlag;
    if (modifiers & Qt::ControlModifier) {
        m_selection->setCurrentIndex(index, Flag::Toggle | Flag::Rows);
    } else if ((modifiers & Qt::ShiftModifier) && m_selection->currentIndex().isValid()) {
        const int from = m_selection->currentIndex().row();
        const QItemSelection range(model()->index(std::min(from, row), 0), model()->index(std::max(from, row), 0));
        m_selection->select(range, Flag::Select | Flag::Rows);
        m_selection->setCurrentIndex(index, Flag::NoUpdate);
    } else if (row >= int(m_selected.size()) || !m_selected[size_t(row)]) {
        m_selection->setCurrentIndex(index, Flag::ClearAndSelect | Flag::Rows);
    } else {
        m_selection->setCurrentIndex(index, Flag::NoUpdate);
    }
}

void RouteLayer::setDragging(bool dragging)
{
    if (dragging == m_dragging)
        return;
    m_dragging = dragging;
    emit draggingChanged();
}

void RouteLayer::mousePressEvent(QMouseEvent *event)
{
    m_pressRow = m_editable ? waypointAt(event->position()) : -1;
    m_pressLeg = (m_editable && m_pressRow < 0) ? legAt(event->position()) : -1;
    if (m_pressRow < 0 && m_pressLeg < 0) {
        event->ignore(); // the map's
        return;
    }
    m_pressPos = event->position();
    m_pressModifiers = event->modifiers();
    if (m_pressRow >= 0)
        pressWaypoint(m_pressRow, m_pressModifiers);
    if (map())
        map()->forceActiveFocus(Qt::MouseFocusReason);
    event->accept();
}

void RouteLayer::mouseMoveEvent(QMouseEvent *event)
{
    if (map())
        map()->setCursorPosition(event->position());
    if (m_pressRow < 0)
        return;
    if (!m_dragging) {
        if ((event->position() - m_pressPos).manhattanLength() < QGuiApplication::styleHints()->startDragDistance())
            return;
        const bool moveSelection = m_pressRow < int(m_selected.size()) && m_selected[size_t(m_pressRow)];
        m_dragRows.clear();
        if (moveSelection) {
            for (size_t row = 0; row < m_selected.size(); ++row) {
                if (m_selected[row] && m_points.isValid(int(row)))
                    m_dragRows.push_back(int(row));
            }
        } else {
            m_dragRows.push_back(m_pressRow);
        }
        setDragging(true);
        m_frameStale = true; // the dragged rows leave the still part
    }
    m_dragOffset = normalisedAt(event->position()) - normalisedAt(m_pressPos);
    polish();
}

void RouteLayer::mouseReleaseEvent(QMouseEvent *event)
{
    const int pressRow = std::exchange(m_pressRow, -1);
    const int pressLeg = std::exchange(m_pressLeg, -1);
    if (m_dragging) {
        QList<int> rows;
        QList<QGeoCoordinate> coordinates;
        rows.reserve(qsizetype(m_dragRows.size()));
        coordinates.reserve(qsizetype(m_dragRows.size()));
        for (int row : m_dragRows) {
            rows.append(row);
            coordinates.append(WebMercator::unproject(m_points.points()[size_t(row)] + m_dragOffset));
        }
        setDragging(false);
        m_dragRows.clear();
        m_frameStale = true;
        polish();
        emit waypointsMoved(rows, coordinates);
    } else if (pressRow >= 0) {
        emit waypointClicked(pressRow, int(m_pressModifiers));
    } else if (pressLeg >= 0) {
        emit legClicked(pressLeg, viewport().screenToGeo(event->position()), int(m_pressModifiers));
    }
}

void RouteLayer::mouseUngrabEvent()
{
    m_pressRow = -1;
    m_pressLeg = -1;
    if (m_dragging) {
        setDragging(false);
        m_dragRows.clear();
        m_frameStale = true;
        polish();
    }
}

} // namespace sortie::ui
