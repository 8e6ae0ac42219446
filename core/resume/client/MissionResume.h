#pragma once

#include "ResumeRoute.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <map>

Q_MOC_INCLUDE("Vehicle.h")

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::client {
class FleetRoutes;
class VehicleFleet;
}

namespace sortie::resume {

// The fly view's offer to finish a mission a vehicle stopped half-way (a battery change, low
// battery, a return home, a lost link): for the chosen vehicle, once it stands disarmed with the
// route it holds flown part of the way (FleetRoutes' progress when it stopped), the rest as a new
// route (resumeRoute) from the last photo it took on that route or the last waypoint it reached,
// taking off where it stands. The route goes to the mission editor through the opener the graph
// hands in, chosen for that vehicle: there every rule checks it, and it goes up through the same
// upload gate as any route.
class MissionResume : public QObject
{
    Q_OBJECT
    // The fly view's chosen vehicle (one of the fleet's); null: none.
    Q_PROPERTY(sortie::vehicle::Vehicle *vehicle READ vehicle WRITE setVehicle NOTIFY vehicleChanged)
    Q_PROPERTY(bool available READ isAvailable NOTIFY offerChanged)
    Q_PROPERTY(bool fromPhotoAvailable READ isFromPhotoAvailable NOTIFY offerChanged)
    Q_PROPERTY(bool fromWaypointAvailable READ isFromWaypointAvailable NOTIFY offerChanged)
    Q_PROPERTY(QString summary READ summary NOTIFY offerChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY resultChanged)
    Q_PROPERTY(QStringList notes READ notes NOTIFY resultChanged)

public:
    // Where a resumed route goes: the mission editor's document, chosen for the vehicle.
    using RouteOpener = std::function<void(mission::Route route, const QString &undoText, const QString &vehicleId)>;

    // Neither is owned; both outlive this.
    MissionResume(client::VehicleFleet *fleet, client::FleetRoutes *routes, QObject *parent = nullptr);

    void setRouteOpener(RouteOpener opener) { m_open = std::move(opener); }

    vehicle::Vehicle *vehicle() const;
    void setVehicle(vehicle::Vehicle *vehicle);

    bool isAvailable() const { return m_offer.available; }
    bool isFromPhotoAvailable() const { return m_offer.available && m_offer.photos > 0; }
    bool isFromWaypointAvailable() const { return m_offer.available && m_offer.reached > 0; }
    QString summary() const { return m_offer.summary; }
    QString errorString() const { return m_error; }
    QStringList notes() const { return m_notes; }

    // Builds the rest and opens it; false, with errorString, when it cannot be.
    Q_INVOKABLE bool resumeFromLastPhoto() { return resume(ResumeRequest::From::LastPhoto); }
    Q_INVOKABLE bool resumeFromLastWaypoint() { return resume(ResumeRequest::From::LastWaypoint); }

signals:
    void vehicleChanged();
    void offerChanged();
    void resultChanged();
    // The resumed route is open in the mission editor.
    void opened();

private:
    struct Offer
    {
        bool available = false;
        int reached = 0;  // the mission's waypoints the vehicle reached
        int count = 0;
        int photos = 0;   // photos it took since the route went up
        QString summary;
        bool operator==(const Offer &) const = default;
    };

    bool resume(ResumeRequest::From from);
    void refresh();
    Offer currentOffer() const;
    void fail(const QString &why);

    QPointer<client::VehicleFleet> m_fleet;
    QPointer<client::FleetRoutes> m_routes;
    RouteOpener m_open;
    QPointer<vehicle::Vehicle> m_vehicle;
    QMetaObject::Connection m_telemetry, m_photo;
    // Per vehicle: when its route went up and its photo count then, so the photos of that route are known.
    struct Upload
    {
        QDateTime at;
        int photoCount = 0;
    };
    std::map<QString, Upload> m_uploads;
    Offer m_offer;
    QString m_error;
    QStringList m_notes;
};

} // namespace sortie::resume
