#include "SimSessionService.h"

#include "HciRequestDispatcher.h"
#include "HciServerConnection.h"
#include "Messages.pb.h"
#include "SimLog.h"
#include "SimSessionTable.h"
#include "SimWorld.h"

namespace sortie::sim {
namespace {

constexpr int kMajor = 2;
constexpr int kMinor = 0;
constexpr int kLicenceConstraint = 1001;

} // namespace

SimSessionService::SimSessionService(SimServices services)
    : m_s(services)
{
}

void SimSessionService::install(HciRequestDispatcher &d)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::AuthorizeHciRequest::default_instance(), A::Anyone, [this](SimCall &c) { authorize(c); });
    d.add(pb::LoginRequest::default_instance(), A::Authorized, [this](SimCall &c) { login(c); });
    d.add(pb::LogoutRequest::default_instance(), A::Authorized, [this](SimCall &c) { logout(c); });
    d.add(pb::SetHciLocaleRequest::default_instance(), A::Authorized, [this](SimCall &c) { setLocale(c); });
}

void SimSessionService::authorize(SimCall &call)
{
    const auto &r = static_cast<const pb::AuthorizeHciRequest &>(call.request);
    if (r.has_clientversion() && r.clientversion().major() != kMajor) {
        pb::ErrorDetailWrapper detail;
        auto *server = detail.mutable_unsupportedprotocolversiondetail()->mutable_serverversion();
        server->set_major(kMajor);
        server->set_minor(kMinor);
        call.respond.error(QStringLiteral("Unsupported protocol version %1.%2").arg(r.clientversion().major()).arg(r.clientversion().minor()),
                           0, false, &detail);
        return;
    }
    SimSession *session = nullptr;
    if (r.clientid() < 0) {
        session = &m_s.sessions.create(&call.connection);
        qCInfo(lcSim) << "new session" << session->clientId << "for" << call.connection.peer();
    } else {
        session = m_s.sessions.attach(r.clientid(), &call.connection);
        if (!session) {
            call.respond.error(QStringLiteral("Session %1 does not exist or has expired").arg(r.clientid()));
            return;
        }
        qCInfo(lcSim) << "session" << session->clientId << "re-attached from" << call.connection.peer();
    }
    // A connection belongs to one session: authorizing again leaves the previous one detached.
    if (call.connection.clientId() >= 0 && call.connection.clientId() != session->clientId)
        if (SimSession *previous = m_s.sessions.find(call.connection.clientId()); previous) {
            previous->connection = nullptr;
            previous->detachedAt = SimWorld::now();
        }
    call.connection.setClientId(session->clientId);
    if (r.has_locale())
        session->locale = QString::fromStdString(r.locale());

    pb::AuthorizeHciResponse response;
    response.set_clientid(session->clientId);
    response.mutable_serverversion()->set_major(kMajor);
    response.mutable_serverversion()->set_minor(kMinor);
    call.respond.reply(response);
}

void SimSessionService::login(SimCall &call)
{
    const auto &r = static_cast<const pb::LoginRequest &>(call.request);
    const auto user = m_s.world.users().authenticate(QString::fromStdString(r.userlogin()), QString::fromStdString(r.userpassword()));
    if (!user) {
        qCInfo(lcSim).noquote() << "login refused for" << QString::fromStdString(r.userlogin());
        call.respond.error(QStringLiteral("Invalid login or password"));
        return;
    }
    const int limit = m_s.world.config().maxSessions;
    if (limit > 0 && !call.session->user && m_s.sessions.loggedInCount() >= limit) {
        pb::ErrorDetailWrapper detail;
        detail.mutable_licenseconstrainterrordetail()->set_licenseconstrainterrorsubtype(pb::LCS_PERMISSION_EXCEEDED);
        detail.mutable_licenseconstrainterrordetail()->set_permission("hciConnectionsLimit");
        call.respond.error(QStringLiteral("License limit reached: hciConnectionsLimit (%1)").arg(limit), kLicenceConstraint,
                           false, &detail);
        return;
    }
    call.session->user = user;
    qCInfo(lcSim).noquote() << "user" << user->login << "logged in, session" << call.session->clientId;
    pb::LoginResponse response;
    auto *u = response.mutable_user();
    u->set_id(user->id);
    u->set_version(1);
    u->set_login(user->login.toStdString());
    u->set_role(user->administrator ? pb::UR_ADMINISTRATOR : pb::UR_OPERATOR);
    call.respond.reply(response);
}

void SimSessionService::logout(SimCall &call)
{
    const int id = call.session->clientId;
    call.connection.setClientId(-1);
    m_s.sessions.remove(id);
    qCInfo(lcSim) << "session" << id << "logged out";
    call.respond.reply(pb::LogoutResponse());
}

void SimSessionService::setLocale(SimCall &call)
{
    const auto &r = static_cast<const pb::SetHciLocaleRequest &>(call.request);
    call.session->locale = QString::fromStdString(r.locale());
    call.respond.reply(pb::SetHciLocaleResponse());
}

} // namespace sortie::sim
