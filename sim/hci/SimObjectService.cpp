#include "SimObjectService.h"

#include "HciObjectType.h"
#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimSessionTable.h"
#include "SimWorld.h"
#include "SimZones.h"

namespace sortie::sim {
namespace {

using google::protobuf::Message;

const QString kCommandDefinition = QStringLiteral("CommandDefinition");

void sanitize(pb::DomainObjectWrapper *w)
{
    if (w->has_user())
        w->mutable_user()->clear_password();
}

// Gives `to` the value `from` has for one named field (absent in `from` clears it). False when the
// type has no such field.
bool copyField(const Message &from, Message *to, const std::string &name)
{
    const auto *field = to->GetDescriptor()->FindFieldByName(name);
    if (!field)
        field = to->GetDescriptor()->FindFieldByCamelcaseName(name);
    if (!field)
        return false;
    std::unique_ptr<Message> source(from.New());
    source->CopyFrom(from);
    to->GetReflection()->SwapFields(to, source.get(), {field});
    return true;
}

} // namespace

SimObjectService::SimObjectService(SimServices services)
    : m_s(services)
{
}

void SimObjectService::install(HciRequestDispatcher &d)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::GetObjectListRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { list(c); });
    d.add(pb::GetObjectRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { get(c); });
    d.add(pb::CreateOrUpdateObjectRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { createOrUpdate(c); });
    d.add(pb::UpdateObjectFieldsRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { updateFields(c); });
    d.add(pb::DeleteObjectRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { remove(c); });
}

QString SimObjectService::readOnlyReason(const QString &type, bool creating)
{
    if (type == kCommandDefinition || type == QLatin1String("TraverseAlgorithm"))
        return QStringLiteral("%1 objects are defined by the server and cannot be changed").arg(type);
    if (type == QLatin1String("RoutePass"))
        return QStringLiteral("RoutePass objects are kept by the server while a vehicle flies an uploaded route");
    if (type == QLatin1String("User"))
        return QStringLiteral("Users are configured when the simulator starts (--user) and cannot be changed over HCI");
    if (type == QLatin1String("Vehicle") && creating)
        return QStringLiteral("Vehicles appear when they connect to the server; they cannot be created over HCI");
    return {};
}

QString SimObjectService::lockedReason(const SimCall &call, const QString &type, int id) const
{
    const auto owner = m_s.world.locks().holder(type, id);
    if (!owner || owner->clientId == call.session->clientId)
        return {};
    return QStringLiteral("%1 %2 is locked by user '%3' in another session").arg(type).arg(id).arg(owner->login);
}

void SimObjectService::list(SimCall &call)
{
    const auto &r = static_cast<const pb::GetObjectListRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    if (!hci::isObjectType(type)) {
        call.respond.error(QStringLiteral("Unknown object type '%1'").arg(type));
        return;
    }
    pb::GetObjectListResponse response;
    response.set_objecttype(r.objecttype());
    if (type == kCommandDefinition) {
        for (auto &d : m_s.world.commandDefinitions())
            *response.add_objects()->mutable_commanddefinition() = std::move(d);
    } else {
        for (const auto *w : m_s.world.store().list(type)) {
            auto *copy = response.add_objects();
            *copy = *w;
            sanitize(copy);
        }
    }
    call.respond.reply(response);
}

void SimObjectService::get(SimCall &call)
{
    const auto &r = static_cast<const pb::GetObjectRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    pb::GetObjectResponse response;
    response.set_objecttype(r.objecttype());
    if (type == kCommandDefinition) {
        for (auto &d : m_s.world.commandDefinitions())
            if (d.id() == r.objectid())
                *response.mutable_object()->mutable_commanddefinition() = std::move(d);
    } else if (const auto *w = m_s.world.store().find(type, r.objectid())) {
        *response.mutable_object() = *w;
        sanitize(response.mutable_object());
    }
    if (!response.has_object()) {
        call.respond.error(QStringLiteral("%1 %2 does not exist").arg(type).arg(r.objectid()));
        return;
    }
    call.respond.reply(response);
}

