#pragma once

#include "AirspaceCheck.h"
#include "FlightAlerts.h"

#include <QHash>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

namespace sortie::client {
class VehicleFleet;
}
namespace sortie::terrain {
class ElevationService;
}

namespace sortie::airspace {

// A vehicle predicted to enter an exclusion zone or leave the permitted area.
struct ZoneAlert : vehicle::FlightAlert
{
    enum class Kind { EntersExclusion, LeavesInclusion };
    // key: "<vehicle id>|<set>|<zone name>|enter" / "...|leave"
    QString zone;
    Kind kind = Kind::EntersExclusion;
    bool heightUnknown = false;
};

// In-flight zone alerts: every second each airborne vehicle of the fleet is extrapolated in a
// straight line at its present velocity (ground speed along its course, vertical speed) and the
// line is checked in 3D against the zones (PlaneZone: the zone's shape between its floor and
// ceiling). A vehicle predicted to enter an exclusion zone, or to leave the permitted area (outside
// every active inclusion zone of a set), within kHorizonSeconds raises an alert; it stays while
// predicted within kClearSeconds (the hysteresis: a prediction wavering around 30 s does not raise
// it again and again) and goes after that. Heights: AMSL from the vehicle, above home from its
// home's AMSL altitude, above the ground through `ground` (unknown without it: the stretch counts
// as inside an exclusion zone, outside an inclusion zone, and the alert says so).
//
// Two sets of zones: the airspace the client knows (setZones, the same for every vehicle) and each
// vehicle's own fence (setVehicleZones: what was uploaded with its mission). Each set's inclusion
// zones are one permitted area. A UAS geographical zone (ED-269 / ED-318) counts while it applies by
// the clock; one with no restriction raises nothing.
//
// The alerts keep the in-flight alert contract (vehicle::AlertModel, as ProximityMonitor's and the
// battery's): a row here per alert, one entry in the fleet's command log per rise (CommandLog::alert),
// alertRaised / alertCleared.
class ZoneAlertMonitor : public vehicle::AlertList<ZoneAlert>
{
    Q_OBJECT

public:
    static constexpr double kHorizonSeconds = 30.0;
    static constexpr double kClearSeconds = 36.0;

    using Alert = ZoneAlert;
    using Kind = ZoneAlert::Kind;

    // `fleet` (required) and `ground` (may be nullptr) are not owned. Checks every `intervalMs`
    // (0: only when check() is called, as tests do).
    ZoneAlertMonitor(client::VehicleFleet *fleet, terrain::ElevationService *ground = nullptr, int intervalMs = 1000,
                     QObject *parent = nullptr);
    ~ZoneAlertMonitor() override;

    // The airspace every vehicle is checked against (null or empty: none).
    void setZones(std::shared_ptr<const ZoneSet> zones);
    // One vehicle's own fence (by Vehicle::id), e.g. the route fence uploaded with its mission.
    void setVehicleZones(const QString &vehicleId, std::vector<Zone> zones);

    // The clock a UAS geographical zone's applicability is read against (default: the system's, UTC):
    // a zone counts when it applies in the next kClearSeconds. Tests set their own.
    void setClock(std::function<QDateTime()> clock);

    void check();

private:
    struct Mover;
    std::vector<Alert> predict() const;
    void predictAgainst(const Mover &m, const ZoneSet &zones, const QString &set, std::vector<Alert> &found) const;

    QPointer<client::VehicleFleet> m_fleet;
    QPointer<terrain::ElevationService> m_ground;
    std::shared_ptr<const ZoneSet> m_zones;
    QHash<QString, std::shared_ptr<const ZoneSet>> m_vehicleZones;
    QTimer m_timer;
    std::function<QDateTime()> m_clock;
};

} // namespace sortie::airspace
