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
        connect(v, &vehicle::Vehicle::missionChanged, this, [this] {
            emit plansChanged();
            repaint();
        });
        // Telemetry moves the vehicle's line to its waypoint, the active waypoint, the take-off point.
        connect(v, &vehicle::Vehicle::telemetryChanged, this, &FlightPlanLayer::repaint);
    }
    emit plansChanged();
    repaint();
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
    const QColor done(0x9e, 0x9e, 0x9e);
    // The take-off point of vehicles that report no home (the vehicle layer draws reported homes).
    for (int row : order) {
        const vehicle::Vehicle *v = vehicleAt(row);
        if (!v || v->home().isValid())
            continue;
        const QGeoCoordinate takeoff = FlightStatus::homeOf(*v);
        if (!takeoff.isValid())
            continue;
        const QRectF box(view.geoToScreen(takeoff) - QPointF(7, 7), QSizeF(14, 14));
        painter->setPen(QPen(Qt::white, 1.5));
        painter->setBrush(vehicleColor(row).darker(120));
        painter->drawRect(box);
        painter->setPen(Qt::white);
        painter->drawText(box, Qt::AlignCenter, QStringLiteral("H"));
    }
    for (int row : order) {
        const vehicle::Vehicle *v = vehicleAt(row);
        if (!v || v->mission().empty())
            continue;
        const bool current = row == m_current;
        const int active = activeWaypoint(row);
        const bool complete = v->missionState() == QLatin1String("complete");
        QColor color = vehicleColor(row);
        if (!current && m_current >= 0)
            color.setAlpha(150);
        QPolygonF points;
        for (const vehicle::MissionItem &item : v->mission())
            points.append(view.geoToScreen(vehicle::coordinateOf(item)));
        // A waypoint is behind once the vehicle flies to a later one (or the mission is complete).
        auto behind = [&](int index) { return complete || (active >= 0 && index < active); };
        for (int i = 1; i < points.size(); ++i) {
            const bool flown = behind(i);
            painter->setPen(flown ? QPen(done, 2, Qt::DashLine, Qt::RoundCap)
                                  : QPen(color, current ? 4 : 2.5, Qt::SolidLine, Qt::RoundCap));
            painter->drawLine(points[i - 1], points[i]);
        }
        // From the vehicle to where it flies now.
        const QGeoCoordinate position = v->position();
        if (active >= 0 && position.isValid()) {
            painter->setPen(QPen(color, 2, Qt::DashLine, Qt::RoundCap));
            painter->drawLine(view.geoToScreen(position), points[active]);
        }
        // Numbers for the current vehicle's waypoints only (text is the costly part); the others
        // get plain dots, and nothing off the picture is drawn.
        const QRectF picture = QRectF(QPointF(0, 0), view.size()).adjusted(-12, -12, 12, 12);
        for (int i = 0; i < points.size(); ++i) {
            if (!picture.contains(points[i]))
                continue;
            const bool isActive = i == active;
            const bool numbered = current || m_current < 0;
            const double radius = isActive ? 10 : numbered ? 8 : 4;
            if (isActive) {
                painter->setPen(QPen(QColor(0xff, 0xd6, 0x00), 3));
                painter->setBrush(Qt::NoBrush);
                painter->drawEllipse(points[i], radius + 4, radius + 4);
            }
            painter->setPen(QPen(Qt::white, 1.5));
            painter->setBrush(behind(i) ? done : color);
            painter->drawEllipse(points[i], radius, radius);
            if (!numbered && !isActive)
                continue;
            painter->setPen(Qt::white);
            painter->drawText(QRectF(points[i] - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)), Qt::AlignCenter,
                              QString::number(i + 1));
        }
    }
}

} // namespace sortie::ui
