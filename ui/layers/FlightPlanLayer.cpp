#include "FlightPlanLayer.h"

#include "FlightStatus.h"
#include "MissionProgress.h"
#include "Vehicle.h"
#include "VehiclePalette.h"
#include "WebMercator.h"

#include <QPainter>

#include <cmath>

namespace sortie::ui {

FlightPlanLayer::FlightPlanLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    connect(this, &FlightPlanLayer::modelChanged, this, &FlightPlanLayer::reload);
}

void FlightPlanLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
            connect(m_model, signal, this, &FlightPlanLayer::reload);
        connect(m_model, &QAbstractItemModel::modelReset, this, &FlightPlanLayer::reload);
        connect(m_model, &QAbstractItemModel::layoutChanged, this, &FlightPlanLayer::reload);
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    emit modelChanged();
}

void FlightPlanLayer::setCurrentIndex(int row)
{
    if (row == m_current)
        return;
    m_current = row;
    emit currentIndexChanged();
    repaint();
}

void FlightPlanLayer::reload()
{
    for (const auto &v : m_vehicles)
        if (v)
            disconnect(v, nullptr, this, nullptr);
    m_vehicles.clear();
    m_plans.clear();
    int role = -1;
    if (m_model) {
        const auto names = m_model->roleNames();
        for (auto it = names.cbegin(); it != names.cend(); ++it)
            if (it.value() == m_vehicleRole.toUtf8())
                role = it.key();
    }
    const int rows = m_model && role >= 0 ? m_model->rowCount() : 0;
    for (int row = 0; row < rows; ++row) {
        auto *v = qobject_cast<vehicle::Vehicle *>(m_model->index(row, 0).data(role).value<QObject *>());
        m_vehicles.emplace_back(v);
        if (!v)
            continue;
        connect(v, &vehicle::Vehicle::missionChanged, this, [this, row] {
            m_plans[size_t(row)].invalidate();
            emit plansChanged();
            repaint();
        });
        // Telemetry moves the vehicle's line to its waypoint, the active waypoint, the take-off point
        // (drawn for a vehicle that reports no home): nothing of it is drawn for a vehicle with a
        // reported home and no mission.
        connect(v, &vehicle::Vehicle::telemetryChanged, this, [this, v] {
            if (!v->mission().empty() || !v->home().isValid())
                repaint();
        });
    }
    m_plans.resize(m_vehicles.size());
    emit plansChanged();
    repaint();
}

void FlightPlanLayer::onViewportChanged()
{
    for (PlanPicture &plan : m_plans)
        plan.invalidate(); // laid out for the new picture on the next paint
    MapLayer::onViewportChanged();
}

int FlightPlanLayer::planRedraws(int row) const
{
    return row >= 0 && row < int(m_plans.size()) ? m_plans[size_t(row)].redraws() : 0;
}

vehicle::Vehicle *FlightPlanLayer::vehicleAt(int row) const
{
    return row >= 0 && row < int(m_vehicles.size()) ? m_vehicles[size_t(row)].data() : nullptr;
}

int FlightPlanLayer::planCount() const
{
    return int(std::count_if(m_vehicles.begin(), m_vehicles.end(), [](const auto &v) { return v && !v->mission().empty(); }));
}

int FlightPlanLayer::waypointCount(int row) const
{
    const vehicle::Vehicle *v = vehicleAt(row);
    return v ? int(v->mission().size()) : 0;
}

int FlightPlanLayer::activeWaypoint(int row) const
{
    const vehicle::Vehicle *v = vehicleAt(row);
    if (!v)
        return -1;
    const int active = v->missionCurrent();
    return active >= 0 && active < int(v->mission().size()) ? active : -1;
}

QPointF FlightPlanLayer::waypointPosition(int row, int index) const
{
    const vehicle::Vehicle *v = vehicleAt(row);
    if (!v || index < 0 || index >= int(v->mission().size()))
        return {};
    return viewport().geoToScreen(vehicle::coordinateOf(v->mission()[size_t(index)]));
}

void FlightPlanLayer::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    const MapViewport &view = paintViewport();
    QFont font = painter->font();
    font.setPixelSize(10);
    font.setBold(true);
    painter->setFont(font);
    std::vector<int> order;
    for (int row = 0; row < int(m_vehicles.size()); ++row)
        if (row != m_current)
            order.push_back(row);
    if (m_current >= 0 && m_current < int(m_vehicles.size()))
        order.push_back(m_current); // over the others
    // The take-off point of vehicles that report no home (the vehicle layer draws reported homes).
    for (int row : order) {
        const vehicle::Vehicle *v = vehicleAt(row);
        if (!v || v->home().isValid())
            continue;
        const QGeoCoordinate takeoff = FlightStatus::homeOf(*v);
        if (!takeoff.isValid())
            continue;
        const QRectF box(view.geoToScreen(takeoff) - QPointF(7, 7), QSizeF(14, 14));
        painter->setPen(QPen(colours().outline, 1.5));
        painter->setBrush(client::vehicleColor(row).darker(120));
        painter->drawRect(box);
        painter->setPen(colours().markText);
        painter->drawText(box, Qt::AlignCenter, QStringLiteral("H"));
    }
    const QRectF clip(QPointF(0, 0), view.size());
    qint64 budget = kPictureBudget;
    for (int row : order) {
        const vehicle::Vehicle *v = vehicleAt(row);
        if (!v || v->mission().empty())
            continue;
        PlanPicture &plan = m_plans[size_t(row)];
        if (!plan.isLaidOut()) {
            QPolygonF points;
            points.reserve(qsizetype(v->mission().size()));
            for (const vehicle::MissionItem &item : v->mission())
                points.append(view.geoToScreen(vehicle::coordinateOf(item)));
            plan.layOut(std::move(points));
        }
        PlanPicture::Look look = PlanPicture::Look::in(colours(), client::vehicleColor(row));
        look.current = row == m_current;
        look.numbered = look.current || m_current < 0;
        look.active = activeWaypoint(row);
        look.complete = v->missionState() == QLatin1String("complete");
        if (!look.current && m_current >= 0)
            look.color.setAlpha(150);
        // From the vehicle to where it flies now: it moves every frame, so it is not in the
        // picture (drawn first, under the legs and waypoints).
        const QGeoCoordinate position = v->position();
        if (look.active >= 0 && position.isValid()) {
            if (const auto line = PlanPicture::clipped(QLineF(view.geoToScreen(position), plan.points()[look.active]), clip)) {
                painter->setPen(QPen(look.color, 2, Qt::DashLine, Qt::FlatCap)); // round dash ends cost a curve each
                painter->drawLine(*line);
            }
        }
        plan.paint(*painter, look, clip, &budget);
    }
}

} // namespace sortie::ui
