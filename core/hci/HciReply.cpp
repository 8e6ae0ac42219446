#include "HciReply.h"

#include "HciMessageTypes.h"

#include <google/protobuf/message.h>

namespace sortie::hci {

HciReply::HciReply(int32_t instanceId, int32_t requestType, QObject *parent)
    : QObject(parent)
    , m_instanceId(instanceId)
    , m_requestType(requestType)
{
    m_timeout.setSingleShot(true);
}

HciReply::~HciReply() = default;

QString HciReply::requestName() const
{
    const auto name = HciMessageTypes::name(m_requestType);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

std::unique_ptr<google::protobuf::Message> HciReply::takeResponse()
{
    return std::move(m_response);
}

void HciReply::succeed(std::unique_ptr<google::protobuf::Message> response)
{
    if (m_finished)
        return;
    m_response = std::move(response);
    emitFinished();
}

void HciReply::fail(const HciError &error)
{
    if (m_finished)
        return;
    m_error = error;
    emitFinished();
}

void HciReply::failLater(const HciError &error)
{
    QMetaObject::invokeMethod(this, [this, error] { fail(error); }, Qt::QueuedConnection);
}

void HciReply::emitFinished()
{
    m_finished = true;
    m_timeout.stop();
    emit finished();
    if (m_autoDelete)
        deleteLater();
}

} // namespace sortie::hci
