#include "SimLockService.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimSessionTable.h"
#include "SimWorld.h"

namespace sortie::sim {
namespace {

void describe(const QString &type, int id, const SimLockTable::Owner &owner, pb::Lock *lock)
{
    lock->set_objecttype(type.toStdString());
    lock->set_objectid(id);
    lock->mutable_owner()->set_id(owner.userId);
    lock->mutable_owner()->set_login(owner.login.toStdString());
}

} // namespace

SimLockService::SimLockService(SimServices services)
    : m_s(services)
{
}

void SimLockService::install(HciRequestDispatcher &d)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::AcquireLockRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { acquire(c); });
    d.add(pb::ReleaseLockRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { release(c); });
    d.add(pb::CheckLockRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { check(c); });
    d.add(pb::CheckMultipleLocksRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { checkMultiple(c); });
}

void SimLockService::acquire(SimCall &call)
{
    const auto &r = static_cast<const pb::AcquireLockRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    if (!m_s.world.store().find(type, r.objectid())) {
        call.respond.error(QStringLiteral("%1 %2 does not exist").arg(type).arg(r.objectid()));
        return;
    }
    const auto &user = *call.session->user;
    if (const hci::HciError refused = m_s.world.locks().acquire(type, r.objectid(), {call.session->clientId, user.id, user.login})) {
        call.respond.error(refused.message());
        return;
    }
    call.respond.reply(pb::AcquireLockResponse());
}

void SimLockService::release(SimCall &call)
{
    const auto &r = static_cast<const pb::ReleaseLockRequest &>(call.request);
    if (const hci::HciError refused = m_s.world.locks().release(QString::fromStdString(r.objecttype()), r.objectid(),
                                                                call.session->clientId, r.ifexclusive())) {
        call.respond.error(refused.message());
        return;
    }
    call.respond.reply(pb::ReleaseLockResponse());
}

void SimLockService::check(SimCall &call)
{
    const auto &r = static_cast<const pb::CheckLockRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    pb::CheckLockResponse response;
    response.set_objecttype(r.objecttype());
    response.set_objectid(r.objectid());
    if (const auto owner = m_s.world.locks().holder(type, r.objectid()))
        describe(type, r.objectid(), *owner, response.mutable_lock());
    call.respond.reply(response);
}

void SimLockService::checkMultiple(SimCall &call)
{
    const auto &r = static_cast<const pb::CheckMultipleLocksRequest &>(call.request);
    const QString type = QString::fromStdString(r.objecttype());
    pb::CheckMultipleLocksResponse response;
    response.set_objecttype(r.objecttype());
    for (int id : r.objectids()) {
        if (const auto owner = m_s.world.locks().holder(type, id)) {
            response.add_objectids(id);
            describe(type, id, *owner, response.add_locks());
        }
    }
    call.respond.reply(response);
}

} // namespace sortie::sim
