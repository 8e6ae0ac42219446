#pragma once

#include "HciError.h"

#include <QObject>

#include <memory>

namespace sortie::hci {

// One event subscription (telemetry, object changes, locks, commands...). The session owns it and keeps
// it across reconnects: the server gives it a new id each time, which this object hides. Events arrive
// through received() synchronously, as the frame is decoded: copy what you keep.
class HciSubscription : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool active READ isActive NOTIFY activeChanged)

public:
    ~HciSubscription() override;

    // What was asked for: an EventSubscriptionWrapper with exactly one member set.
    const pb::EventSubscriptionWrapper &request() const { return *m_request; }
    // The id the server gave it on the current connection, or -1 while it is not established.
    int32_t serverId() const { return m_serverId; }
    bool isActive() const { return m_serverId >= 0; }
    const HciError &lastError() const { return m_lastError; }
    quint64 eventsReceived() const { return m_events; }

signals:
    void received(const pb::EventWrapper &event);
    void activeChanged(bool active);
    // The server refused the subscription; the session tries again after the next reconnect.
    void failed(const sortie::hci::HciError &error);

private:
    friend class HciConnection;
    friend class HciSession;
    HciSubscription(const pb::EventSubscriptionWrapper &request, QObject *parent);

    void setServerId(int32_t id);
    void setFailed(const HciError &error);
    void deliver(const pb::Notification &notification);

    std::unique_ptr<pb::EventSubscriptionWrapper> m_request;
    int32_t m_serverId = -1;
    HciError m_lastError;
    quint64 m_events = 0;
};

} // namespace sortie::hci
