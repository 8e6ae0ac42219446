#pragma once

#include "MapLayer.h"
#include "PlanPicture.h"

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
// Vehicles come from a list model's `vehicleRole` (the fleet's "vehicle"). Each plan is kept as a
// picture (PlanPicture), drawn anew only when its waypoints, its active waypoint, its look or the
// layout change; a frame of moving vehicles only redraws the lines to their waypoints.
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
    // How many times the row's plan was drawn anew (not from its picture).
    Q_INVOKABLE int planRedraws(int row) const;

    // Pixels the plans' pictures may hold together (64 MB); plans beyond it are drawn each time.
    static constexpr qint64 kPictureBudget = 16 * 1024 * 1024;

    void paint(QPainter *painter) override;

protected:
    void onViewportChanged() override;

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
    std::vector<PlanPicture> m_plans; // by row
    int m_current = -1;
};

} // namespace sortie::ui
