#include "ZoneSharing.h"

#include "Airspace.h"
#include "ServerZoneReply.h"
#include "ServerZones.h"
#include "ZoneEditor.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <algorithm>

Q_LOGGING_CATEGORY(lcZoneSharing, "sortie.airspace.sharing")

namespace sortie::airspace {

ZoneSharing::ZoneSharing(Airspace *store, ServerZones *server, QObject *parent)
    : QObject(parent)
    , m_store(store)
    , m_server(server)
{
    Q_ASSERT(store && server);
    connect(store, &Airspace::selectedZoneChanged, this, &ZoneSharing::selectionChanged);
    connect(store, &Airspace::changed, this, &ZoneSharing::selectionChanged);
    connect(store, &Airspace::changed, this, &ZoneSharing::chooseSent);
}

// The zone just sent stays the chosen one, once the server's list holds it.
void ZoneSharing::chooseSent()
{
    if (!m_chooseWhenListed)
        return;
    const int row = m_store->rowOfServerZone(*m_chooseWhenListed);
    if (row < 0)
        return;
    m_chooseWhenListed.reset();
    m_store->setSelectedZone(row);
}

bool ZoneSharing::canSend() const
{
    return m_store->selectedCustom() >= 0;
}

bool ZoneSharing::sendUpdates() const
{
    const int drawn = m_store->selectedCustom();
    return drawn >= 0 && m_store->customZones()[size_t(drawn)].serverId.has_value();
}

bool ZoneSharing::canEditOnServer() const
{
    return isServerCustom(m_store->selectedZone());
}

bool ZoneSharing::isServerCustom(int row) const
{
    return row >= 0 && row < m_store->count() && m_store->groupOf(row) == Airspace::Group::Server
        && m_store->zoneAt(row).source == ZoneSource::ServerCustom && m_store->zoneAt(row).serverId;
}

bool ZoneSharing::send(int row)
{
    if (isBusy())
        return refuse(tr("Wait: the server has not answered the last change yet."));
    if (row < 0 || row >= int(m_store->customZones().size()) || m_store->groupOf(row) != Airspace::Group::Custom)
        return refuse(tr("Only a zone drawn here can be sent to the server."));
    const Zone &zone = m_store->customZones()[size_t(row)];
    if (zone.serverId) {
        // The server's current version, when it is listed: a newer one is another operator's change.
        for (const Zone &current : m_server->zones())
            if (current.serverId == zone.serverId && current.serverVersion != zone.serverVersion)
                return refuse(tr("Zone '%1' was changed on the server since you copied it (version %2, now %3). "
                                 "Remove your copy and edit the server's zone again.")
                                  .arg(zone.name)
                                  .arg(zone.serverVersion)
                                  .arg(current.serverVersion));
    }
    const Zone sent = zone;
    ServerZoneReply *reply = m_server->save(sent);
    start(reply);
    connect(reply, &ServerZoneReply::finished, this, [this, reply, sent] {
        if (!reply->isOk())
            return end(false, reply->error());
        // The draft, unless the operator changed it meanwhile: then it stays, to be sent again.
        const std::vector<Zone> &drawn = m_store->customZones();
        const auto it = std::find(drawn.begin(), drawn.end(), sent);
        if (it == drawn.end())
            return end(true, tr("Zone '%1' is on the server; you changed it since sending, so your copy stays.").arg(sent.name));
        m_store->editor()->removeZoneAs(int(it - drawn.begin()), tr("Send zone '%1' to the server").arg(sent.name));
        if (reply->zone() && reply->zone()->serverId) {
            m_chooseWhenListed = *reply->zone()->serverId;  // the server's answer lists it soon
            chooseSent();
        }
        end(true, tr("Zone '%1' is on the server.").arg(sent.name));
    });
    return true;
}

bool ZoneSharing::editCopy(int row)
{
    if (!isServerCustom(row))
        return refuse(tr("Only the server's custom zones can be edited here; aerodrome zones are the server's own."));
    const Zone &original = m_store->zoneAt(row);
    Zone copy = original;
    copy.origin = QCoreApplication::translate("Airspace", "server zone %1, edited here").arg(*original.serverId);
    copy.active = true;  // the operator's switch on the server's zone stays with it
    const QString name = copy.name;
    const int drawn = m_store->editor()->adopt(std::move(copy), tr("Edit server zone '%1'").arg(name));
    m_store->setSelectedZone(drawn);
    end(true, tr("Zone '%1' is drawn here to edit; send it to store the change on the server.").arg(name));
    return true;
}

bool ZoneSharing::removeFromServer(int row)
{
    if (isBusy())
        return refuse(tr("Wait: the server has not answered the last change yet."));
    if (!isServerCustom(row))
        return refuse(tr("Only the server's custom zones can be deleted here."));
    const QString name = m_store->zoneAt(row).name;
    ServerZoneReply *reply = m_server->remove(m_store->zoneAt(row));
    start(reply);
    connect(reply, &ServerZoneReply::finished, this, [this, reply, name] {
        end(reply->isOk(), reply->isOk() ? tr("Zone '%1' was deleted on the server.").arg(name) : reply->error());
    });
    return true;
}

bool ZoneSharing::refuse(const QString &why)
{
    m_status = why;
    m_failed = true;
    emit stateChanged();
    return false;
}

void ZoneSharing::start(ServerZoneReply *reply)
{
    m_pending = reply;
    m_chooseWhenListed.reset();
    m_status.clear();
    m_failed = false;
    emit stateChanged();
}

void ZoneSharing::end(bool ok, const QString &status)
{
    m_pending = nullptr;
    m_status = status;
    m_failed = !ok;
    if (ok)
        qCInfo(lcZoneSharing).noquote() << status;
    else
        qCWarning(lcZoneSharing).noquote() << status;
    emit stateChanged();
    emit finished(ok, status);
}

} // namespace sortie::airspace
