#pragma once

#include "TrafficReport.h"

#include <QAbstractListModel>
#include <QHash>
#include <QTimer>

#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace sortie::traffic {

// One aircraft as the picture knows it: every field the last report that carried it said (so a
// position from one message and a call sign from another make one aircraft), when it was last heard,
// and from which source.
struct TrafficAircraft
{
    TrafficReport state;      // merged: a field stays until a later report brings a new value
    qint64 lastSeenMs = 0;    // the picture's clock when it was last heard
    qint64 firstSeenMs = 0;
    qint64 mslAltitudeMs = 0; // when the last altitude above mean sea level came (0: never)
    bool stale = false;
    double rangeM = std::numeric_limits<double>::infinity(); // from the picture's reference (infinity: no position or no reference)
};

// Velocity over the ground and up, in m/s, east-north-up: from ground speed and track (and the
// vertical rate, which is absent when no source gave one). Absent without ground speed or track.
struct TrafficVelocity
{
    double east = 0;
    double north = 0;
    std::optional<double> up;
};
std::optional<TrafficVelocity> velocityOf(const TrafficReport &state);

// The manned traffic around: aircraft by address, merged from partial reports of any source. An
// aircraft not heard for kStaleAfterMs is stale (kept, shown faded: its position is old); one not
// heard for kRemoveAfterMs is removed. The sweep runs every second on the clock given (tests pass
// their own clock and call sweep()). Absent values are invalid QVariants in the model, never 0.
//
// Bounded under a flood (issue 36: a feed of 200,000 addresses): at most capacity() aircraft are
// held, the nearest to the reference (the view's centre) kept — a newcomer nearer than the farthest
// held takes its row, one farther (or with no position yet, when full) is left out and counted.
// Aircraft are found by address in a hash, and what the model tells its views is gathered: one
// dataChanged, countChanged and changed() a frame (kNotifyMs), however many reports came in it.
class TrafficPicture : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    using Clock = std::function<qint64()>; // milliseconds; default: the system clock
    static constexpr qint64 kStaleAfterMs = 60000;
    static constexpr qint64 kRemoveAfterMs = 120000;
    static constexpr qint64 kMslAltitudePreferredMs = 10000;
    static constexpr int kDefaultCapacity = 500;
    static constexpr int kNotifyMs = 16;

    enum Role {
        AddressRole = Qt::UserRole + 1, CallsignRole, LatitudeRole, LongitudeRole, AltitudeRole, AltitudeReferenceRole,
        GroundSpeedRole, TrackRole, VerticalRateRole, VelocityEastRole, VelocityNorthRole, VelocityUpRole, SquawkRole,
        OnGroundRole, LastSeenRole, StaleRole, SourceRole
    };

    explicit TrafficPicture(Clock clock = {}, QObject *parent = nullptr);

    // Merges what a source heard now. A report whose sourceTimeMs equals the one already held (the
    // server repeating an old entry) updates the fields but does not count as heard again. An
    // altitude above mean sea level (the server's) is kept over a pressure altitude (a receiver's)
    // until none came for kMslAltitudePreferredMs, so two sources do not make it flip between them.
    void report(const TrafficReport &report);
    // Marks aircraft stale and removes the ones gone, at the clock's now.
    void sweep();
    void clear();
    // Tells the views now what the frame gathered (sweep() and clear() do it first).
    void flush();

    // How many aircraft are held at most (at least 1); fewer now drops the farthest.
    void setCapacity(int capacity);
    int capacity() const { return m_capacity; }
    // Where "nearest" is measured from (degrees); until set, a full picture keeps the ones it has.
    void setReference(double latitude, double longitude);
    // Reports of aircraft left out because the picture was full and they were not nearer.
    qint64 leftOut() const { return m_leftOut; }

    int count() const { return int(m_aircraft.size()); }
    const std::vector<TrafficAircraft> &aircraft() const { return m_aircraft; }
    const TrafficAircraft *find(quint32 address, bool nonIcao = false) const;
    qint64 now() const { return m_clock(); }

    // "4CA2D6" (a non-ICAO address "~4CA2D6").
    static QString addressText(const TrafficReport &state);
    static QString referenceName(AltitudeReference reference);
    static QString sourceName(TrafficSource source);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();
    // Anything drawn changed (an aircraft moved, came, went stale or left).
    void changed();

private:
    int rowOf(quint32 address, bool nonIcao) const;
    static quint64 keyOf(quint32 address, bool nonIcao) { return quint64(address) | (nonIcao ? quint64(1) << 32 : 0); }
    double rangeOf(const TrafficReport &state) const;
    int farthestRow();
    void touch(int row);
    void reindex();

    Clock m_clock;
    std::vector<TrafficAircraft> m_aircraft;
    QHash<quint64, int> m_rows; // address key -> row
    QTimer m_sweep;
    QTimer m_notify;
    int m_capacity = kDefaultCapacity;
    std::optional<std::pair<double, double>> m_reference; // radians
    int m_farthest = -1; // cached farthest row; -1: to be found again
    qint64 m_leftOut = 0;
    int m_dirtyFirst = -1, m_dirtyLast = -1;
    int m_notifiedCount = 0;
    bool m_changed = false;
};

} // namespace sortie::traffic
