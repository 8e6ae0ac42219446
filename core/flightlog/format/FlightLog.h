#pragma once

#include "TelemetryBlockCodec.h"
#include "VehicleTypes.h"

#include <QString>
#include <QStringList>

#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace sortie::flightlog {

// A flight log opened for reading: its vehicles, events and uploaded routes, and the telemetry
// blocks kept encoded in memory (about 2 bytes a value) and decoded when asked for. Opening reads
// the file once, checking every block. A damaged block (one that fails its check, or names a
// vehicle the log does not hold) is skipped, and reading goes on: `skipped()` names each. A log
// that cannot be read further (cut short, a damaged table) is read up to there, and `stoppedAt()`
// says where and why reading stopped.
class FlightLog
{
public:
    struct Event
    {
        int vehicle = -1; // index into vehicles(); -1 for the session's own events
        int64_t time = 0;
        QString kind;
        QString text;
        int ok = -1;
    };

    struct Mission
    {
        int64_t time = 0;
        std::vector<vehicle::MissionItem> items;
    };

    struct Block
    {
        int64_t t0 = 0, t1 = 0;
        uint32_t fields = 0; // bit per TelemetryField present
        std::string data;
    };

    struct Vehicle
    {
        QString key;
        vehicle::VehicleIdentity identity;
        std::vector<Block> blocks;  // time order
        std::vector<Mission> missions;
        std::array<uint64_t, vehicle::kTelemetryFieldCount> counts{}; // samples per field
        int64_t start = 0, end = 0; // first and last sample; both 0 when none
        QString name() const { return identity.name.isEmpty() ? key : identity.name; }
        uint64_t sampleCount() const;
        // Checks an encoded block and adds it; false (and why in *error) when it is damaged.
        bool appendBlock(std::string data, std::string *error = nullptr);
    };

    // nullptr and *error when the file is no flight log or cannot be read at all.
    static std::unique_ptr<FlightLog> open(const QString &path, QString *error);
    // Builds a log in memory (the server's history, tests).
    FlightLog() = default;

    const QString &path() const { return m_path; }
    const std::vector<Vehicle> &vehicles() const { return m_vehicles; }
    const std::vector<Event> &events() const { return m_events; } // time order
    int vehicleIndex(const QString &nameOrKey) const; // -1 when absent
    // The span of the telemetry (of the events when there is none).
    int64_t start() const { return m_start; }
    int64_t end() const { return m_end; }
    // Empty when the whole file was read; else where reading stopped and why.
    const QString &stoppedAt() const { return m_stoppedAt; }
    // The damaged blocks reading went past, one sentence each ("block 7 of vehicle row 3 … is
    // skipped: unknown vehicle"); the first kMaxSkippedNamed, then one line counting the rest.
    const QStringList &skipped() const { return m_skipped; }
    static constexpr int kMaxSkippedNamed = 20;
    // stoppedAt() and skipped() in one text for an operator; empty when the whole file was read.
    QString damage() const;

    // Every sample of a field between two times (inclusive), time order.
    std::vector<vehicle::TelemetrySample> series(int vehicle, vehicle::TelemetryField field,
                                                 int64_t from = INT64_MIN, int64_t to = INT64_MAX) const;
    // Every sample of every field with from < time <= to, as the Vehicle model ingests it: one
    // update per sample, time order.
    vehicle::TelemetryBatch updatesBetween(int vehicle, int64_t from, int64_t to) const;
    // The last value of every field at or before `time` (fields not seen by then are absent).
    vehicle::TelemetryBatch stateAt(int vehicle, int64_t time) const;
    // Every field over the whole span, thinned evenly to at most `perField` samples a field (0: all),
    // grouped by field and in time order within each: what a replay's plots hold. Decodes every
    // block, so a replay runs it on a worker thread; it returns early (with nullopt) once
    // *cancelled is set. Safe to call from any thread (the log is not changed after open/finish).
    std::optional<vehicle::TelemetryBatch> thinnedSeries(int vehicle, size_t perField,
                                                         const std::atomic_bool *cancelled = nullptr) const;

    // For building logs in memory.
    void addVehicle(Vehicle v);
    void addEvent(Event e);
    void finish(); // sorts events, computes spans and counts

private:
    QString m_path;
    std::vector<Vehicle> m_vehicles;
    std::vector<Event> m_events;
    int64_t m_start = 0, m_end = 0;
    QString m_stoppedAt;
    QStringList m_skipped;
};

} // namespace sortie::flightlog
