#include "SimEventService.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimNotifier.h"
#include "SimSessionTable.h"
#include "SimWorld.h"

namespace sortie::sim {

SimEventService::SimEventService(SimServices services)
    : m_s(services)
{
}

void SimEventService::install(HciRequestDispatcher &d)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::SubscribeEventRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { subscribe(c); });
    d.add(pb::UnsubscribeEventRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { unsubscribe(c); });
}

void SimEventService::subscribe(SimCall &call)
{
    const auto &r = static_cast<const pb::SubscribeEventRequest &>(call.request);
    const auto &wrapper = r.subscription();
    std::vector<const google::protobuf::FieldDescriptor *> set;
    wrapper.GetReflection()->ListFields(wrapper, &set);
    if (set.size() != 1) {
        call.respond.error(QStringLiteral("A subscription must name exactly one kind of event (this one names %1)").arg(set.size()));
        return;
    }
    if (!wrapper.has_telemetrysubscription() && !wrapper.has_objectmodificationsubscription() && !wrapper.has_locksubscription()
        && !wrapper.has_commandsubscription() && !wrapper.has_environmentsubscription()) {
        call.respond.error(QStringLiteral("The Sortie simulator does not implement %1").arg(QString::fromStdString(set[0]->name())));
        return;
    }
    if (wrapper.has_commandsubscription() && !m_s.world.vehicle(wrapper.commandsubscription().vehicle().id())) {
        call.respond.error(QStringLiteral("Vehicle %1 does not exist").arg(wrapper.commandsubscription().vehicle().id()));
        return;
    }
    const int id = m_s.sessions.nextSubscriptionId();
    call.session->subscriptions[id] = std::make_shared<pb::EventSubscriptionWrapper>(wrapper);
    pb::SubscribeEventResponse response;
    response.set_subscriptionid(id);
    call.respond.reply(response);
    m_s.notifier.greet(*call.session, id); // after the answer, so the client knows the id it carries
}

void SimEventService::unsubscribe(SimCall &call)
{
    const auto &r = static_cast<const pb::UnsubscribeEventRequest &>(call.request);
    if (!call.session->subscriptions.erase(r.subscriptionid())) {
        call.respond.error(QStringLiteral("Session %1 has no subscription %2").arg(call.session->clientId).arg(r.subscriptionid()));
        return;
    }
    call.respond.reply(pb::UnsubscribeEventResponse());
}

} // namespace sortie::sim
