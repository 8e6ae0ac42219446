#pragma once

#include "CommandLog.h"
#include "TelemetryStore.h"
#include "VehicleLink.h"

#include <QElapsedTimer>
#include <QGeoCoordinate>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <array>
#include <bitset>

namespace sortie::vehicle {

// One vehicle as the rest of the client sees it, whichever protocol feeds it: identity, link state,
// the last value and time of every telemetry field, which fields have gone stale, and the history
// (TelemetryStore). Fed by one VehicleLink (not owned).
//
// For QML the telemetry properties share one notification, telemetryChanged(), emitted at most once
// per notifyInterval (100 ms by default) however fast telemetry arrives: the first change goes out at
// once, later ones are gathered until the interval has passed. It means a value changed: a parked
// vehicle repeating the same values raises none (so nothing redraws for it); historyChanged, gathered
// the same way, says the history grew (the plots, whose time axis moves with every sample). Values are SI, angles in degrees
// (TelemetryField.h); `position` and `home` are QGeoCoordinates.
class Vehicle : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString id READ id NOTIFY identityChanged)
    Q_PROPERTY(QString name READ name NOTIFY identityChanged)
    Q_PROPERTY(QString protocol READ protocol CONSTANT)
    Q_PROPERTY(sortie::vehicle::VehicleLink::State linkState READ linkState NOTIFY linkStateChanged)
    Q_PROPERTY(bool connected READ isConnected NOTIFY linkStateChanged)
    Q_PROPERTY(bool stale READ isStale NOTIFY staleChanged)
    Q_PROPERTY(QString lastError READ lastError NOTIFY lastErrorChanged)
    // The camera's stream as the vehicle publishes it (video_stream_uri); empty: none said.
    Q_PROPERTY(QString videoStreamUri READ videoStreamUri NOTIFY videoStreamUriChanged)
    Q_PROPERTY(int photoCount READ photoCount NOTIFY photoTaken)
    Q_PROPERTY(QGeoCoordinate position READ position NOTIFY telemetryChanged)
    Q_PROPERTY(QGeoCoordinate home READ home NOTIFY telemetryChanged)
    Q_PROPERTY(double altitudeAmsl READ altitudeAmsl NOTIFY telemetryChanged)
    Q_PROPERTY(double altitudeAgl READ altitudeAgl NOTIFY telemetryChanged)
    Q_PROPERTY(double heading READ heading NOTIFY telemetryChanged)
    Q_PROPERTY(double groundSpeed READ groundSpeed NOTIFY telemetryChanged)
    Q_PROPERTY(double verticalSpeed READ verticalSpeed NOTIFY telemetryChanged)
    Q_PROPERTY(double batteryVoltage READ batteryVoltage NOTIFY telemetryChanged)
    Q_PROPERTY(double batteryRemaining READ batteryRemaining NOTIFY telemetryChanged)
    Q_PROPERTY(int satellites READ satellites NOTIFY telemetryChanged)
    Q_PROPERTY(int gpsFix READ gpsFix NOTIFY telemetryChanged)
    Q_PROPERTY(bool armed READ armed NOTIFY telemetryChanged)
    Q_PROPERTY(QString mode READ mode NOTIFY telemetryChanged)
    Q_PROPERTY(QString missionState READ missionState NOTIFY telemetryChanged)
    Q_PROPERTY(int missionCurrent READ missionCurrent NOTIFY telemetryChanged)
    Q_PROPERTY(int missionCount READ missionCount NOTIFY telemetryChanged)
    // Outside its fence now (VCI /fence/status); false when it has no fence or does not say.
    Q_PROPERTY(bool fenceBreached READ fenceBreached NOTIFY telemetryChanged)
    Q_PROPERTY(int notifyInterval READ notifyInterval WRITE setNotifyInterval NOTIFY notifyIntervalChanged)

