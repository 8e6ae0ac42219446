#pragma once

#include "ServerZoneReply.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <optional>

namespace sortie::airspace {

class Airspace;
class ServerZones;

// The drawn zones and the server's custom zones meet here, one operation at a time:
// - send: a drawn zone goes to the server, as a new custom zone or, when it is a copy of one, as
//   that zone's new version (under its lock). Once stored, the drawn zone is taken off the drawn
//   ones in one undo step (undo brings the draft back, not the server's change) and the server's
//   answer draws it.
// - editCopy: a server custom zone becomes a drawn copy that remembers the zone's id and version;
//   while the copy exists, the server's zone is not listed (one zone, drawn once). Removing the copy
//   brings the server's back unchanged.
// - removeFromServer: a server custom zone deleted (under its lock).
// A copy whose zone another operator changed since is not sent (it would undo their change); the
// operator is told and can copy the new version. Aerodrome zones are the server's: not edited.
class ZoneSharing : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool busy READ isBusy NOTIFY stateChanged)
    // The last operation's outcome for the operator ("'Pier' is on the server.", an error); empty before.
    Q_PROPERTY(QString status READ status NOTIFY stateChanged)
    Q_PROPERTY(bool failed READ hasFailed NOTIFY stateChanged)
    // What the chosen zone (Airspace::selectedZone) allows.
    Q_PROPERTY(bool canSend READ canSend NOTIFY selectionChanged)        // a drawn zone
    Q_PROPERTY(bool sendUpdates READ sendUpdates NOTIFY selectionChanged)  // ... that is a server zone's copy
    Q_PROPERTY(bool canEditOnServer READ canEditOnServer NOTIFY selectionChanged)  // a server custom zone

public:
    ZoneSharing(Airspace *store, ServerZones *server, QObject *parent = nullptr);

    bool isBusy() const { return bool(m_pending); }
    QString status() const { return m_status; }
    bool hasFailed() const { return m_failed; }
    bool canSend() const;
    bool sendUpdates() const;
    bool canEditOnServer() const;

    // Each returns false (and says why in status) when it cannot start.
    Q_INVOKABLE bool send(int row);
    Q_INVOKABLE bool editCopy(int row);
    Q_INVOKABLE bool removeFromServer(int row);

signals:
    void stateChanged();
    void selectionChanged();
    // An operation ended (tests, the command log).
    void finished(bool ok, const QString &status);

private:
    bool refuse(const QString &why);
    bool isServerCustom(int row) const;
    void start(ServerZoneReply *reply);
    void end(bool ok, const QString &status);
    void chooseSent();

    Airspace *m_store;
    ServerZones *m_server;
    QPointer<ServerZoneReply> m_pending;
    QString m_status;
    bool m_failed = false;
    std::optional<int> m_chooseWhenListed;
};

} // namespace sortie::airspace
