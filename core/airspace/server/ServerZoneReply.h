#pragma once

#include "Zone.h"

#include <QObject>

#include <optional>

namespace sortie::airspace {

// The outcome of saving or deleting one server zone (ServerZones::save, remove), which takes
// several requests (lock, write, release). finished() comes exactly once, never before the caller
// could connect to it (at the earliest on the next event-loop turn); then the reply deletes itself
// (deleteLater). error() is for the operator and names the zone: "Zone 'Pier' was not saved:
// NoFlightZone 12 is locked by user 'bob' in another session".
class ServerZoneReply : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool finished READ isFinished NOTIFY finished)
    Q_PROPERTY(bool ok READ isOk NOTIFY finished)
    Q_PROPERTY(QString error READ error NOTIFY finished)

public:
    explicit ServerZoneReply(QObject *parent = nullptr);

    bool isFinished() const { return m_finished; }
    bool isOk() const { return m_finished && m_error.isEmpty(); }
    QString error() const { return m_error; }
    // Saved: the zone as the server stored it (its id and new version). Deleted: the zone deleted.
    const std::optional<Zone> &zone() const { return m_zone; }

    // For ServerZones: ends the reply (once) with a zone or an error.
    void succeed(Zone zone);
    void fail(const QString &error);

signals:
    void finished();

private:
    void finish();

    bool m_finished = false;
    QString m_error;
    std::optional<Zone> m_zone;
};

} // namespace sortie::airspace
