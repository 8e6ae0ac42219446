#include "ServerZones.h"

#include "HciClient.h"
#include "HciLock.h"
#include "HciReply.h"
#include "HciSession.h"
#include "HciSubscription.h"
#include "Messages.pb.h"
#include "NfzConversion.h"

#include <QLoggingCategory>

#include <numbers>

Q_LOGGING_CATEGORY(lcServerZones, "sortie.airspace.server")

namespace sortie::airspace {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

bool meets(const mission::GeoBox &a, double south, double west, double north, double east)
{
    return !a.empty && a.south <= north && south <= a.north && a.west <= east && west <= a.east;
}

// What one write under the lock brings back, kept until the lock is released.
struct Written
{
    std::shared_ptr<hci::HciReply> reply;
    QString refusal;
};

std::shared_ptr<hci::HciReply> kept(hci::HciReply *reply)
{
    return std::shared_ptr<hci::HciReply>(reply, [](hci::HciReply *r) { r->deleteLater(); });
}

} // namespace

ServerZones::ServerZones(hci::HciClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    pb::EventSubscriptionWrapper subscription;
    subscription.mutable_environmentsubscription();
    m_events = m_client->session()->subscribe(subscription);
    connect(m_events, &hci::HciSubscription::received, this, &ServerZones::onEvent);
    connect(m_events, &hci::HciSubscription::failed, this, [](const hci::HciError &e) {
        qCWarning(lcServerZones).noquote() << "the server refused the zone-change subscription:" << e.toString();
    });
    connect(m_client->session(), &hci::HciSession::stateChanged, this, [this](hci::HciSession::State state) {
        if (state == hci::HciSession::State::Ready)
            refresh();
    });
}

ServerZones::~ServerZones()
{
    delete m_events.data();  // ends it on the server too (null when the session went first)
}

void ServerZones::setViewBox(const mission::GeoBox &box)
{
    if (box == m_box)
        return;
    m_box = box;
    refresh();
}

void ServerZones::refresh()
{
    if (m_box.empty || !m_client->session()->isReady())
        return;
    if (m_box.crossesAntimeridian())
        return setError(tr("Zones across the ±180° meridian are not supported; the view was not asked about."));
    if (m_pending) {
        m_again = true;
        return;
    }
    m_again = false;
    pb::GetNfzListRequest request;
    request.set_clientid(-1);
    request.set_minlatitude(m_box.south * kRadiansPerDegree);
    request.set_minlongitude(m_box.west * kRadiansPerDegree);
    request.set_maxlatitude(m_box.north * kRadiansPerDegree);
    request.set_maxlongitude(m_box.east * kRadiansPerDegree);
    request.add_types(pb::NT_CUSTOM);
    request.add_types(pb::NT_AERODROME);
    hci::HciReply *reply = m_client->session()->send(request);
    m_pending = reply;
    connect(reply, &hci::HciReply::finished, this, [this, reply] { onAnswer(reply); });
    emit stateChanged();
}

void ServerZones::onEvent(const pb::EventWrapper &event)
{
    if (!event.has_environmentevent() || event.environmentevent().environmenteventtype() != pb::EET_NFZ_UPDATED)
        return;
    const auto &e = event.environmentevent();
    const bool boxed = e.has_minlatitude() && e.has_minlongitude() && e.has_maxlatitude() && e.has_maxlongitude();
    constexpr double kDeg = 1.0 / kRadiansPerDegree;
    if (boxed && !meets(m_box, e.minlatitude() * kDeg, e.minlongitude() * kDeg, e.maxlatitude() * kDeg, e.maxlongitude() * kDeg))
        return;  // a change elsewhere
    refresh();
}

void ServerZones::onAnswer(hci::HciReply *reply)
{
    m_pending = nullptr;
    if (!reply->isOk()) {
        qCWarning(lcServerZones).noquote() << "server zones:" << reply->error().toString();
        setError(tr("The server's no-fly zones could not be read: %1").arg(reply->error().message()));
    } else {
        const auto &answer = reply->response<pb::GetNfzListResponse>();
        QStringList problems;
        m_zones = NfzConversion::toZones(answer.zones(), &problems);
        for (const QString &p : problems)
            qCWarning(lcServerZones).noquote() << p;
        m_sent.clear();
        for (const pb::NoFlightZone &nfz : answer.zones())
            if (nfz.has_id())
                m_sent[nfz.id()] = std::make_shared<const pb::NoFlightZone>(nfz);
        m_problems = problems;
        m_error.clear();
        emit zonesChanged();
        emit answered();
    }
    emit stateChanged();  // not asking (or asking again, just below), perhaps a new error
    if (m_again)
        refresh();
}

void ServerZones::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit stateChanged();
}

