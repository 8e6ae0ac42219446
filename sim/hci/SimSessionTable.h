#pragma once

#include "SimUsers.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>

namespace com::ugcs::ucs::proto {
class EventSubscriptionWrapper;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class HciServerConnection;

// One client session on the simulated server. It outlives its connection: a client that reconnects
// re-attaches by clientId and finds its login, subscriptions and locks, until the session expires.
struct SimSession
{
    int clientId = -1;
    std::optional<SimUser> user; // set by a successful login
    QString locale;
    QPointer<HciServerConnection> connection;
    qint64 detachedAt = 0; // ms since the epoch; 0 while a connection is attached
    std::map<int, std::shared_ptr<pb::EventSubscriptionWrapper>> subscriptions; // by subscription id
};

class SimSessionTable : public QObject
{
    Q_OBJECT

public:
    explicit SimSessionTable(QObject *parent = nullptr);

    SimSession &create(HciServerConnection *connection);
    // Re-attaches a live session to a connection; nullptr when it does not exist (or expired).
    SimSession *attach(int clientId, HciServerConnection *connection);
    void detach(HciServerConnection *connection);
    SimSession *find(int clientId);
    void remove(int clientId);
    // Ends every session detached for longer than the expiry (all detached ones with force).
    int expire(bool force = false);
    int loggedInCount() const;
    int size() const { return int(m_sessions.size()); }
    int nextSubscriptionId() { return m_nextSubscriptionId++; }
    std::map<int, SimSession> &all() { return m_sessions; }

    void setExpiry(int ms) { m_expiryMs = ms; }
    int expiry() const { return m_expiryMs; }

signals:
    // A session ended (logout or expiry): its locks go with it.
    void sessionEnded(int clientId);

private:
    std::map<int, SimSession> m_sessions;
    int m_nextClientId = 1;
    int m_nextSubscriptionId = 100;
    int m_expiryMs = 60000;
    QTimer m_sweep;
};

} // namespace sortie::sim
