#pragma once

#include "HciFrame.h"
#include "SimResponder.h"

#include <QHash>

#include <functional>

namespace sortie::sim {

class HciServerConnection;
class SimSessionTable;
struct SimSession;

// One request as a handler sees it: the decoded message, the caller's session (null before
// AuthorizeHci), and the way to answer.
struct SimCall
{
    HciServerConnection &connection;
    SimSession *session;
    const google::protobuf::Message &request;
    SimResponder respond;
};

// Routes decoded requests to their handlers by type number, after checking what each needs: an
// authorized session with a matching clientId, or a logged-in user. Every request gets an answer:
// one no handler serves gets an Error that names it, and so does a frame the codec had to drop when
// it still carries an instance id (the SDK's server stays silent there; a named error is kinder).
class HciRequestDispatcher
{
public:
    enum class Access { Anyone, Authorized, LoggedIn };
    using Handler = std::function<void(SimCall &)>;

    explicit HciRequestDispatcher(SimSessionTable &sessions);

    // Serves requests of the prototype's type (e.g. pb::LoginRequest::default_instance()).
    void add(const google::protobuf::Message &prototype, Access access, Handler handler);
    void dispatch(HciServerConnection &connection, const hci::HciFrame &frame);
    void rejectDropped(HciServerConnection &connection, const hci::HciDroppedFrame &dropped);

private:
    struct Entry
    {
        Access access;
        Handler handler;
    };
    SimSessionTable &m_sessions;
    QHash<int32_t, Entry> m_handlers;
};

} // namespace sortie::sim
