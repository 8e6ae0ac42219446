#include "SimSessionTable.h"

#include "HciServerConnection.h"
#include "Messages.pb.h"
#include "SimLog.h"
#include "SimWorld.h"

namespace sortie::sim {

SimSessionTable::SimSessionTable(QObject *parent)
    : QObject(parent)
{
    m_sweep.setInterval(1000);
    connect(&m_sweep, &QTimer::timeout, this, [this] { expire(); });
    m_sweep.start();
}

SimSession &SimSessionTable::create(HciServerConnection *connection)
{
    const int id = m_nextClientId++;
    SimSession &s = m_sessions[id];
    s.clientId = id;
    s.connection = connection;
    return s;
}

SimSession *SimSessionTable::attach(int clientId, HciServerConnection *connection)
{
    SimSession *s = find(clientId);
    if (!s)
        return nullptr;
    if (s->connection && s->connection != connection)
        s->connection->setClientId(-1); // the session moves to the newer connection
    s->connection = connection;
    s->detachedAt = 0;
    return s;
}

void SimSessionTable::detach(HciServerConnection *connection)
{
    for (auto &[id, s] : m_sessions) {
        if (s.connection == connection || (!s.connection && s.detachedAt == 0)) {
            s.connection = nullptr;
            s.detachedAt = SimWorld::now();
        }
    }
}

SimSession *SimSessionTable::find(int clientId)
{
    const auto it = m_sessions.find(clientId);
    return it == m_sessions.end() ? nullptr : &it->second;
}

void SimSessionTable::remove(int clientId)
{
    if (m_sessions.erase(clientId))
        emit sessionEnded(clientId);
}

int SimSessionTable::expire(bool force)
{
    const qint64 now = SimWorld::now();
    QList<int> ended;
    for (const auto &[id, s] : m_sessions)
        if (!s.connection && s.detachedAt > 0 && (force || now - s.detachedAt >= m_expiryMs))
            ended.append(id);
    for (int id : ended) {
        qCInfo(lcSim) << "session" << id << "expired";
        remove(id);
    }
    return int(ended.size());
}

int SimSessionTable::loggedInCount() const
{
    int n = 0;
    for (const auto &[id, s] : m_sessions)
        if (s.user)
            ++n;
    return n;
}

} // namespace sortie::sim
