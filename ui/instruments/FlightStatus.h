#pragma once

#include "MissionProgress.h"

#include <QObject>
#include <QPointer>
#include <QtQml/qqmlregistration.h>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::ui {

// What the fly view says about one vehicle beyond its raw telemetry: the mission's progress
// (waypoint n of m, distance and time left), where home and the next waypoint are from it, how
// long it has been armed, how its battery stands against the low and critical levels, and how
// well its link delivers (telemetry rate). Everything is derived in C++ from the Vehicle; the
// view only formats (DisplayUnits) and colours it. Unknown values are NaN, never 0.
class FlightStatus : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QObject *vehicle READ vehicleObject WRITE setVehicle NOTIFY vehicleChanged)
    Q_PROPERTY(double roll READ roll NOTIFY changed)   // deg; NaN until reported
    Q_PROPERTY(double pitch READ pitch NOTIFY changed) // deg
    Q_PROPERTY(int waypointCount READ waypointCount NOTIFY changed)
    Q_PROPERTY(int activeWaypoint READ activeWaypoint NOTIFY changed)         // 0-based, -1: none
    Q_PROPERTY(bool missionFlying READ missionFlying NOTIFY changed)
    Q_PROPERTY(bool missionComplete READ missionComplete NOTIFY changed)
    Q_PROPERTY(QString progressText READ progressText NOTIFY changed)
    Q_PROPERTY(double distanceLeft READ distanceLeft NOTIFY changed)         // m
    Q_PROPERTY(double timeLeft READ timeLeft NOTIFY changed)                 // s
    Q_PROPERTY(double bearingToNext READ bearingToNext NOTIFY changed)       // deg
    Q_PROPERTY(QGeoCoordinate home READ home NOTIFY changed)                 // reported, else the take-off point
    Q_PROPERTY(double distanceToHome READ distanceToHome NOTIFY changed)     // m
    Q_PROPERTY(double bearingToHome READ bearingToHome NOTIFY changed)       // deg
    Q_PROPERTY(double flightSeconds READ flightSeconds NOTIFY changed)       // since armed; NaN when disarmed
    Q_PROPERTY(double telemetryRate READ telemetryRate NOTIFY changed)       // position reports per second, last 5 s
    Q_PROPERTY(BatteryState batteryState READ batteryState NOTIFY changed)
    Q_PROPERTY(double lowBattery MEMBER m_lowBattery NOTIFY levelsChanged)           // 0..1
    Q_PROPERTY(double criticalBattery MEMBER m_criticalBattery NOTIFY levelsChanged) // 0..1
    Q_PROPERTY(double lowVoltage MEMBER m_lowVoltage NOTIFY levelsChanged)           // V; NaN: not judged by voltage
    Q_PROPERTY(double criticalVoltage MEMBER m_criticalVoltage NOTIFY levelsChanged) // V

public:
    enum class BatteryState { Unknown, Normal, Low, Critical };
    Q_ENUM(BatteryState)

    explicit FlightStatus(QObject *parent = nullptr);

    vehicle::Vehicle *vehicle() const { return m_vehicle; }
    QObject *vehicleObject() const;
    void setVehicle(QObject *vehicle);

    const vehicle::MissionProgress &progress() const { return m_progress; }
    double roll() const { return m_roll; }
    double pitch() const { return m_pitch; }
    int waypointCount() const { return m_progress.count; }
    int activeWaypoint() const { return m_progress.active; }
    bool missionFlying() const { return m_progress.isFlying(); }
    bool missionComplete() const { return m_complete; }
    // "waypoint 2 of 5", "mission complete", "5 waypoints on board", "no mission on board".
    QString progressText() const;
    double distanceLeft() const { return m_progress.distanceLeft; }
    double timeLeft() const { return m_progress.timeLeft; }
    double bearingToNext() const { return m_progress.bearingToActive; }
    QGeoCoordinate home() const { return m_home; }
    double distanceToHome() const { return m_distanceToHome; }
    double bearingToHome() const { return m_bearingToHome; }
    double flightSeconds() const { return m_flightSeconds; }
    double telemetryRate() const { return m_telemetryRate; }
    BatteryState batteryState() const { return m_battery; }

    // Home as the vehicle reports it; for one that does not (HCI), where it was when it was
    // last armed: its take-off point. Invalid when neither is known.
    static QGeoCoordinate homeOf(const vehicle::Vehicle &vehicle);
    // Judges a battery against the levels: the remaining fraction when reported, else the voltage.
    static BatteryState judgeBattery(double remaining, double voltage, double low, double critical,
                                     double lowVoltage, double criticalVoltage);

public slots:
    void refresh();

signals:
    void vehicleChanged();
    void changed();
    void levelsChanged();

private:
    QPointer<vehicle::Vehicle> m_vehicle;
    vehicle::MissionProgress m_progress;
    bool m_complete = false;
    double m_roll = qQNaN();
    double m_pitch = qQNaN();
    QGeoCoordinate m_home;
    double m_distanceToHome = qQNaN();
    double m_bearingToHome = qQNaN();
    double m_flightSeconds = qQNaN();
    double m_telemetryRate = qQNaN();
    BatteryState m_battery = BatteryState::Unknown;
    double m_lowBattery = 0.30;
    double m_criticalBattery = 0.15;
    double m_lowVoltage = qQNaN();
    double m_criticalVoltage = qQNaN();
};

} // namespace sortie::ui
