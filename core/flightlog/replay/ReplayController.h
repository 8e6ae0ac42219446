#pragma once

#include "FlightLog.h"
#include "ReplayEventModel.h"
#include "ReplayVehicleLink.h"
#include "Vehicle.h"

#include <QAbstractListModel>
#include <QElapsedTimer>
#include <QObject>
#include <QThread>
#include <QTimer>
#include <QUrl>

#include <memory>

namespace sortie::flightlog {

// The replayed vehicles as a list, with the row roles of the live fleet (so the same map layer and
// lists draw them) and `replay` true on every row.
class ReplayFleet : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Roles {
        VehicleIdRole = Qt::UserRole + 1, NameRole, ProtocolRole, LinkStateRole, StaleRole,
        LatitudeRole, LongitudeRole, HeadingRole, HomeLatitudeRole, HomeLongitudeRole,
        AltitudeAglRole, GroundSpeedRole, ModeRole, ArmedRole, BatteryRole, VehicleRole, ReplayRole,
    };
    using QAbstractListModel::QAbstractListModel;

    int count() const { return int(m_vehicles.size()); }
    Q_INVOKABLE sortie::vehicle::Vehicle *vehicleAt(int row) const;
    void reset(std::vector<vehicle::Vehicle *> vehicles);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();

private:
    std::vector<vehicle::Vehicle *> m_vehicles;
    std::vector<QMetaObject::Connection> m_connections;
};

// Plays a flight log through Vehicle models: a clock over the log's span with play, pause, a speed of
// 1x to 50x, seeking (by time or as a fraction of the span) and jumps to events. At every position
// each replayed vehicle shows what the log recorded at that moment (its last value of every field, its
// link state, the route it carried); while playing, every recorded sample is delivered in order, so
// the vehicles' instruments and trails move as they did.
//
// Opening is cheap: the log's blocks stay encoded and each vehicle gets its state at the start (the
// few blocks that holds). The plots' histories (the log's whole span, thinned evenly when it holds
// more than a live history would) are decoded on a worker thread and replace each Vehicle's history
// when ready (historyLoaded); until then the plots show what has been played.
class ReplayController : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool active READ isActive NOTIFY loadedChanged)
    Q_PROPERTY(QString path READ path NOTIFY loadedChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorChanged)
    Q_PROPERTY(QString warning READ warning NOTIFY loadedChanged)
    Q_PROPERTY(qint64 start READ start NOTIFY loadedChanged)
    Q_PROPERTY(qint64 end READ end NOTIFY loadedChanged)
    Q_PROPERTY(qint64 position READ position WRITE seek NOTIFY positionChanged)
    Q_PROPERTY(double progress READ progress WRITE setProgress NOTIFY positionChanged)
    Q_PROPERTY(QString positionText READ positionText NOTIFY positionChanged)
    Q_PROPERTY(QString spanText READ spanText NOTIFY loadedChanged)
    Q_PROPERTY(double spanSeconds READ spanSeconds NOTIFY loadedChanged)
    Q_PROPERTY(bool playing READ isPlaying NOTIFY playingChanged)
    Q_PROPERTY(double speed READ speed WRITE setSpeed NOTIFY speedChanged)
    Q_PROPERTY(sortie::flightlog::ReplayFleet *fleet READ fleet CONSTANT)
    Q_PROPERTY(sortie::flightlog::ReplayEventModel *events READ events CONSTANT)
    Q_PROPERTY(QList<double> speeds READ speeds CONSTANT)
    Q_PROPERTY(bool historyLoaded READ isHistoryLoaded NOTIFY historyLoadedChanged)

public:
    static constexpr double kMinSpeed = 1, kMaxSpeed = 50;

    explicit ReplayController(QObject *parent = nullptr);
    ~ReplayController() override;

    // Opens a log file; false with errorString when it cannot be read at all. A damaged log opens
    // with its damaged blocks skipped (or up to where it cannot be read further), `warning` saying which.
    Q_INVOKABLE bool open(const QString &pathOrUrl); // a path or a file: URL
    // A log built elsewhere (the server's history).
    void open(std::unique_ptr<FlightLog> log);
    Q_INVOKABLE void close();

    bool isActive() const { return m_log != nullptr; }
    // The plots' whole-span histories are in the vehicles (false while no log is open).
    bool isHistoryLoaded() const { return m_historyLoaded; }
    const FlightLog *log() const { return m_log.get(); }
    QString path() const { return m_log ? m_log->path() : QString(); }
    QString errorString() const { return m_error; }
    QString warning() const { return m_log ? m_log->damage() : QString(); }
    qint64 start() const { return m_log ? m_log->start() : 0; }
    qint64 end() const { return m_log ? m_log->end() : 0; }
    qint64 position() const { return m_position; }
    double progress() const;
    QString positionText() const;
    QString spanText() const;
    double spanSeconds() const { return m_log ? double(m_log->end() - m_log->start()) / 1000.0 : 0; }
    bool isPlaying() const { return m_timer.isActive(); }
    double speed() const { return m_speed; }
    ReplayFleet *fleet() { return &m_fleet; }
    ReplayEventModel *events() { return &m_events; }
    vehicle::Vehicle *vehicle(int index) const;

    Q_INVOKABLE void play();
    Q_INVOKABLE void pause();
    Q_INVOKABLE void togglePlaying() { isPlaying() ? pause() : play(); }
    void seek(qint64 time);
    void setProgress(double fraction);
    void setSpeed(double speed);
    Q_INVOKABLE void jumpToEvent(int row);
    Q_INVOKABLE void nextEvent();
    Q_INVOKABLE void previousEvent();
    // The speeds the timeline offers.
    static QList<double> speeds() { return {1, 2, 5, 10, 20, 50}; }
    // Writes the open log's tracks as "gpx", "kml" or "csv" (a local file URL or path); the error
    // for the operator, or empty.
    Q_INVOKABLE QString exportTracks(const QString &format, const QUrl &file) const;
    // Advances the clock as if `ms` of wall time had passed while playing (the timer calls it; so
    // do benchmarks that want no wall clock).
    void advance(qint64 ms);

signals:
    void loadedChanged();
    void errorChanged();
    void positionChanged();
    void seeked(); // a jump, not play: trails drawn so far no longer lead to the vehicles
    void playingChanged();
    void speedChanged();
    void historyLoadedChanged();

private:
    struct Replayed
    {
        std::unique_ptr<ReplayVehicleLink> link;
        std::unique_ptr<vehicle::Vehicle> vehicle;
    };
    void tick();
    void showAt(qint64 time);                 // every vehicle jumps to its state at `time`
    void playTo(qint64 time);                 // every sample in (position, time] delivered in order
    void applyEventsAndMissions(qint64 time); // link state and route as of `time`
    void setError(const QString &error);
    void startHistoryFill();
    void stopHistoryFill(); // cancels and waits for the worker
    void applyHistories(quint64 generation, std::vector<vehicle::TelemetryStore> &histories);

    std::shared_ptr<const FlightLog> m_log; // shared with the history worker
    std::unique_ptr<QThread> m_historyThread;
    std::shared_ptr<std::atomic_bool> m_cancelHistory;
    quint64 m_generation = 0; // which open a worker's result belongs to
    bool m_historyLoaded = false;
    std::vector<Replayed> m_vehicles;
    ReplayFleet m_fleet;
    ReplayEventModel m_events;
    QTimer m_timer;
    QElapsedTimer m_wall;
    qint64 m_position = 0;
    double m_speed = 1;
    QString m_error;
};

} // namespace sortie::flightlog
