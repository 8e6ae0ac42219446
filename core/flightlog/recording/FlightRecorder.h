#pragma once

#include "CommandLog.h"
#include "FlightLogWriter.h"
#include "RecordingChunk.h"
#include "Vehicle.h"

#include <QObject>
#include <QPointer>
#include <QThread>
#include <QTimer>

#include <memory>
#include <vector>

namespace sortie::flightlog {

// Records vehicles into a flight log while they fly: every telemetry batch their links deliver,
// their link changes, arming and mode changes, uploaded routes and identities, the photos their
// cameras took (PhotoEvents.h); and the results of the
// commands a command log (the fleet's) saw sent to them.
// This object only gathers (a vector append per value) on the thread the vehicles live on; every
// flushInterval the gathered chunk goes to a FlightLogWriter on a thread of its own, which encodes
// and commits it. A crash loses at most the chunk being gathered and the one being written.
class FlightRecorder : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString path READ path NOTIFY pathChanged)
    Q_PROPERTY(bool recording READ isRecording NOTIFY recordingChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorChanged)

public:
    struct Options
    {
        QString path;                 // the first part's file; created with its folder
        RecordingLimits limits;
        int flushIntervalMs = 500;
    };

    explicit FlightRecorder(Options options, QObject *parent = nullptr);
    ~FlightRecorder() override; // closes the log cleanly

    bool start(QString *error = nullptr);
    void stop(); // flushes, closes the file and ends the writer thread

    // Starts recording a vehicle (its identity, mission and everything from now on) until it is
    // destroyed or removed.
    void addVehicle(vehicle::Vehicle *vehicle);
    void removeVehicle(vehicle::Vehicle *vehicle);
    // Records each command the log sees finish as a "command" event of the recorded vehicle it went
    // to (the log names vehicles as Vehicle::name() does); commands to other vehicles are left out.
    // One log at a time; nullptr stops following.
    void followCommands(vehicle::CommandLog *log);
    // Something that happened outside any vehicle's signals (the connection to the server, a note).
    void recordEvent(vehicle::Vehicle *vehicle, const QString &kind, const QString &text, int ok = -1);
    // Hands what was gathered to the writer now.
    void flush();

    QString path() const;
    // The folder the logs go to.
    QString folder() const;
    // The size cap and folder limit; a change applies to the log being written at once (it rotates
    // if it is over the new cap, the folder is pruned to the new limit) and to later parts.
    RecordingLimits limits() const { return m_options.limits; }
    void setLimits(RecordingLimits limits);
    bool isRecording() const { return m_thread.isRunning(); }
    QString errorString() const { return m_error; }
    FlightLogWriter::Stats stats() const; // of the last recording once stopped

    // A new file for a session starting now, in `folder` (made private if it is missing), created
    // exclusively (0600): session-20261124-061423.sortielog, or session-20261124-061423-c2.sortielog
    // when another client took that name in the same second.
    static QString sessionPath(const QString &folder);

signals:
    void pathChanged();
    void recordingChanged();
    void errorChanged();
    void limitsChanged();

private:
    struct Recorded
    {
        QPointer<vehicle::Vehicle> vehicle;
        QString key;
        RecordedSamples pending;
        std::array<int, vehicle::kTelemetryFieldCount> slot; // index into pending.fields, -1 when none yet
        double armed = qQNaN(), mode = qQNaN();
        // The vehicle's clock minus ours at its last telemetry: events are put on the vehicle's
        // clock, the one its telemetry times use, so the timeline shows them where they happened.
        int64_t clockOffset = 0;
        QMetaObject::Connection telemetry;
        std::vector<QMetaObject::Connection> connections;
    };

    Recorded *find(const vehicle::Vehicle *vehicle);
    Recorded *findNamed(const QString &name);
    void recordCommand(const vehicle::CommandLog::Entry &entry);
    void gather(Recorded &r, const vehicle::TelemetryBatch &batch);
    void writeEvent(const Recorded &r, const QString &kind, const QString &text, int ok = -1);
    static int64_t vehicleTime(const Recorded &r) { return now() + r.clockOffset; }
    static int64_t now();

    Options m_options;
    QThread m_thread;
    FlightLogWriter *m_writer = nullptr; // lives on m_thread
    QTimer m_flushTimer;
    std::vector<std::unique_ptr<Recorded>> m_recorded;
    QMetaObject::Connection m_commands;
    RecordingChunk m_chunk;
    QString m_error;
    FlightLogWriter::Stats m_lastStats;
};

} // namespace sortie::flightlog
