#include "HciSubscription.h"

#include "Messages.pb.h"

namespace sortie::hci {

HciSubscription::HciSubscription(const pb::EventSubscriptionWrapper &request, QObject *parent)
    : QObject(parent)
    , m_request(std::make_unique<pb::EventSubscriptionWrapper>(request))
{
}

HciSubscription::~HciSubscription() = default;

void HciSubscription::setServerId(int32_t id)
{
    const bool wasActive = isActive();
    m_serverId = id;
    if (id >= 0)
        m_lastError = {};
    if (wasActive != isActive())
        emit activeChanged(isActive());
}

void HciSubscription::setFailed(const HciError &error)
{
    m_lastError = error;
    setServerId(-1);
    emit failed(error);
}

void HciSubscription::deliver(const pb::Notification &notification)
{
    ++m_events;
    emit received(notification.event());
}

} // namespace sortie::hci
