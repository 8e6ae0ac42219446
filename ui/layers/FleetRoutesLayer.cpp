#include "FleetRoutesLayer.h"

#include "PlanPicture.h"
#include "Polyline.h"

#include <QGeoCoordinate>
#include <QPainter>

namespace sortie::ui {

namespace {
// Pixels a simplified path may stray from the route: invisible at the legs' widths.
constexpr double kTolerance = 0.75;

int roleOf(const QAbstractItemModel *model, const char *name)
{
    const auto names = model->roleNames();
    for (auto it = names.cbegin(); it != names.cend(); ++it) {
        if (it.value() == name)
            return it.key();
    }
    return -1;
}
} // namespace

FleetRoutesLayer::FleetRoutesLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::NoButton); // only drawn: clicks go to the map and the layers above
}

void FleetRoutesLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
            connect(m_model, signal, this, &FleetRoutesLayer::reload);
        connect(m_model, &QAbstractItemModel::modelReset, this, &FleetRoutesLayer::reload);
        connect(m_model, &QAbstractItemModel::layoutChanged, this, &FleetRoutesLayer::reload);
        connect(m_model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex &first, const QModelIndex &last) { reloadRows(first.row(), last.row()); });
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    reload();
    emit modelChanged();
}

void FleetRoutesLayer::setCurrentVehicleRow(int row)
{
    if (row == m_current)
        return;
    m_current = row;
    emit currentVehicleRowChanged();
    repaint();
}

void FleetRoutesLayer::setHideOpen(bool hide)
{
    if (hide == m_hideOpen)
        return;
    m_hideOpen = hide;
    emit hideOpenChanged();
    emit routesChanged();
    repaint();
}

FleetRoutesLayer::Route FleetRoutesLayer::read(int row) const
{
    const QModelIndex at = m_model->index(row, 0);
    Route route;
    route.path = at.data(roleOf(m_model, "path")).value<QPolygonF>();
    route.color = at.data(roleOf(m_model, "color")).value<QColor>();
    route.state = at.data(roleOf(m_model, "state")).toString();
    const QVariant vehicleRow = at.data(roleOf(m_model, "vehicleRow"));
    route.vehicleRow = vehicleRow.isValid() ? vehicleRow.toInt() : -1;
    route.open = at.data(roleOf(m_model, "open")).toBool();
    return route;
}

void FleetRoutesLayer::reload()
{
    m_routes.clear();
    const int rows = m_model ? m_model->rowCount() : 0;
    for (int row = 0; row < rows; ++row)
        m_routes.push_back(read(row));
    emit routesChanged();
    repaint();
}

void FleetRoutesLayer::reloadRows(int first, int last)
{
    bool changed = false;
    for (int row = std::max(0, first); row <= last && row < int(m_routes.size()); ++row) {
        Route route = read(row);
        if (route == m_routes[size_t(row)])
            continue; // the list's figures changed, not what is drawn
        m_routes[size_t(row)] = std::move(route);
        changed = true;
    }
    if (!changed)
        return;
    emit routesChanged();
    repaint();
}

bool FleetRoutesLayer::shown(const Route &route) const
{
    return route.path.size() > 0 && !(m_hideOpen && route.open);
}

int FleetRoutesLayer::routeCount() const
{
    return int(std::count_if(m_routes.begin(), m_routes.end(), [this](const Route &r) { return shown(r); }));
}

QColor FleetRoutesLayer::routeColor(int row) const
{
    return row >= 0 && row < int(m_routes.size()) ? m_routes[size_t(row)].color : QColor();
}

QPointF FleetRoutesLayer::pointPosition(int row, int index) const
{
    if (row < 0 || row >= int(m_routes.size()) || index < 0 || index >= m_routes[size_t(row)].path.size())
        return {};
    const QPointF p = m_routes[size_t(row)].path[index];
    return viewport().geoToScreen(QGeoCoordinate(p.y(), p.x()));
}

void FleetRoutesLayer::paint(QPainter *painter)
{
    const MapViewport &view = paintViewport();
    const QRectF clip(QPointF(0, 0), view.size());
    // The current vehicle's routes last: over the others.
    std::vector<const Route *> order;
    for (const Route &route : m_routes) {
        if (shown(route) && (m_current < 0 || route.vehicleRow != m_current))
            order.push_back(&route);
    }
    for (const Route &route : m_routes) {
        if (shown(route) && m_current >= 0 && route.vehicleRow == m_current)
            order.push_back(&route);
    }
    for (const Route *route : order) {
        QPolygonF points;
        points.reserve(route->path.size());
        for (const QPointF &p : route->path)
            points.append(view.geoToScreen(QGeoCoordinate(p.y(), p.x())));
        PlanPicture::Look look = PlanPicture::Look::in(colours(), route->color);
        look.current = m_current >= 0 && route->vehicleRow == m_current;
        look.complete = route->state == QLatin1String("flown");
        if (route->state == QLatin1String("planned"))
            look.color.setAlpha(150); // not on the vehicle yet
        PlanPicture::draw(*painter, simplifyPolyline(points, kTolerance), look, clip);
    }
}

} // namespace sortie::ui