public:
    explicit Vehicle(VehicleLink *link, QObject *parent = nullptr, size_t historyCapacity = TelemetryStore::kDefaultCapacity);

    VehicleLink *link() const { return m_link; }
    const TelemetryStore &history() const { return m_history; }

    QString id() const { return m_identity.id; }
    QString name() const { return m_identity.name.isEmpty() ? m_identity.id : m_identity.name; }
    QString protocol() const { return m_protocol; }
    // "HCI:7", "VCI:vci-1": unique in a fleet, where the ids of two protocols may meet.
    QString fleetId() const { return m_protocol + QLatin1Char(':') + id(); }
    VehicleIdentity identity() const { return m_identity; }
    VehicleLink::State linkState() const { return m_link ? m_link->state() : VehicleLink::State::Disconnected; }
    bool isConnected() const { return linkState() == VehicleLink::State::Connected; }
    // The link's last problem, for the operator; cleared when the link connects.
    QString lastError() const { return m_lastError; }
    QString videoStreamUri() const { return m_videoStreamUri; }
    // The photos its camera reported taking since it connected, and the last of them (none: NaN
    // position, sequence 0).
    int photoCount() const { return m_photoCount; }
    const CameraPhoto &lastPhoto() const { return m_lastPhoto; }

    // The last value of a field with the vehicle's time, or nullopt before the first.
    std::optional<TelemetrySample> last(TelemetryField field) const;
    double value(TelemetryField field, double fallback = qQNaN()) const;
    bool isStale(TelemetryField field) const; // never received, or not for staleAfter
    bool isStale() const { return m_stale; }  // nothing at all for staleAfter
    Q_INVOKABLE double value(const QString &field) const;
    Q_INVOKABLE bool isFieldStale(const QString &field) const;

    QGeoCoordinate position() const;
    QGeoCoordinate home() const;
    double altitudeAmsl() const { return value(TelemetryField::AltitudeAmsl); }
    double altitudeAgl() const { return value(TelemetryField::AltitudeAgl); }
    double heading() const { return value(TelemetryField::Heading); }
    double groundSpeed() const { return value(TelemetryField::GroundSpeed); }
    double verticalSpeed() const { return value(TelemetryField::VerticalSpeed); }
    double batteryVoltage() const { return value(TelemetryField::BatteryVoltage); }
    double batteryRemaining() const { return value(TelemetryField::BatteryRemaining); }
    int satellites() const { return int(value(TelemetryField::Satellites, 0)); }
    int gpsFix() const { return int(value(TelemetryField::GpsFix, 0)); }
    bool armed() const { return value(TelemetryField::Armed, 0) != 0; }
    FlightMode flightMode() const { return FlightMode(int(value(TelemetryField::Mode, 0))); }
    QString mode() const;
    QString missionState() const;
    int missionCurrent() const { return int(value(TelemetryField::MissionCurrent, -1)); }
    int missionCount() const { return int(value(TelemetryField::MissionCount, 0)); }
    bool fenceBreached() const { return value(TelemetryField::FenceBreach, 0) != 0; }

    int notifyInterval() const { return m_notifyInterval; }
    void setNotifyInterval(int ms);
    int staleAfter() const { return m_staleAfter; }
    void setStaleAfter(int ms);
    quint64 telemetryNotifications() const { return m_notifications; }
    // Whether gathered changes are waiting for their telemetryChanged (the interval's timer runs);
    // when not, nothing goes out until the next ingest.
    bool notificationPending() const { return m_notifyTimer.isActive(); }

    // The mission the vehicle holds, as last uploaded to it or read back from it; empty when unknown.
    // The fly view draws it under the vehicle; whoever uploads or downloads a mission sets it.
    const std::vector<MissionItem> &mission() const { return m_mission; }
    void setMission(std::vector<MissionItem> items);

    // Applies a batch as if the link had sent it (the link's signal is connected to this).
    void ingest(const TelemetryBatch &batch);
    // Replaces the history (not the last values): a replay fills its plots with a log's whole span,
    // built on a worker thread, without stalling the GUI thread.
    void replaceHistory(TelemetryStore history);

    // The vehicle's parameters as its link reports them (VCI: /parameters; HCI: the vehicle profile's
    // VPT_* values) by the link's own names, read after each connect; empty until then. For the
    // policies in C++ (CommandPolicy's take-off altitude), not a view's property.
    QVariantMap parameters() const { return m_parameters; }

    // Where the commands below are recorded (not owned; none by default).
    void setCommandLog(CommandLog *log);
    CommandLog *commandLog() const { return m_commandLog; }

    // Commands for QML; each ends with commandFinished(command, ok, message) and, with a command
    // log, an entry there.
    Q_INVOKABLE void arm();
    Q_INVOKABLE void disarm();
    Q_INVOKABLE void setMode(const QString &mode);
    Q_INVOKABLE void takeoff(double altitude);
    Q_INVOKABLE void land();
    Q_INVOKABLE void returnHome();

signals:
    void telemetryChanged();
    void historyChanged();
    void staleChanged();
    void linkStateChanged();
    void lastErrorChanged();
    void videoStreamUriChanged();
    void photoTaken(const sortie::vehicle::CameraPhoto &photo);
    void identityChanged();
    void notifyIntervalChanged();
    void commandFinished(const QString &command, bool ok, const QString &message);
    void missionChanged();
    void parametersChanged();

private:
    struct Last
    {
        TelemetrySample sample;
        qint64 receivedAt = -1; // m_clock ms; -1: never
    };

    void scheduleNotify();
    void readParameters();
    void emitNotify();
    void checkStale();
    VehicleLink::Done finisher(const QString &command, const QString &logged = {});

    QPointer<VehicleLink> m_link;
    QPointer<CommandLog> m_commandLog;
    QString m_protocol;
    VehicleIdentity m_identity;
    QString m_lastError;
    QString m_videoStreamUri;
    CameraPhoto m_lastPhoto;
    int m_photoCount = 0;
    QVariantMap m_parameters;
    std::vector<MissionItem> m_mission;
    TelemetryStore m_history;
    std::array<Last, kTelemetryFieldCount> m_last;
    std::bitset<kTelemetryFieldCount> m_staleFields;
    bool m_stale = true;
    qint64 m_lastReceivedAt = -1;
    QElapsedTimer m_clock;
    QTimer m_notifyTimer, m_staleTimer;
    int m_notifyInterval = 100;
    int m_staleAfter = 3000;
    qint64 m_lastNotifyAt = -1000000;
    bool m_dirty = false, m_historyDirty = false, m_staleDirty = false;
    quint64 m_notifications = 0;
};

} // namespace sortie::vehicle
