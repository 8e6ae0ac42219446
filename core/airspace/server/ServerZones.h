#pragma once

#include "GeoPoint.h"
#include "HciReply.h"
#include "HciSubscription.h"
#include "ServerZoneReply.h"
#include "Zone.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <map>
#include <memory>
#include <vector>

namespace com::ugcs::ucs::proto {
class EventWrapper;
class NoFlightZone;
} // namespace com::ugcs::ucs::proto

namespace sortie::hci {
class HciClient;
} // namespace sortie::hci

namespace sortie::airspace {

// The UgCS server's no-fly zones around the map's view: both types (aerodrome and custom) through
// GetNfzListRequest for the view box, asked when the session is ready, when the box changes, when
// the server says its zones changed (EnvironmentSubscription, EET_NFZ_UPDATED, over the box) and
// after this client changed one; one request at a time (a change meanwhile asks once more after
// the answer). A zone the conversion refuses is left out and logged by name (problems()). Zones
// stay while the line is down (they are still the airspace) and are replaced by the next answer.
//
// Custom zones are created, edited and deleted here: an edit or a delete takes the zone's lock
// (hci::underLock, as a route's save does), writes, releases; a lock another operator holds
// refuses it with their name. Every outcome reaches the caller as a ServerZoneReply.
class ServerZones : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString error READ error NOTIFY stateChanged)        // the last fetch's failure, empty after an answer
    Q_PROPERTY(QStringList problems READ problems NOTIFY zonesChanged)  // zones left out of the last answer
    Q_PROPERTY(bool asking READ isAsking NOTIFY stateChanged)

public:
    explicit ServerZones(hci::HciClient *client, QObject *parent = nullptr);
    ~ServerZones() override;

    // The area to ask about (degrees). An empty box asks for nothing; one across ±180° is refused
    // (error()), as the airspace check does not support it.
    void setViewBox(const mission::GeoBox &box);
    const mission::GeoBox &viewBox() const { return m_box; }
    // Asks now, or once more after the answer outstanding.
    void refresh();

    const std::vector<Zone> &zones() const { return m_zones; }
    QStringList problems() const { return m_problems; }
    QString error() const { return m_error; }
    bool isAsking() const { return bool(m_pending); }

    // Creates the zone as a custom zone (no serverId) or updates it (with one, under its lock).
    ServerZoneReply *save(const Zone &zone);
    // Deletes a custom zone the server holds (serverId), under its lock.
    ServerZoneReply *remove(const Zone &zone);

signals:
    void zonesChanged();
    void stateChanged();
    // After each answer went into zones() (tests, the lead's wiring).
    void answered();

private:
    void onEvent(const com::ugcs::ucs::proto::EventWrapper &event);
    void onAnswer(hci::HciReply *reply);
    void setError(const QString &error);
    void write(ServerZoneReply *out, const com::ugcs::ucs::proto::NoFlightZone &nfz, const QString &name);
    const com::ugcs::ucs::proto::NoFlightZone *sent(const std::optional<int> &id) const;

    hci::HciClient *m_client;
    QPointer<hci::HciSubscription> m_events;  // the session owns it
    QPointer<hci::HciReply> m_pending;
    bool m_again = false;
    mission::GeoBox m_box;
    std::vector<Zone> m_zones;
    // The zones as the server sent them, by id: an update starts from these (unmodelled fields kept).
    std::map<int, std::shared_ptr<const com::ugcs::ucs::proto::NoFlightZone>> m_sent;
    QStringList m_problems;
    QString m_error;
};

} // namespace sortie::airspace