const pb::NoFlightZone *ServerZones::sent(const std::optional<int> &id) const
{
    if (!id)
        return nullptr;
    const auto it = m_sent.find(*id);
    return it == m_sent.end() ? nullptr : it->second.get();
}

ServerZoneReply *ServerZones::save(const Zone &zone)
{
    auto *out = new ServerZoneReply(this);
    const QString name = zone.name;
    if (!m_client->session()->isReady()) {
        out->fail(tr("Zone '%1' was not saved: not connected to the server.").arg(name));
        return out;
    }
    QString why;
    const auto nfz = NfzConversion::toNfz(zone, sent(zone.serverId), &why);
    if (!nfz) {
        out->fail(tr("Zone '%1' cannot be saved on the server: %2.").arg(name, why));
        return out;
    }
    if (!zone.serverId) {  // a new object has no lock to take, as a new route has none
        hci::HciReply *reply = m_client->createOrUpdate(*nfz);
        connect(reply, &hci::HciReply::finished, this, [this, out, reply, name] {
            if (!reply->isOk())
                return out->fail(tr("Zone '%1' was not saved: %2").arg(name, reply->error().message()));
            write(out, reply->response<pb::CreateOrUpdateObjectResponse>().object().noflightzone(), name);
        });
        return out;
    }
    hci::underLock<Written>(m_client, hci::HciObjectType::NoFlightZone, *zone.serverId, this,
                            {[this, nfz = *nfz](auto finish) {
                                 hci::HciReply *reply = m_client->createOrUpdate(nfz);
                                 reply->setAutoDelete(false);
                                 connect(reply, &hci::HciReply::finished, this, [reply, finish] { finish(Written{kept(reply), {}}); });
                             },
                             [](const hci::HciError &refusal) { return Written{nullptr, refusal.message()}; },
                             [this, out, name](Written outcome) {
                                 if (!outcome.refusal.isEmpty())
                                     return out->fail(tr("Zone '%1' was not saved: it is locked (%2)").arg(name, outcome.refusal));
                                 if (!outcome.reply->isOk())
                                     return out->fail(tr("Zone '%1' was not saved: %2").arg(name, outcome.reply->error().message()));
                                 write(out, outcome.reply->response<pb::CreateOrUpdateObjectResponse>().object().noflightzone(), name);
                             },
                             {},
                             {}});
    return out;
}

void ServerZones::write(ServerZoneReply *out, const pb::NoFlightZone &stored, const QString &name)
{
    QString why;
    auto zone = NfzConversion::toZone(stored, &why);
    if (!zone)
        return out->fail(tr("Zone '%1' was saved, but the server's answer cannot be read back: %2").arg(name, why));
    qCInfo(lcServerZones).noquote() << "saved" << zone->name << "as NoFlightZone" << *zone->serverId << "version" << zone->serverVersion;
    out->succeed(std::move(*zone));
    refresh();
}

ServerZoneReply *ServerZones::remove(const Zone &zone)
{
    auto *out = new ServerZoneReply(this);
    const QString name = zone.name;
    if (!zone.serverId) {
        out->fail(tr("Zone '%1' was not deleted: it is not on the server.").arg(name));
        return out;
    }
    if (zone.source == ZoneSource::ServerAerodrome) {
        out->fail(tr("Zone '%1' was not deleted: aerodrome zones are the server's own.").arg(name));
        return out;
    }
    if (!m_client->session()->isReady()) {
        out->fail(tr("Zone '%1' was not deleted: not connected to the server.").arg(name));
        return out;
    }
    const int id = *zone.serverId;
    hci::underLock<Written>(m_client, hci::HciObjectType::NoFlightZone, id, this,
                            {[this, id](auto finish) {
                                 hci::HciReply *reply = m_client->deleteObject(hci::HciObjectType::NoFlightZone, id);
                                 reply->setAutoDelete(false);
                                 connect(reply, &hci::HciReply::finished, this, [reply, finish] { finish(Written{kept(reply), {}}); });
                             },
                             [](const hci::HciError &refusal) { return Written{nullptr, refusal.message()}; },
                             [this, out, name, zone](Written outcome) {
                                 if (!outcome.refusal.isEmpty())
                                     return out->fail(tr("Zone '%1' was not deleted: it is locked (%2)").arg(name, outcome.refusal));
                                 if (!outcome.reply->isOk())
                                     return out->fail(tr("Zone '%1' was not deleted: %2").arg(name, outcome.reply->error().message()));
                                 qCInfo(lcServerZones).noquote() << "deleted" << name << "(NoFlightZone" << *zone.serverId << ")";
                                 out->succeed(zone);
                                 refresh();
                             },
                             {},
                             {}});
    return out;
}

} // namespace sortie::airspace
