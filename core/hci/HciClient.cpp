#include "HciClient.h"

#include "HciSession.h"
#include "Messages.pb.h"

namespace sortie::hci {
namespace {

void toValue(const QVariant &v, pb::Value *out)
{
    switch (v.typeId()) {
    case QMetaType::Bool: out->set_boolvalue(v.toBool()); break;
    case QMetaType::QString: out->set_stringvalue(v.toString().toStdString()); break;
    default: out->set_doublevalue(v.toDouble()); break;
    }
}

} // namespace

HciClient::HciClient(HciSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
}

HciReply *HciClient::listObjects(HciObjectType type, bool refreshDependencies)
{
    return listObjects(objectTypeName(type), refreshDependencies);
}

HciReply *HciClient::listObjects(const QString &objectType, bool refreshDependencies)
{
    pb::GetObjectListRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectType.toStdString());
    r.set_refreshdependencies(refreshDependencies);
    return m_session->send(r);
}

HciReply *HciClient::getObject(HciObjectType type, int objectId, bool refreshDependencies)
{
    return getObject(objectTypeName(type), objectId, refreshDependencies);
}

HciReply *HciClient::getObject(const QString &objectType, int objectId, bool refreshDependencies)
{
    pb::GetObjectRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectType.toStdString());
    r.set_objectid(objectId);
    r.set_refreshdependencies(refreshDependencies);
    return m_session->send(r);
}

HciReply *HciClient::createOrUpdate(const google::protobuf::Message &object, bool acquireLock)
{
    pb::CreateOrUpdateObjectRequest r;
    r.set_clientid(-1);
    r.set_objecttype(object.GetDescriptor()->name());
    wrapObject(object, r.mutable_object()); // an unwrappable type leaves `object` empty: the server says so
    if (acquireLock)
        r.set_acquirelock(true);
    return m_session->send(r);
}

HciReply *HciClient::updateFields(const google::protobuf::Message &object, const QStringList &fieldNames, bool acquireLock)
{
    pb::UpdateObjectFieldsRequest r;
    r.set_clientid(-1);
    r.set_objecttype(object.GetDescriptor()->name());
    wrapObject(object, r.mutable_object());
    for (const QString &name : fieldNames)
        r.add_fieldnames(name.toStdString());
    if (acquireLock)
        r.set_acquirelock(true);
    return m_session->send(r);
}

HciReply *HciClient::deleteObject(HciObjectType type, int objectId)
{
    return deleteObject(objectTypeName(type), objectId);
}

HciReply *HciClient::deleteObject(const QString &objectType, int objectId)
{
    pb::DeleteObjectRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectType.toStdString());
    r.set_objectid(objectId);
    return m_session->send(r);
}

HciReply *HciClient::acquireLock(HciObjectType type, int objectId)
{
    pb::AcquireLockRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectTypeName(type).toStdString());
    r.set_objectid(objectId);
    return m_session->send(r);
}

HciReply *HciClient::releaseLock(HciObjectType type, int objectId, bool ifExclusive)
{
    pb::ReleaseLockRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectTypeName(type).toStdString());
    r.set_objectid(objectId);
    r.set_ifexclusive(ifExclusive);
    return m_session->send(r);
}

HciReply *HciClient::checkLock(HciObjectType type, int objectId)
{
    pb::CheckLockRequest r;
    r.set_clientid(-1);
    r.set_objecttype(objectTypeName(type).toStdString());
    r.set_objectid(objectId);
    return m_session->send(r);
}

HciReply *HciClient::sendCommand(const pb::Vehicle &vehicle, const pb::Command &command)
{
    pb::SendCommandRequest r;
    r.set_clientid(-1);
    *r.mutable_command() = command;
    *r.add_vehicles() = vehicle;
    return m_session->send(r);
}

HciReply *HciClient::sendCommand(const pb::Vehicle &vehicle, const QString &code, const QVariantMap &arguments)
{
    pb::Command command;
    command.set_code(code.toStdString());
    command.set_subsystem(pb::S_FLIGHT_CONTROLLER);
    command.set_subsystemid(0);
    for (auto it = arguments.begin(); it != arguments.end(); ++it) {
        auto *argument = command.add_arguments();
        argument->set_code(it.key().toStdString());
        toValue(it.value(), argument->mutable_value());
    }
    return sendCommand(vehicle, command);
}

HciReply *HciClient::processRoute(const pb::Route &route)
{
    pb::ProcessRouteRequest r;
    r.set_clientid(-1);
    *r.mutable_route() = route;
    return m_session->send(r, m_longTimeout);
}

HciReply *HciClient::uploadRoute(const pb::Vehicle &vehicle, const pb::ProcessedRoute &route, bool addFirstWaypoint)
{
    pb::UploadRouteRequest r;
    r.set_clientid(-1);
    *r.mutable_vehicle() = vehicle;
    *r.mutable_processedroute() = route;
    if (!addFirstWaypoint)
        r.set_addfirstwaypoint(false);
    return m_session->send(r, m_longTimeout);
}

HciReply *HciClient::telemetryHistory(const pb::Vehicle &vehicle, qint64 fromTimeMs, qint64 toTimeMs, int limit)
{
    pb::GetTelemetryRequest r;
    r.set_clientid(-1);
    *r.mutable_vehicle() = vehicle;
    r.set_fromtime(fromTimeMs);
    r.set_totime(toTimeMs);
    r.set_limit(limit);
    return m_session->send(r);
}

HciSubscription *HciClient::subscribeTelemetry(int vehicleId)
{
    pb::EventSubscriptionWrapper w;
    auto *s = w.mutable_telemetrysubscription();
    if (vehicleId >= 0)
        s->mutable_vehicle()->set_id(vehicleId);
    return m_session->subscribe(w);
}

HciSubscription *HciClient::subscribeObjectChanges(HciObjectType type, int objectId)
{
    pb::EventSubscriptionWrapper w;
    auto *s = w.mutable_objectmodificationsubscription();
    s->set_objecttype(objectTypeName(type).toStdString());
    if (objectId >= 0)
        s->set_objectid(objectId);
    return m_session->subscribe(w);
}

HciSubscription *HciClient::subscribeLocks(HciObjectType type, int objectId)
{
    pb::EventSubscriptionWrapper w;
    auto *s = w.mutable_locksubscription();
    s->set_objecttype(objectTypeName(type).toStdString());
    if (objectId >= 0)
        s->set_objectid(objectId);
    return m_session->subscribe(w);
}

HciSubscription *HciClient::subscribeCommands(const pb::Vehicle &vehicle)
{
    pb::EventSubscriptionWrapper w;
    *w.mutable_commandsubscription()->mutable_vehicle() = vehicle;
    return m_session->subscribe(w);
}

} // namespace sortie::hci
