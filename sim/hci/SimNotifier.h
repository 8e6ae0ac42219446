#pragma once

#include "SimServices.h"

#include <QObject>

#include <functional>

namespace com::ugcs::ucs::proto {
class DomainObjectWrapper;
class EventSubscriptionWrapper;
class EventWrapper;
class NoFlightZone;
class TelemetryEvent;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
struct SimSession;

// Publishes events to the sessions that subscribed to them, as Notification frames (instance id -1)
// carrying each subscription's id: telemetry, object modifications, locks, vehicle commands and
// no-fly zone changes (EnvironmentEvent EET_NFZ_UPDATED over the zone's box).
// Detached sessions miss what happens while they are away, as with UgCS.
class SimNotifier : public QObject
{
    Q_OBJECT

public:
    SimNotifier(SimWorld &world, SimSessionTable &sessions, QObject *parent = nullptr);

    // The state a new subscription starts from: the vehicle's commands for a command subscription.
    void greet(SimSession &session, int subscriptionId);

private:
    using Match = std::function<bool(const pb::EventSubscriptionWrapper &)>;
    using Fill = std::function<void(pb::EventWrapper *)>;
    void publish(const Match &match, const Fill &fill);
    void onTelemetry(const pb::TelemetryEvent &event);
    void onObjectChanged(int modificationType, const QString &type, int id, const pb::DomainObjectWrapper &object);
    void onLockChanged(const QString &type, int id, bool held);
    // EET_NFZ_UPDATED to environment subscribers; `zone` null after a delete.
    void onZonesChanged(const pb::NoFlightZone *zone);
    void onCommandsChanged(int vehicleId);

    SimWorld &m_world;
    SimSessionTable &m_sessions;
};

} // namespace sortie::sim
