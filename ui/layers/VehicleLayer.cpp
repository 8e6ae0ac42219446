#include "VehicleLayer.h"

#include "LabelPlacer.h"
#include "ModelCoordinates.h"
#include "VehiclePainter.h"

#include <QPainter>

#include <cmath>

namespace sortie::ui {

VehicleLayer::VehicleLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::LeftButton);
    connect(this, &VehicleLayer::modelChanged, this, &VehicleLayer::reload);
    connect(this, &MapLayer::mapChanged, this, [this] { m_camera.setMap(map()); });
    connect(&m_camera, &VehicleCamera::followChanged, this, &VehicleLayer::followChanged);
    connect(&m_camera, &VehicleCamera::autoFitChanged, this, &VehicleLayer::autoFitChanged);
}

int VehicleLayer::positionedCount() const
{
    return int(std::count_if(m_vehicles.begin(), m_vehicles.end(), [](const VehicleMark &v) { return v.hasPosition(); }));
}

void VehicleLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        connect(m_model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                    reloadRows(topLeft.row(), bottomRight.row());
                });
        connect(m_model, &QAbstractItemModel::rowsInserted, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::rowsRemoved, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::rowsMoved, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::modelReset, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::layoutChanged, this, &VehicleLayer::reload);
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    emit modelChanged();
}

void VehicleLayer::setCurrentIndex(int row)
{
    if (row == m_current)
        return;
    m_current = row;
    emit currentIndexChanged();
    m_camera.setCurrent(m_current);
    redraw(); // the labels are laid out again: the current one goes first
}

void VehicleLayer::setTrailLength(int points)
{
    if (!m_trails.setLength(points))
        return;
    emit trailLengthChanged();
    redraw();
}

void VehicleLayer::setTrailsVisible(bool visible)
{
    if (!m_trails.setVisible(visible))
        return;
    emit trailLengthChanged();
    redraw();
}

void VehicleLayer::redraw()
{
    relayout();
}

void VehicleLayer::onViewportChanged()
{
    m_trails.redrawAll();
    MapLayer::onViewportChanged();
}

void VehicleLayer::reload()
{
    m_reader.resolve(m_model, {m_idRole, m_latitudeRole, m_longitudeRole, m_headingRole, m_labelRole,
                               m_homeLatitudeRole, m_homeLongitudeRole, m_staleRole});
    m_trails.redrawAll(); // rows (and so colours) may have changed
    m_vehicles.clear();
    const int rows = m_model ? m_model->rowCount() : 0;
    for (int row = 0; row < rows; ++row) {
        m_vehicles.push_back(m_reader.read(*m_model, row));
        m_trails.record(m_vehicles.back());
    }
    emit vehiclesChanged();
    m_camera.keepInView();
    redraw();
}

void VehicleLayer::reloadRows(int first, int last)
{
    bool positioned = false;
    bool changed = false;
    for (int row = std::max(0, first); row <= last && row < int(m_vehicles.size()); ++row) {
        VehicleMark &vehicle = m_vehicles[size_t(row)];
        VehicleMark next = m_reader.read(*m_model, row);
        next.staleColor = colours().stale;
        if (next == vehicle)
            continue; // the row changed in something this layer does not draw
        changed = true;
        const QColor before = vehicle.shownColor();
        const bool had = vehicle.hasPosition();
        vehicle = std::move(next);
        positioned = positioned || had != vehicle.hasPosition();
        if (vehicle.shownColor() != before)
            m_trails.redrawAll();
        m_trails.record(vehicle);
    }
    if (!changed)
        return;
    if (positioned)
        emit vehiclesChanged();
    m_camera.keepInView();
    redraw();
}

void VehicleLayer::clearTrails()
{
    m_trails.clear();
    redraw();
}

int VehicleLayer::trailPointCount(int row) const
{
    if (row < 0 || row >= count())
        return 0;
    return m_trails.pointCount(m_vehicles[size_t(row)].id);
}

QPointF VehicleLayer::vehiclePosition(int row) const
{
    if (row < 0 || row >= count() || !m_vehicles[size_t(row)].hasPosition())
        return {};
    return viewport().toScreen(m_vehicles[size_t(row)].position);
}

