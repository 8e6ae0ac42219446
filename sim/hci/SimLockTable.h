#pragma once

#include "HciError.h"

#include <QHash>
#include <QObject>
#include <QString>

#include <optional>

namespace sortie::sim {

// Object locks, keyed by (object type, id), each owned by one session. A second session is refused a
// held lock; a session's locks go when it logs out or expires.
class SimLockTable : public QObject
{
    Q_OBJECT

public:
    struct Owner
    {
        int clientId = -1;
        int userId = 0;
        QString login;
    };

    explicit SimLockTable(QObject *parent = nullptr);

    // No error on success (also when this session already holds it), else a server error saying why
    // not: what the simulator answers with, and what the client's HciLock sees refused.
    hci::HciError acquire(const QString &type, int id, const Owner &owner);
    // ifExclusive: release only when this session holds the lock, and succeed quietly otherwise.
    // Without it, releasing another session's lock is refused.
    hci::HciError release(const QString &type, int id, int clientId, bool ifExclusive);
    std::optional<Owner> holder(const QString &type, int id) const;
    // True when the object is free or held by this session.
    bool mayModify(const QString &type, int id, int clientId) const;
    void releaseAll(int clientId);
    int count() const { return int(m_locks.size()); }

signals:
    // A lock was taken (held) or released (!held).
    void lockChanged(const QString &type, int id, bool held);

private:
    using Key = QPair<QString, int>;
    QHash<Key, Owner> m_locks;
};

} // namespace sortie::sim
