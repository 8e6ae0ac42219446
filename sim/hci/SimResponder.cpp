#include "SimResponder.h"

#include "HciServerConnection.h"
#include "Messages.pb.h"

namespace sortie::sim {

SimResponder::SimResponder(HciServerConnection *connection, int32_t instanceId, int32_t requestType)
    : m_connection(connection)
    , m_instanceId(instanceId)
    , m_requestType(requestType)
{
}

bool SimResponder::connected() const
{
    return m_connection && m_connection->isOpen();
}

void SimResponder::reply(const google::protobuf::Message &answer) const
{
    if (m_connection)
        m_connection->sendAnswer(m_instanceId, m_requestType, answer);
}

void SimResponder::error(const QString &message, int code, bool suppressible, const pb::ErrorDetailWrapper *detail) const
{
    pb::Error e;
    e.set_errormessage(message.toStdString());
    if (code)
        e.set_errorcode(code);
    if (suppressible)
        e.set_issuppressible(true);
    if (detail)
        *e.mutable_errordetail() = *detail;
    reply(e);
}

void SimResponder::progress(const QString &title, int value, int maximum) const
{
    if (!m_connection)
        return;
    pb::OperationStatus status;
    auto *p = status.add_progressstack();
    p->set_title(title.toStdString());
    p->set_progress(value);
    p->set_maxprogress(maximum);
    m_connection->sendProgress(m_instanceId, status);
}

} // namespace sortie::sim
