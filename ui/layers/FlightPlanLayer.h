#pragma once

#include "MapLayer.h"

#include <QAbstractItemModel>
#include <QPointer>

#include <vector>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::ui {

// The mission each vehicle carries (Vehicle::mission(), as uploaded to it or read back), drawn
// under the vehicles: the legs already flown thin and dashed grey, the legs ahead in the
// vehicle's colour, a dashed line from the vehicle to the waypoint it flies to, waypoints with
// the active one ringed. The current vehicle's plan is drawn over the others, bolder and with
// numbered waypoints (the others get dots: text is what costs when many vehicles fly missions).
// Vehicles come from a list model's `vehicleRole` (the fleet's "vehicle").
class FlightPlanLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *model READ model WRITE setModel NOTIFY modelChanged)
    Q_PROPERTY(QString vehicleRole MEMBER m_vehicleRole NOTIFY modelChanged)
    Q_PROPERTY(int currentIndex READ currentIndex WRITE setCurrentIndex NOTIFY currentIndexChanged)
    Q_PROPERTY(int planCount READ planCount NOTIFY plansChanged)

public:
    explicit FlightPlanLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *model() const { return m_model; }
    void setModel(QAbstractItemModel *model);
    int currentIndex() const { return m_current; }
    void setCurrentIndex(int row);
    // Vehicles with a mission to draw.
    int planCount() const;

    // For tests and tools: the row's mission length, its active waypoint (-1: none), and where
    // a waypoint is drawn (item pixels).
    Q_INVOKABLE int waypointCount(int row) const;
    Q_INVOKABLE int activeWaypoint(int row) const;
    Q_INVOKABLE QPointF waypointPosition(int row, int index) const;

    void paint(QPainter *painter) override;

signals:
    void modelChanged();
    void currentIndexChanged();
    void plansChanged();

private:
    void reload();
    vehicle::Vehicle *vehicleAt(int row) const;

    QPointer<QAbstractItemModel> m_model;
    QString m_vehicleRole = QStringLiteral("vehicle");
    std::vector<QPointer<vehicle::Vehicle>> m_vehicles;
    std::vector<int> m_active; // each row's active waypoint at the last repaint
    int m_current = -1;
};

} // namespace sortie::ui
