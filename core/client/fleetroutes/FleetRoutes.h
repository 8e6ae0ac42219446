#pragma once

#include "FleetRoute.h"
#include "ScanPlanCache.h"
#include "VehicleTypes.h"

#include <QAbstractListModel>
#include <QPointer>
#include <QPolygonF>

#include <vector>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::client {

class MissionUploader;
class RouteDocument;
class RoutePreparation;
class VehicleFleet;

// Every route given to a vehicle of the fleet, so that the map draws them all and a list shows
// them: one row per route. The open route chosen for a vehicle (RoutePreparation's vehicleId) is
// its Planned row while it differs from what that vehicle holds; an upload that succeeds (through
// the preparation's MissionUploader, or any uploader passed to follow()) gives the vehicle's
// on-board row: a copy of the route as uploaded, and when. That row becomes Flying while the
// vehicle reports the mission active or paused (the same telemetry over HCI, from the server's
// RoutePass, and over VCI): waypoint n of m, elapsed and remaining time. Flown once it reports the
// mission complete. A vehicle holds one route: a newer upload replaces its row; a vehicle whose
// mission changes otherwise (another client, a read-back) or that leaves the fleet loses it.
// Rows change at most at the vehicles' notify rate, and only when something shown changed (the
// elapsed time by the second).
//
// For the views: the vehicle's id, name, fleet row and colour (client::vehicleColor, as the
// vehicle layer draws it), the route's name, the state and its text, the times (seconds; NaN
// when unknown) and the flown path (`path`: a QPolygonF of x = longitude, y = latitude, area
// scans expanded). `open`: the row is the route open in the editor, which draws it itself.
//
// For 4D deconfliction: routes() hands every row out as a FleetRoute value: the route
// (mission::Route), its vehicle id, its state, its start time (wall clock, UTC; invalid before it
// flies) and, while flying, its progress. Not-yet-flown rows have no start time by design.
class FleetRoutes : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Roles {
        VehicleIdRole = Qt::UserRole + 1, VehicleNameRole, VehicleRowRole, ColorRole, RouteNameRole, StateRole,
        StateTextRole, FlightSecondsRole, ElapsedSecondsRole, RemainingSecondsRole, UploadedAtRole, PathRole, OpenRole,
    };

    // `fleet` (required), `document` and `preparation` (the open route and its chosen vehicle; both
    // or neither) are not owned. The preparation's uploader is followed.
    FleetRoutes(VehicleFleet *fleet, RouteDocument *document, RoutePreparation *preparation, QObject *parent = nullptr);
    ~FleetRoutes() override;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;
    int count() const { return int(m_rows.size()); }

    // Uploads this uploader completes become rows too (not owned; a script's or a test's own).
    void follow(MissionUploader *uploader);

    // Every row as a value, in row order (see the class comment).
    std::vector<FleetRoute> routes() const;
    // The states of the vehicle's rows (its fleet id), in row order: at most one on board and one
    // planned. Cheap: no route is copied (the pre-flight check asks at every change).
    std::vector<FleetRouteState> statesOf(const QString &vehicleId) const;
    // The route the vehicle (its fleet id) holds, as uploaded, with its state and progress; nullptr
    // when it holds none. Valid until the rows next change.
    const FleetRoute *onBoard(const QString &vehicleId) const;
    // The flown path of a row, longitude/latitude (what the `path` role holds).
    QPolygonF pathAt(int row) const;

signals:
    void countChanged();

private:
    struct Row
    {
        FleetRoute value;
        QPointer<vehicle::Vehicle> vehicle;
        std::vector<vehicle::MissionItem> held; // what the upload left on the vehicle
        QPolygonF path;
        bool planned = false;
        // What the views were last told, to signal only real changes.
        QString stateText;
        qint64 elapsed = -1, remaining = -1;
    };

    void uploaded(MissionUploader *uploader, vehicle::Vehicle *vehicle);
    void refreshPlanned();
    void refreshVehicle(vehicle::Vehicle *vehicle);
    void missionReplaced(vehicle::Vehicle *vehicle);
    void watch(vehicle::Vehicle *vehicle);
    void removeRow(int row);
    int onBoardRow(const vehicle::Vehicle *vehicle) const;
    int plannedRow() const;
    // Fills the row's path and flight time from its route.
    void describe(Row &row);
    // The state and progress the vehicle's telemetry says; true when what is shown changed.
    bool track(Row &row);
    QString stateText(const Row &row) const;
    int fleetRow(const vehicle::Vehicle *vehicle) const;
    bool isOpen(const Row &row) const;

    QPointer<VehicleFleet> m_fleet;
    QPointer<RouteDocument> m_document;
    QPointer<RoutePreparation> m_preparation;
    std::vector<Row> m_rows;
    std::vector<QPointer<vehicle::Vehicle>> m_watched;
    mission::ScanPlanCache m_scans;
};

} // namespace sortie::client
