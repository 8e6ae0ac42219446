#include "HciRequestDispatcher.h"

#include "HciMessageTypes.h"
#include "HciServerConnection.h"
#include "Messages.pb.h"
#include "SimLog.h"
#include "SimSessionTable.h"

namespace sortie::sim {
namespace {

QString typeName(int32_t type)
{
    const auto name = hci::HciMessageTypes::name(type);
    return name.empty() ? QStringLiteral("type %1").arg(type) : QString::fromLatin1(name.data(), qsizetype(name.size()));
}

std::optional<int32_t> clientIdOf(const google::protobuf::Message &m)
{
    const auto *f = m.GetDescriptor()->FindFieldByNumber(1);
    if (!f || f->name() != "clientId" || f->cpp_type() != google::protobuf::FieldDescriptor::CPPTYPE_INT32)
        return std::nullopt;
    return m.GetReflection()->GetInt32(m, f);
}

} // namespace

HciRequestDispatcher::HciRequestDispatcher(SimSessionTable &sessions)
    : m_sessions(sessions)
{
}

void HciRequestDispatcher::add(const google::protobuf::Message &prototype, Access access, Handler handler)
{
    const auto type = hci::HciMessageTypes::number(prototype.GetDescriptor());
    Q_ASSERT(type);
    m_handlers.insert(*type, {access, std::move(handler)});
}

void HciRequestDispatcher::dispatch(HciServerConnection &connection, const hci::HciFrame &frame)
{
    const int32_t type = frame.header.type;
    SimResponder respond(&connection, frame.header.instanceId, type);
    const auto it = m_handlers.constFind(type);
    if (it == m_handlers.cend()) {
        const QString name = typeName(type);
        qCInfo(lcSim).noquote() << "not implemented:" << name;
        respond.error(name.endsWith(QLatin1String("Request"))
                          ? QStringLiteral("The Sortie simulator does not implement %1 (type %2)").arg(name).arg(type)
                          : QStringLiteral("%1 (type %2) is not a request").arg(name).arg(type));
        return;
    }
    SimSession *session = connection.clientId() >= 0 ? m_sessions.find(connection.clientId()) : nullptr;
    if (it->access != Access::Anyone) {
        if (!session) {
            respond.error(QStringLiteral("%1 needs a session: send AuthorizeHciRequest first").arg(typeName(type)));
            return;
        }
        const auto clientId = clientIdOf(*frame.message);
        if (clientId && *clientId != session->clientId) {
            respond.error(QStringLiteral("clientId %1 is not this connection's session (%2)").arg(*clientId).arg(session->clientId));
            return;
        }
        if (it->access == Access::LoggedIn && !session->user) {
            respond.error(QStringLiteral("%1 needs a logged-in user: send LoginRequest first").arg(typeName(type)));
            return;
        }
    }
    SimCall call{connection, session, *frame.message, respond};
    it->handler(call);
}

void HciRequestDispatcher::rejectDropped(HciServerConnection &connection, const hci::HciDroppedFrame &dropped)
{
    qCInfo(lcSim).noquote() << "dropped a frame from" << connection.peer() << "-" << hci::toString(dropped.reason)
                            << QString::fromStdString(dropped.detail);
    switch (dropped.reason) {
    case hci::HciDropReason::UnknownType:
    case hci::HciDropReason::InvalidPayload:
    case hci::HciDropReason::MissingRequired:
    case hci::HciDropReason::TooLarge:
        // The header is sound, so the sender is waiting on that instance id: tell it why, not silence.
        SimResponder(&connection, dropped.header.instanceId, dropped.header.type)
            .error(QStringLiteral("Request dropped: %1 (%2)")
                       .arg(QString::fromLatin1(hci::toString(dropped.reason)), QString::fromStdString(dropped.detail)));
        break;
    default:
        break;
    }
}

} // namespace sortie::sim