void SimObjectService::createOrUpdate(SimCall &call)
{
    const auto &r = static_cast<const pb::CreateOrUpdateObjectRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    const Message *object = hci::unwrapObject(r.object(), type);
    if (!object) {
        call.respond.error(QStringLiteral("The request's object does not hold a %1").arg(type));
        return;
    }
    const int id = hci::objectId(*object);
    if (const QString why = readOnlyReason(type, id < 0); !why.isEmpty()) {
        call.respond.error(why);
        return;
    }
    if (id >= 0)
        if (const QString why = lockedReason(call, type, id); !why.isEmpty()) {
            call.respond.error(why);
            return;
        }
    if (type == SimZones::kType)
        if (const QString why = SimZones::writeRefusal(m_s.world.store(), id, &r.object().noflightzone()); !why.isEmpty()) {
            call.respond.error(why);
            return;
        }
    const auto saved = m_s.world.store().save(type, r.object(), SimWorld::now());
    if (!saved.object) {
        call.respond.error(saved.error);
        return;
    }
    if (r.acquirelock()) {
        const int savedId = hci::objectId(*hci::unwrapObject(*saved.object, type));
        m_s.world.locks().acquire(type, savedId, {call.session->clientId, call.session->user->id, call.session->user->login});
    }
    pb::CreateOrUpdateObjectResponse response;
    response.set_objecttype(r.objecttype());
    *response.mutable_object() = *saved.object;
    call.respond.reply(response);
}

void SimObjectService::updateFields(SimCall &call)
{
    const auto &r = static_cast<const pb::UpdateObjectFieldsRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    const Message *changes = hci::unwrapObject(r.object(), type);
    const int id = changes ? hci::objectId(*changes) : -1;
    const pb::DomainObjectWrapper *stored = id >= 0 ? m_s.world.store().find(type, id) : nullptr;
    if (!stored) {
        call.respond.error(changes ? QStringLiteral("%1 %2 does not exist").arg(type).arg(id)
                                   : QStringLiteral("The request's object does not hold a %1 with an id").arg(type));
        return;
    }
    if (const QString why = readOnlyReason(type, false); !why.isEmpty()) {
        call.respond.error(why);
        return;
    }
    if (const QString why = lockedReason(call, type, id); !why.isEmpty()) {
        call.respond.error(why);
        return;
    }
    pb::DomainObjectWrapper updated = *stored;
    auto *target = const_cast<Message *>(hci::unwrapObject(updated, type));
    for (const auto &name : r.fieldnames()) {
        if (name == "id" || name == "version")
            continue;
        if (!copyField(*changes, target, name)) {
            call.respond.error(QStringLiteral("%1 has no field '%2'").arg(type, QString::fromStdString(name)));
            return;
        }
    }
    if (type == SimZones::kType)
        if (const QString why = SimZones::writeRefusal(m_s.world.store(), id, &updated.noflightzone()); !why.isEmpty()) {
            call.respond.error(why);
            return;
        }
    const auto saved = m_s.world.store().save(type, updated, SimWorld::now());
    if (!saved.object) {
        call.respond.error(saved.error);
        return;
    }
    if (r.acquirelock())
        m_s.world.locks().acquire(type, id, {call.session->clientId, call.session->user->id, call.session->user->login});
    pb::UpdateObjectFieldsResponse response;
    response.set_objecttype(r.objecttype());
    *response.mutable_object() = *saved.object;
    call.respond.reply(response);
}

void SimObjectService::remove(SimCall &call)
{
    const auto &r = static_cast<const pb::DeleteObjectRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    if (type == QLatin1String("Vehicle")) {
        call.respond.error(QStringLiteral("The simulator's vehicles cannot be deleted"));
        return;
    }
    if (const QString why = readOnlyReason(type, false); !why.isEmpty()) {
        call.respond.error(why);
        return;
    }
    if (const QString why = lockedReason(call, type, r.objectid()); !why.isEmpty()) {
        call.respond.error(why);
        return;
    }
    if (type == SimZones::kType)
        if (const QString why = SimZones::writeRefusal(m_s.world.store(), r.objectid(), nullptr); !why.isEmpty()) {
            call.respond.error(why);
            return;
        }
    int version = 0;
    if (!m_s.world.store().remove(type, r.objectid(), &version)) {
        call.respond.error(QStringLiteral("%1 %2 does not exist").arg(type).arg(r.objectid()));
        return;
    }
    m_s.world.locks().release(type, r.objectid(), call.session->clientId, true);
    pb::DeleteObjectResponse response;
    response.set_objecttype(r.objecttype());
    response.set_objectid(r.objectid());
    response.set_objectversion(version);
    call.respond.reply(response);
}

} // namespace sortie::sim
