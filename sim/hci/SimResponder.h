#pragma once

#include <QPointer>
#include <QString>

namespace google::protobuf {
class Message;
} // namespace google::protobuf

namespace com::ugcs::ucs::proto {
class ErrorDetailWrapper;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

class HciServerConnection;

// Answers one request, now or later (a handler may keep a copy for a long operation). Does nothing
// once the connection is gone.
class SimResponder
{
public:
    SimResponder(HciServerConnection *connection, int32_t instanceId, int32_t requestType);

    void reply(const google::protobuf::Message &answer) const;
    void error(const QString &message, int code = 0, bool suppressible = false,
               const com::ugcs::ucs::proto::ErrorDetailWrapper *detail = nullptr) const;
    void progress(const QString &title, int value, int maximum) const;
    bool connected() const;
    int32_t instanceId() const { return m_instanceId; }

private:
    QPointer<HciServerConnection> m_connection;
    int32_t m_instanceId;
    int32_t m_requestType;
};

} // namespace sortie::sim