int VehicleLayer::vehicleAt(QPointF position, qreal radius) const
{
    const MapViewport view = viewport();
    int best = -1;
    double bestDistance = radius;
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        if (!m_vehicles[row].hasPosition())
            continue;
        const QPointF s = view.toScreen(m_vehicles[row].position);
        const double d = std::hypot(s.x() - position.x(), s.y() - position.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(row);
        }
    }
    return best;
}

void VehicleLayer::updatePolish()
{
    const MapViewport view = paintViewport();
    m_drawn.assign(m_vehicles.size(), Drawn());
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        const VehicleMark &vehicle = m_vehicles[row];
        Drawn &drawn = m_drawn[row];
        drawn.hasPosition = vehicle.hasPosition();
        if (!drawn.hasPosition)
            continue;
        drawn.position = view.toScreen(vehicle.position);
        if (vehicle.hasHome()) {
            drawn.hasHome = true;
            drawn.home = view.toScreenUnwrapped(nearestCopy(view.toNormalised(drawn.position), vehicle.home));
        }
    }
    m_trails.layOut(view, m_vehicles);
    layOutLabels();
}

// The current vehicle's label is placed first, so it stays by its arrow.
void VehicleLayer::layOutLabels()
{
    std::vector<QPointF> arrows;
    std::vector<size_t> arrowOf(m_drawn.size(), 0);
    std::vector<size_t> order;
    for (size_t row = 0; row < m_drawn.size(); ++row) {
        if (!m_drawn[row].hasPosition)
            continue;
        arrowOf[row] = arrows.size();
        arrows.push_back(m_drawn[row].position);
        if (!m_vehicles[row].label.isEmpty())
            order.push_back(row);
    }
    std::stable_partition(order.begin(), order.end(), [this](size_t row) { return int(row) == m_current; });
    LabelPlacer placer(std::move(arrows));
    for (const QRectF &label : labelsToKeepClearOf())
        placer.keepClear(label);
    for (size_t row : order) {
        const LabelPlacer::Placement placement = placer.place(arrowOf[row], VehiclePainter::labelSize(m_vehicles[row].label));
        m_drawn[row].label = placement.rect;
        m_drawn[row].labelMoved = placement.moved;
    }
}

QRectF VehicleLayer::labelRect(int row) const
{
    if (row < 0 || row >= int(m_drawn.size()) || m_drawn[size_t(row)].label.isEmpty())
        return {};
    return m_drawn[size_t(row)].label.translated(paintOrigin());
}

void VehicleLayer::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    m_trails.paint(*painter);
    VehiclePainter vehicles(*painter, colours());
    const size_t rows = std::min(m_drawn.size(), m_vehicles.size());
    for (size_t row = 0; row < rows; ++row)
        if (m_drawn[row].hasHome)
            vehicles.paintHome(m_vehicles[row], m_drawn[row].home);
    std::vector<size_t> order;
    for (size_t row = 0; row < rows; ++row)
        if (m_drawn[row].hasPosition && int(row) != m_current)
            order.push_back(row);
    if (m_current >= 0 && size_t(m_current) < rows && m_drawn[size_t(m_current)].hasPosition)
        order.push_back(size_t(m_current)); // on top of the others
    for (size_t row : order) {
        const Drawn &drawn = m_drawn[row];
        const VehicleMark &vehicle = m_vehicles[row];
        const bool current = int(row) == m_current;
        vehicles.paintArrow(vehicle, drawn.position, current);
        if (!vehicle.label.isEmpty() && !drawn.label.isEmpty())
            vehicles.paintLabel(vehicle, drawn.position, drawn.label, drawn.labelMoved, current);
    }
}

void VehicleLayer::mousePressEvent(QMouseEvent *event)
{
    m_pressRow = vehicleAt(event->position());
    if (m_pressRow < 0) {
        event->ignore();
        return;
    }
    event->accept();
}

void VehicleLayer::mouseReleaseEvent(QMouseEvent *event)
{
    const int row = std::exchange(m_pressRow, -1);
    if (row >= 0 && row == vehicleAt(event->position())) {
        setCurrentIndex(row);
        emit vehicleClicked(row, int(event->modifiers()));
    }
}

} // namespace sortie::ui
