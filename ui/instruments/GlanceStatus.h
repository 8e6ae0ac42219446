#pragma once

#include "ConnectionController.h"
#include "FlightStatus.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// The toolbar's glance: the connection, the vehicle, its GPS, battery and link, each judged ok,
// warning, problem or missing against the thresholds below, with a few words and an icon's name.
// Everything is decided here; GlanceBar.qml only shows it. A value never reported is missing
// (shown as such), never 0. The vehicle is the one chosen in the fly view, else the fleet's first.
class GlanceStatus : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(sortie::client::ConnectionController *connection READ connection WRITE setConnection NOTIFY inputsChanged)
    Q_PROPERTY(sortie::client::VehicleFleet *fleet READ fleet WRITE setFleet NOTIFY inputsChanged)
    Q_PROPERTY(sortie::vehicle::Vehicle *chosen READ chosen WRITE setChosen NOTIFY inputsChanged)
    Q_PROPERTY(sortie::vehicle::Vehicle *vehicle READ vehicle NOTIFY changed) // the one judged

    Q_PROPERTY(Level connectionLevel READ connectionLevel NOTIFY changed)
    Q_PROPERTY(QString connectionText READ connectionText NOTIFY changed)
    Q_PROPERTY(Level vehicleLevel READ vehicleLevel NOTIFY changed)
    Q_PROPERTY(QString vehicleText READ vehicleText NOTIFY changed)
    Q_PROPERTY(Level gpsLevel READ gpsLevel NOTIFY changed)
    Q_PROPERTY(QString gpsText READ gpsText NOTIFY changed)
    Q_PROPERTY(QString gpsIcon READ gpsIcon NOTIFY changed)
    Q_PROPERTY(Level batteryLevel READ batteryLevel NOTIFY changed)
    Q_PROPERTY(QString batteryText READ batteryText NOTIFY changed)
    Q_PROPERTY(QString batteryIcon READ batteryIcon NOTIFY changed)
    Q_PROPERTY(Level linkLevel READ linkLevel NOTIFY changed)
    Q_PROPERTY(QString linkText READ linkText NOTIFY changed)
    Q_PROPERTY(QString linkIcon READ linkIcon NOTIFY changed)

public:
    enum class Level { Missing, Ok, Warning, Problem };
    Q_ENUM(Level)

    // Where each reading turns from ok to warning to problem.
    struct Thresholds
    {
        int warningSatellites = 8;  // fewer: a fix that may not hold
        int problemSatellites = 5;  // fewer: no position to fly on
        double okRate = 2.0;        // position reports a second at or above: a link in good health
        double problemRate = 0.5;   // below: hardly a link
        double lowBattery = 0.30;   // FlightStatus's levels
        double criticalBattery = 0.15;
    };

    explicit GlanceStatus(QObject *parent = nullptr);
    ~GlanceStatus() override;

    client::ConnectionController *connection() const { return m_connection; }
    void setConnection(client::ConnectionController *connection);
    client::VehicleFleet *fleet() const { return m_fleet; }
    void setFleet(client::VehicleFleet *fleet);
    vehicle::Vehicle *chosen() const { return m_chosen; }
    void setChosen(vehicle::Vehicle *vehicle);
    vehicle::Vehicle *vehicle() const { return m_vehicle; }

    Level connectionLevel() const { return m_connectionLevel; }
    QString connectionText() const { return m_connectionText; }
    Level vehicleLevel() const { return m_vehicleLevel; }
    QString vehicleText() const { return m_vehicleText; }
    Level gpsLevel() const { return m_gpsLevel; }
    QString gpsText() const { return m_gpsText; }
    QString gpsIcon() const { return m_gpsLevel == Level::Missing || m_gpsLevel == Level::Problem ? QStringLiteral("location-services-disabled")
                                                                                                 : QStringLiteral("location-services-active"); }
    Level batteryLevel() const { return m_batteryLevel; }
    QString batteryText() const { return m_batteryText; }
    QString batteryIcon() const { return m_batteryIcon; }
    Level linkLevel() const { return m_linkLevel; }
    QString linkText() const { return m_linkText; }
    QString linkIcon() const { return m_linkIcon; }

    // The judgements, pure (tst_glancestatus). A NaN reading is one never reported.
    // The session: Ready is ok, on its way (connecting, logging in, reconnecting) a warning, a
    // refusal or a lost connection (an error to show) a problem, not connected and no error missing.
    static Level judgeConnection(const QString &state, bool failed);
    // Present and heard from is ok, silent for a while (stale) a warning, its link lost a problem.
    static Level judgeVehicle(bool present, bool linkConnected, bool linkLost, bool stale);
    // Fix type as MAVLink counts it (0, 1: none, 2: 2D, 3: 3D, more: DGPS, RTK), and satellites.
    static Level judgeGps(double fixType, double satellites, const Thresholds &thresholds);
    static Level judgeBattery(FlightStatus::BatteryState state);
    // Position reports a second over the last seconds; a lost link is a problem whatever the rate.
    static Level judgeLink(double rate, bool linkLost, const Thresholds &thresholds);
    // battery-level-0 … battery-level-100 by tens, battery-missing when unknown.
    static QString batteryIconFor(double remaining);
    // network-wireless-signal-none/weak/ok/good/excellent by the rate, offline when missing or lost.
    static QString linkIconFor(double rate, bool linkLost, const Thresholds &thresholds);

    const Thresholds &thresholds() const { return m_thresholds; }

signals:
    void inputsChanged();
    void changed();

private:
    void follow();
    void refresh();

    Thresholds m_thresholds;
    QPointer<client::ConnectionController> m_connection;
    QPointer<client::VehicleFleet> m_fleet;
    QPointer<vehicle::Vehicle> m_chosen;
    QPointer<vehicle::Vehicle> m_vehicle;
    FlightStatus m_status; // the battery against its levels and the telemetry rate, for m_vehicle
    Level m_connectionLevel = Level::Missing;
    QString m_connectionText;
    Level m_vehicleLevel = Level::Missing;
    QString m_vehicleText;
    Level m_gpsLevel = Level::Missing;
    QString m_gpsText;
    Level m_batteryLevel = Level::Missing;
    QString m_batteryText;
    QString m_batteryIcon;
    Level m_linkLevel = Level::Missing;
    QString m_linkText;
    QString m_linkIcon;
};

} // namespace sortie::ui
