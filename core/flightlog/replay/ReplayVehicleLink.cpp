#include "ReplayVehicleLink.h"

#include <QMetaObject>
#include <QPointer>

namespace sortie::flightlog {

namespace {
vehicle::CommandResult refused()
{
    return vehicle::CommandResult::failure(QObject::tr("a replayed vehicle takes no commands"));
}
} // namespace

ReplayVehicleLink::ReplayVehicleLink(vehicle::VehicleIdentity recorded, QObject *parent)
    : VehicleLink(parent)
    , m_identity(std::move(recorded))
{
    m_identity.protocol = protocolName();
}

void ReplayVehicleLink::deliver(const vehicle::TelemetryBatch &batch)
{
    if (!batch.empty())
        emit telemetryReceived(batch);
}

void ReplayVehicleLink::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void ReplayVehicleLink::refuse(const Done &done)
{
    // Later, never inside the call (the VehicleLink contract).
    QMetaObject::invokeMethod(this, [done] { done(refused()); }, Qt::QueuedConnection);
}

void ReplayVehicleLink::prepareMission(const mission::Route &, PrepareDone done)
{
    QMetaObject::invokeMethod(this, [done] { done(refused(), {}); }, Qt::QueuedConnection);
}

void ReplayVehicleLink::downloadMission(MissionDone done)
{
    QMetaObject::invokeMethod(this, [done] { done(refused(), {}); }, Qt::QueuedConnection);
}

void ReplayVehicleLink::readParameters(ParametersDone done)
{
    QMetaObject::invokeMethod(this, [done] { done(refused(), {}); }, Qt::QueuedConnection);
}

} // namespace sortie::flightlog
