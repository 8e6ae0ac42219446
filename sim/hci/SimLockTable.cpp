#include "SimLockTable.h"

namespace sortie::sim {

namespace {
hci::HciError refusal(const QString &why)
{
    return hci::HciError(hci::HciError::Kind::Server, why);
}
} // namespace

SimLockTable::SimLockTable(QObject *parent)
    : QObject(parent)
{
}

hci::HciError SimLockTable::acquire(const QString &type, int id, const Owner &owner)
{
    const Key key(type, id);
    if (const auto it = m_locks.constFind(key); it != m_locks.cend()) {
        if (it->clientId == owner.clientId)
            return {};
        return refusal(QStringLiteral("%1 %2 is locked by user '%3' in another session").arg(type).arg(id).arg(it->login));
    }
    m_locks.insert(key, owner);
    emit lockChanged(type, id, true);
    return {};
}

hci::HciError SimLockTable::release(const QString &type, int id, int clientId, bool ifExclusive)
{
    const Key key(type, id);
    const auto it = m_locks.constFind(key);
    if (it == m_locks.cend())
        return {};
    if (it->clientId != clientId) {
        if (ifExclusive)
            return {};
        return refusal(QStringLiteral("%1 %2 is locked by user '%3' in another session; only they can release it")
                           .arg(type).arg(id).arg(it->login));
    }
    m_locks.remove(key);
    emit lockChanged(type, id, false);
    return {};
}

std::optional<SimLockTable::Owner> SimLockTable::holder(const QString &type, int id) const
{
    const auto it = m_locks.constFind(Key(type, id));
    if (it == m_locks.cend())
        return std::nullopt;
    return *it;
}

bool SimLockTable::mayModify(const QString &type, int id, int clientId) const
{
    const auto owner = holder(type, id);
    return !owner || owner->clientId == clientId;
}

void SimLockTable::releaseAll(int clientId)
{
    QList<Key> released;
    for (auto it = m_locks.begin(); it != m_locks.end();) {
        if (it->clientId == clientId) {
            released.append(it.key());
            it = m_locks.erase(it);
        } else {
            ++it;
        }
    }
    for (const Key &key : released)
        emit lockChanged(key.first, key.second, false);
}

} // namespace sortie::sim
