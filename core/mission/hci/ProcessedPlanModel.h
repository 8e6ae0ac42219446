#pragma once

#include "ProcessedPlan.h"

#include <QAbstractListModel>
#include <QStringList>

namespace sortie::mission {

// The server-processed plan for a map or table: one row per waypoint the vehicle will fly.
class ProcessedPlanModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY planChanged)
    Q_PROPERTY(double estimatedDistance READ estimatedDistance NOTIFY planChanged)
    Q_PROPERTY(double estimatedTime READ estimatedTime NOTIFY planChanged)
    Q_PROPERTY(bool flyable READ flyable NOTIFY planChanged)
    Q_PROPERTY(QStringList errors READ errors NOTIFY planChanged)

public:
    enum Roles {
        LatitudeRole = Qt::UserRole + 1,
        LongitudeRole,
        AltitudeAmslRole,
        GroundElevationRole,
        HeightAboveGroundRole,  // altitudeAmsl - groundElevation
        FrameRole,              // "WGS84", "AGL", "RANGEFINDER", "SMART_AGL"
        SpeedRole,
        KindRole,               // "waypoint", "takeoff", "land"
        ConnectionRole,         // bool: on the server's connection into a segment
        SegmentRole,            // index of the processed segment
        RouteRowRole,           // the edited route's row, -1 if unknown
        StatusRole,             // "processed", "invalid", "modified", "marked"
    };

    explicit ProcessedPlanModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

    void setPlan(ProcessedPlan plan);
    const ProcessedPlan &plan() const { return m_plan; }
    int count() const { return int(m_plan.waypoints.size()); }
    double estimatedDistance() const { return m_plan.estimatedDistance; }
    double estimatedTime() const { return m_plan.estimatedTime; }
    bool flyable() const { return m_plan.flyable(); }
    QStringList errors() const;  // the server's error messages, "Segment 2: ..."

signals:
    void planChanged();

private:
    ProcessedPlan m_plan;
};

} // namespace sortie::mission
