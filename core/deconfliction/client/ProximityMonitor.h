#pragma once

#include "ClosestApproach.h"
#include "FlightAlerts.h"

#include <QPointer>
#include <QTimer>

#include <functional>
#include <vector>

namespace sortie::client {
class VehicleFleet;
}
namespace sortie::traffic {
class TrafficPicture;
}

namespace sortie::deconfliction {

// Two of ours, or one of ours and an aircraft, predicted to lose separation.
struct ProximityAlert : vehicle::FlightAlert
{
    // key: "EMU-101|EMU-102", "EMU-101|traffic:4CA2D6"; vehicle: the own vehicle it is logged under (the first)
    QString other;          // the other vehicle's name, or the aircraft's call sign and address
    bool traffic = false;
    double horizontal = 0;  // metres across at the closest approach (inSeconds away)
    double vertical = 0;    // metres in height then
};

// In-flight closest-point-of-approach alerts: every second, each pair of the fleet's airborne
// vehicles, and each airborne vehicle against each aircraft of the traffic picture, is extrapolated
// at its present velocity (closestApproach); a pair predicted to lose separation within the horizon
// raises an alert. Thresholds are UgCS's: 20 m across and 15 m in height within 60 s between own
// vehicles, 9,260 m (5 NM) and 300 m within 60 s against manned traffic. A pressure altitude
// (SBS-1's) is compared with the vehicles' AMSL with the height threshold widened by
// kBarometricMarginM: the day's pressure moves a pressure altitude by about 8 m per hPa.
//
// An alert keeps the in-flight alert contract (vehicle::AlertModel): raised once, when first
// predicted: a row here (the fly view's banner), an entry in the fleet's command log (which the
// flight recorder keeps as an "alert" event) and alertRaised. It stays while predicted and goes when
// no longer predicted (alertCleared). Airborne: armed and more than 1 m above home, with a fresh
// position, AMSL altitude and ground speed.
class ProximityMonitor : public vehicle::AlertList<ProximityAlert>
{
    Q_OBJECT

public:
    struct Thresholds
    {
        Separation separation;
        double horizonSeconds = 60.0;
    };
    static constexpr double kBarometricMarginM = 250.0;  // 30 hPa: ordinary sea-level pressures span 983–1043
    static Thresholds ownThresholds() { return {{20.0, 15.0}, 60.0}; }
    static Thresholds trafficThresholds() { return {{9260.0, 300.0}, 60.0}; }

    using Alert = ProximityAlert;

    // `fleet` (required) and `traffic` (may be nullptr) are not owned. Checks every `intervalMs`
    // (0: only when check() is called, as tests do).
    ProximityMonitor(client::VehicleFleet *fleet, traffic::TrafficPicture *traffic, int intervalMs = 1000, QObject *parent = nullptr);

    void setOwnThresholds(const Thresholds &t) { m_own = t; }
    void setTrafficThresholds(const Thresholds &t) { m_traffic = t; }
    void check();

private:
    std::vector<Alert> predict() const;

    QPointer<client::VehicleFleet> m_fleet;
    QPointer<traffic::TrafficPicture> m_trafficPicture;
    Thresholds m_own = ownThresholds();
    Thresholds m_traffic = trafficThresholds();
    QTimer m_timer;
};

} // namespace sortie::deconfliction
