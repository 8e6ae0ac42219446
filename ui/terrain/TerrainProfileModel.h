#pragma once

#include "MissionEnums.h"
#include "TerrainProfile.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

namespace sortie::mission {
class RouteModel;
}

namespace sortie::ui {

// The terrain profile of the route being edited, for the profile view: ground, altitude and
// clearance along the flown path from an ElevationService. Edits and new terrain data only mark it
// stale; one recomputation runs per `delay` ms at most (a drag of a waypoint of a 10,000-waypoint
// route emits hundreds of edits a second, the profile is computed once per frame).
class TerrainProfileModel : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QObject *routeModel READ routeModel WRITE setRouteModel NOTIFY routeModelChanged)
    Q_PROPERTY(sortie::terrain::ElevationService *service READ service WRITE setService NOTIFY serviceChanged)
    Q_PROPERTY(double step READ step WRITE setStep NOTIFY stepChanged)
    Q_PROPERTY(int delay READ delay WRITE setDelay NOTIFY delayChanged)
    Q_PROPERTY(int sampleCount READ sampleCount NOTIFY profileChanged)
    Q_PROPERTY(double length READ length NOTIFY profileChanged)
    Q_PROPERTY(bool pending READ isPending NOTIFY profileChanged)
    Q_PROPERTY(QString sourceText READ sourceText NOTIFY profileChanged)
    Q_PROPERTY(double minClearance READ minClearance NOTIFY profileChanged)  // NaN: unknown
    Q_PROPERTY(int lowStretchCount READ lowStretchCount NOTIFY profileChanged)
    Q_PROPERTY(int noDataCount READ noDataCount NOTIFY profileChanged)
    // Counts recomputations: a binding that calls the row functions below reads it to update.
    Q_PROPERTY(int revision READ recomputeCount NOTIFY profileChanged)

public:
    explicit TerrainProfileModel(QObject *parent = nullptr);

    QObject *routeModel() const;
    void setRouteModel(QObject *model);
    terrain::ElevationService *service() const { return m_service; }
    void setService(terrain::ElevationService *service);
    double step() const { return m_step; }
    void setStep(double metres);
    int delay() const { return m_timer.interval(); }
    void setDelay(int milliseconds);

    const terrain::TerrainProfile &profile() const { return m_profile; }
    const terrain::ProfileRoute &route() const { return m_route; }
    int sampleCount() const { return int(m_profile.size()); }
    double length() const { return m_profile.path.length(); }
    bool isPending() const { return m_profile.pending; }
    QString sourceText() const;
    double minClearance() const;
    int lowStretchCount() const { return int(m_profile.lowStretches.size()); }
    int noDataCount() const { return int(m_profile.noData.size()); }
    int recomputeCount() const { return m_recomputes; }

    // The route segment (row) a leg starts at, -1 when none.
    Q_INVOKABLE int rowOfLeg(int leg) const;
    // Sample index nearest a distance from the start, -1 without samples.
    Q_INVOKABLE int sampleAt(double distance) const;

    // The heights of a table row (a route segment) as the waypoint table shows them. A waypoint has
    // one point; a scan has its passes' points. Unknown is `undefined`, never 0.
    // The altitude as a height of `frame`: a waypoint's converted through the ground under it; a
    // scan's only in its own type (over varying ground no one number is right).
    Q_INVOKABLE QVariant altitudeOfRow(int row, sortie::mission::MissionEnums::AltitudeType frame) const;
    // The ground under a waypoint ("23.4"); "12–48" over a scan's points; "—" without data; "…" while a
    // source is still answering; "" for a row without points.
    Q_INVOKABLE QString groundTextOfRow(int row) const;
    // Says what the ground text is: its datum and source, or which sources had nothing.
    Q_INVOKABLE QString groundToolTipOfRow(int row) const;

public slots:
    void recomputeNow();

signals:
    void routeModelChanged();
    void serviceChanged();
    void stepChanged();
    void delayChanged();
    void profileChanged();

private:
    void schedule();

    QPointer<mission::RouteModel> m_model;
    QPointer<terrain::ElevationService> m_service;
    double m_step = 30.0;
    QTimer m_timer;
    struct RowPoints
    {
        int first = 0;
        int count = 0;
    };
    RowPoints pointsOfRow(int row) const;

    terrain::ProfileRoute m_route;
    terrain::TerrainProfile m_profile;
    std::vector<RowPoints> m_rows;  // by table row: its points in m_route.waypoints / m_profile.waypoints
    int m_recomputes = 0;
};

} // namespace sortie::ui
