#pragma once

#include "TrafficReport.h"

#include <QAbstractListModel>
#include <QTimer>

#include <functional>
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
class TrafficPicture : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    using Clock = std::function<qint64()>; // milliseconds; default: the system clock
    static constexpr qint64 kStaleAfterMs = 60000;
    static constexpr qint64 kRemoveAfterMs = 120000;
    static constexpr qint64 kMslAltitudePreferredMs = 10000;

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

    Clock m_clock;
    std::vector<TrafficAircraft> m_aircraft;
    QTimer m_sweep;
};

} // namespace sortie::traffic
