#include "SimObjectStore.h"

#include "HciObjectType.h"
#include "Messages.pb.h"

#include <QUuid>

namespace sortie::sim {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;

void setInt32(Message &m, const char *name, int32_t value)
{
    if (const auto *f = m.GetDescriptor()->FindFieldByName(name); f && f->cpp_type() == FieldDescriptor::CPPTYPE_INT32)
        m.GetReflection()->SetInt32(&m, f, value);
}

int32_t getInt32(const Message &m, const char *name, int32_t fallback)
{
    const auto *f = m.GetDescriptor()->FindFieldByName(name);
    if (!f || f->cpp_type() != FieldDescriptor::CPPTYPE_INT32 || !m.GetReflection()->HasField(m, f))
        return fallback;
    return m.GetReflection()->GetInt32(m, f);
}

std::string newUuid()
{
    return QUuid::createUuid().toString(QUuid::WithoutBraces).toStdString();
}

Message *mutableObject(pb::DomainObjectWrapper &wrapper, const QString &type)
{
    const auto *object = hci::unwrapObject(wrapper, type);
    return const_cast<Message *>(object); // the wrapper is ours and mutable; unwrapObject only looks
}

} // namespace

SimObjectStore::SimObjectStore(QObject *parent)
    : QObject(parent)
{
}

SimObjectStore::~SimObjectStore() = default;

const pb::DomainObjectWrapper *SimObjectStore::find(const QString &type, int id) const
{
    const auto t = m_objects.find(type);
    if (t == m_objects.end())
        return nullptr;
    const auto o = t->second.find(id);
    return o == t->second.end() ? nullptr : o->second.get();
}

std::vector<const pb::DomainObjectWrapper *> SimObjectStore::list(const QString &type) const
{
    std::vector<const pb::DomainObjectWrapper *> out;
    if (const auto t = m_objects.find(type); t != m_objects.end())
        for (const auto &[id, object] : t->second)
            out.push_back(object.get());
    return out;
}

QStringList SimObjectStore::types() const
{
    QStringList out;
    for (const auto &[type, objects] : m_objects)
        if (!objects.empty())
            out.append(type);
    return out;
}

int SimObjectStore::count() const
{
    int n = 0;
    for (const auto &[type, objects] : m_objects)
        n += int(objects.size());
    return n;
}

void SimObjectStore::insert(const QString &type, const pb::DomainObjectWrapper &wrapper)
{
    const auto *object = hci::unwrapObject(wrapper, type);
    const int id = object ? hci::objectId(*object) : -1;
    if (id < 0)
        return;
    m_objects[type][id] = std::make_shared<pb::DomainObjectWrapper>(wrapper);
    m_nextId = std::max(m_nextId, id + 1);
}

SimObjectStore::SaveResult SimObjectStore::save(const QString &type, const pb::DomainObjectWrapper &wrapper, qint64 nowMs)
{
    SaveResult result;
    auto stored = std::make_shared<pb::DomainObjectWrapper>(wrapper);
    Message *object = mutableObject(*stored, type);
    if (!object) {
        result.error = QStringLiteral("The request's object does not hold a %1").arg(type);
        return result;
    }
    int id = hci::objectId(*object);
    const pb::DomainObjectWrapper *existing = id >= 0 ? find(type, id) : nullptr;
    if (id >= 0 && !existing) {
        result.error = QStringLiteral("%1 %2 does not exist (deleted by another operator?)").arg(type).arg(id);
        return result;
    }
    int version = 1;
    if (existing) {
        const int storedVersion = getInt32(*hci::unwrapObject(*existing, type), "version", 0);
        const int theirs = getInt32(*object, "version", storedVersion);
        if (theirs != storedVersion) {
            result.error = QStringLiteral("%1 %2 was changed by someone else (server version %3, yours %4): reload it first")
                               .arg(type).arg(id).arg(storedVersion).arg(theirs);
            return result;
        }
        version = storedVersion + 1;
    } else {
        id = allocateId();
        result.created = true;
    }
    setInt32(*object, "id", id);
    setInt32(*object, "version", version);
    completeComposites(type, *object, result.created, nowMs);
    m_objects[type][id] = stored;
    result.object = stored;
    emit changed(result.created ? pb::MT_CREATE : pb::MT_UPDATE, type, id, *stored);
    return result;
}

// Gives new parts of a route or mission what the server would: ids, versions, uuids and times.
void SimObjectStore::completeComposites(const QString &type, Message &object, bool created, qint64 nowMs)
{
    if (auto *route = dynamic_cast<pb::Route *>(&object)) {
        if (route->uuid().empty())
            route->set_uuid(newUuid());
        route->set_modificationuuid(newUuid());
        if (created || !route->has_creationtime())
            route->set_creationtime(nowMs);
        route->set_lastmodificationtime(nowMs);
        for (auto &segment : *route->mutable_segments()) {
            if (!segment.has_id()) {
                segment.set_id(allocateId());
                segment.set_version(1);
            }
            if (segment.uuid().empty())
                segment.set_uuid(newUuid());
            segment.set_modificationuuid(newUuid());
            for (auto &action : *segment.mutable_actiondefinitions()) {
                if (!action.has_id()) {
                    action.set_id(allocateId());
                    action.set_version(1);
                }
                if (action.uuid().empty())
                    action.set_uuid(newUuid());
            }
        }
        for (auto &failsafe : *route->mutable_failsafes()) {
            if (!failsafe.has_id()) {
                failsafe.set_id(allocateId());
                failsafe.set_version(1);
            }
        }
    } else if (auto *mission = dynamic_cast<pb::Mission *>(&object)) {
        if (mission->uuid().empty())
            mission->set_uuid(newUuid());
        if (created || !mission->has_creationtime())
            mission->set_creationtime(nowMs);
    }
    Q_UNUSED(type)
}

bool SimObjectStore::remove(const QString &type, int id, int *version)
{
    const auto t = m_objects.find(type);
    if (t == m_objects.end())
        return false;
    const auto o = t->second.find(id);
    if (o == t->second.end())
        return false;
    if (version)
        *version = getInt32(*hci::unwrapObject(*o->second, type), "version", 0);
    t->second.erase(o);
    emit changed(pb::MT_DELETE, type, id, pb::DomainObjectWrapper::default_instance());
    return true;
}

} // namespace sortie::sim
