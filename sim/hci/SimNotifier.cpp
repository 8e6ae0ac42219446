#include "SimNotifier.h"

#include "HciServerConnection.h"
#include "Messages.pb.h"
#include "SimSessionTable.h"
#include "SimVehicle.h"
#include "SimWorld.h"
#include "SimZones.h"

namespace sortie::sim {
namespace {

bool matches(const std::string &wantedType, bool hasId, int wantedId, const QString &type, int id)
{
    return (wantedType.empty() || wantedType == type.toStdString()) && (!hasId || wantedId == id);
}

} // namespace

SimNotifier::SimNotifier(SimWorld &world, SimSessionTable &sessions, QObject *parent)
    : QObject(parent)
    , m_world(world)
    , m_sessions(sessions)
{
    connect(&world, &SimWorld::telemetry, this, &SimNotifier::onTelemetry);
    connect(&world, &SimWorld::commandsChanged, this, &SimNotifier::onCommandsChanged);
    connect(&world.store(), &SimObjectStore::changed, this, &SimNotifier::onObjectChanged);
    connect(&world.locks(), &SimLockTable::lockChanged, this, &SimNotifier::onLockChanged);
}

void SimNotifier::publish(const Match &match, const Fill &fill)
{
    pb::Notification notification;
    bool filled = false;
    for (auto &[clientId, session] : m_sessions.all()) {
        if (!session.connection || !session.connection->isOpen())
            continue;
        for (const auto &[id, subscription] : session.subscriptions) {
            if (!match(*subscription))
                continue;
            if (!filled) {
                fill(notification.mutable_event());
                filled = true;
            }
            notification.set_subscriptionid(id);
            session.connection->sendNotification(notification);
        }
    }
}

void SimNotifier::onTelemetry(const pb::TelemetryEvent &event)
{
    const int vehicleId = event.vehicle().id();
    publish(
        [vehicleId](const pb::EventSubscriptionWrapper &s) {
            return s.has_telemetrysubscription()
                && (!s.telemetrysubscription().has_vehicle() || s.telemetrysubscription().vehicle().id() == vehicleId);
        },
        [&event](pb::EventWrapper *e) { *e->mutable_telemetryevent() = event; });
}

void SimNotifier::onObjectChanged(int modificationType, const QString &type, int id, const pb::DomainObjectWrapper &object)
{
    publish(
        [&](const pb::EventSubscriptionWrapper &s) {
            const auto &m = s.objectmodificationsubscription();
            return s.has_objectmodificationsubscription() && matches(m.objecttype(), m.has_objectid(), m.objectid(), type, id);
        },
        [&](pb::EventWrapper *e) {
            auto *event = e->mutable_objectmodificationevent();
            event->set_modificationtype(pb::ModificationType(modificationType));
            event->set_objecttype(type.toStdString());
            event->set_objectid(id);
            if (modificationType != pb::MT_DELETE) {
                *event->mutable_object() = object;
                if (event->object().has_user())
                    event->mutable_object()->mutable_user()->clear_password();
            }
        });
    if (type == SimZones::kType)
        onZonesChanged(modificationType == pb::MT_DELETE ? nullptr : &object.noflightzone());
}

void SimNotifier::onZonesChanged(const pb::NoFlightZone *zone)
{
    // The zone's box when it has one; a deleted zone's is gone, so the event covers everything.
    const auto box = zone ? SimZones::boxOf(*zone) : std::nullopt;
    publish([](const pb::EventSubscriptionWrapper &s) { return s.has_environmentsubscription(); },
            [&box](pb::EventWrapper *e) {
                auto *event = e->mutable_environmentevent();
                event->set_environmenteventtype(pb::EET_NFZ_UPDATED);
                if (box) {
                    event->set_minlatitude(box->minLatitude);
                    event->set_minlongitude(box->minLongitude);
                    event->set_maxlatitude(box->maxLatitude);
                    event->set_maxlongitude(box->maxLongitude);
                }
            });
}

void SimNotifier::onLockChanged(const QString &type, int id, bool held)
{
    const auto owner = held ? m_world.locks().holder(type, id) : std::nullopt;
    publish(
        [&](const pb::EventSubscriptionWrapper &s) {
            const auto &l = s.locksubscription();
            return s.has_locksubscription() && matches(l.objecttype(), l.has_objectid(), l.objectid(), type, id);
        },
        [&](pb::EventWrapper *e) {
            auto *event = e->mutable_lockevent();
            event->set_objecttype(type.toStdString());
            event->set_objectid(id);
            if (owner) {
                auto *lock = event->mutable_lock();
                lock->set_objecttype(type.toStdString());
                lock->set_objectid(id);
                lock->mutable_owner()->set_id(owner->userId);
                lock->mutable_owner()->set_login(owner->login.toStdString());
            }
        });
}

void SimNotifier::onCommandsChanged(int vehicleId)
{
    const SimVehicle *vehicle = m_world.vehicle(vehicleId);
    if (!vehicle)
        return;
    publish(
        [vehicleId](const pb::EventSubscriptionWrapper &s) {
            return s.has_commandsubscription() && s.commandsubscription().vehicle().id() == vehicleId;
        },
        [vehicle](pb::EventWrapper *e) {
            auto *event = e->mutable_commandevent();
            *event->mutable_vehicle() = vehicle->reference();
            for (auto &d : vehicle->commands())
                *event->add_commands() = std::move(d);
        });
}

void SimNotifier::greet(SimSession &session, int subscriptionId)
{
    const auto it = session.subscriptions.find(subscriptionId);
    if (it == session.subscriptions.end() || !it->second->has_commandsubscription() || !session.connection)
        return;
    const SimVehicle *vehicle = m_world.vehicle(it->second->commandsubscription().vehicle().id());
    if (!vehicle)
        return;
    pb::Notification n;
    n.set_subscriptionid(subscriptionId);
    auto *event = n.mutable_event()->mutable_commandevent();
    *event->mutable_vehicle() = vehicle->reference();
    for (auto &d : vehicle->commands())
        *event->add_commands() = std::move(d);
    session.connection->sendNotification(n);
}

} // namespace sortie::sim
