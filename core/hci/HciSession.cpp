#include "HciSession.h"

#include "HciConnection.h"
#include "HciLog.h"
#include "HciReply.h"
#include "HciSubscription.h"
#include "Messages.pb.h"

#include <QLocale>
#include <QCoreApplication>

namespace sortie::hci {
namespace {

constexpr int32_t kProtocolMajor = 2;
constexpr int32_t kProtocolMinor = 0;
constexpr std::chrono::milliseconds kLogoutTimeout{5000};

// Sets the required `clientId` (field 1) that nearly every HCI request carries.
void stampClientId(google::protobuf::Message &message, int32_t clientId)
{
    const auto *field = message.GetDescriptor()->FindFieldByNumber(1);
    if (field && field->name() == "clientId" && field->cpp_type() == google::protobuf::FieldDescriptor::CPPTYPE_INT32
        && !field->is_repeated())
        message.GetReflection()->SetInt32(&message, field, clientId);
}

} // namespace

HciSession::HciSession(QObject *parent)
    : QObject(parent)
    , m_connection(new HciConnection(this))
    , m_locale(QLocale::system().name().replace(u'_', u'-'))
    , m_user(std::make_unique<pb::User>())
{
    m_reconnectTimer.setSingleShot(true);
    connect(&m_reconnectTimer, &QTimer::timeout, this, [this] { m_connection->connectToServer(m_host, m_port); });
    connect(m_connection, &HciConnection::connected, this, &HciSession::onConnected);
    connect(m_connection, &HciConnection::disconnected, this, &HciSession::onDisconnected);
}

HciSession::~HciSession()
{
    m_connection->disconnect(this);
    for (HciSubscription *s : std::as_const(m_order))
        s->disconnect(this);
}

void HciSession::open(const QString &host, quint16 port, const QString &login, const QString &password, const tls::TlsOptions &tls)
{
    m_reconnectTimer.stop();
    m_handshake = nullptr;
    if (m_connection->state() != HciConnection::State::Unconnected) {
        setState(State::Disconnected); // so the close below is not taken for a drop
        m_connection->disconnectFromServer();
    }
    forgetServerIds();
    m_host = host;
    m_port = port;
    m_login = login;
    m_password = password;
    m_reattachId = -1;
    m_reconnecting = false;
    m_closing = false;
    m_lastError = {};
    m_backoff.reset();
    setClientId(-1);
    m_connection->setTls(tls);
    qCInfo(lcHci).noquote() << "opening session on" << host + u':' + QString::number(port) << "as" << login << (tls.enabled ? "over TLS" : "");
    setState(State::Connecting);
    m_connection->connectToServer(host, port);
}

void HciSession::close()
{
    m_reconnectTimer.stop();
    if (m_state == State::Disconnected || m_closing)
        return;
    if (m_state != State::Ready) {
        finishClose();
        return;
    }
    m_closing = true;
    pb::LogoutRequest logout; // the SDK forgets clientId here; we do not
    logout.set_clientid(m_clientId);
    HciReply *reply = sendRaw(logout, kLogoutTimeout);
    connect(reply, &HciReply::finished, this, [this, reply] {
        if (!reply->isOk())
            qCInfo(lcHci).noquote() << "logout not confirmed:" << reply->error().message();
        if (m_closing)
            finishClose();
    });
}

void HciSession::finishClose()
{
    m_closing = false;
    m_reconnecting = false;
    m_reattachId = -1;
    m_handshake = nullptr;
    m_password.clear();
    forgetServerIds();
    setState(State::Disconnected);
    setClientId(-1);
    m_connection->disconnectFromServer();
    qCInfo(lcHci) << "session closed";
}

// Server subscription ids belong to one connection's session: without it they mean nothing.
void HciSession::forgetServerIds()
{
    for (auto it = m_subscriptions.begin(); it != m_subscriptions.end(); ++it) {
        it.value() = -1;
        it.key()->setServerId(-1);
    }
}

void HciSession::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void HciSession::setClientId(int32_t id)
{
    if (m_clientId == id)
        return;
    m_clientId = id;
    emit clientIdChanged(id);
}

void HciSession::setRequestTimeout(std::chrono::milliseconds timeout)
{
    m_connection->setDefaultTimeout(timeout);
}

void HciSession::setConnectTimeout(std::chrono::milliseconds timeout)
{
    m_connection->setConnectTimeout(timeout);
}

HciReply *HciSession::sendRaw(const google::protobuf::Message &request, std::chrono::milliseconds timeout)
{
    return m_connection->send(request, timeout);
}

HciReply *HciSession::failedReply(const google::protobuf::Message &request, const HciError &error)
{
    const auto *descriptor = request.GetDescriptor();
    auto *reply = new HciReply(-1, -1, m_connection);
    reply->failLater(HciError(error.kind(), QString::fromStdString(descriptor->name()) + QCoreApplication::translate("HciSession", " not sent: ")
                                                + error.message()));
    return reply;
}

HciReply *HciSession::send(const google::protobuf::Message &request, std::chrono::milliseconds timeout)
{
    if (m_state != State::Ready) {
        const QString why = m_state == State::Reconnecting
            ? QCoreApplication::translate("HciSession", "the connection to the server is being re-established")
            : QCoreApplication::translate("HciSession", "not logged in to a server");
        return failedReply(request, {HciError::Kind::Disconnected, why});
    }
    std::unique_ptr<google::protobuf::Message> stamped(request.New());
    stamped->CopyFrom(request);
    stampClientId(*stamped, m_clientId);
    HciReply *reply = m_connection->send(*stamped, timeout);
    watchForSilence(reply);
    return reply;
}

// A request that timed out while nothing at all came from the server (no answer, no telemetry, no
// progress) means the link is dead, not the server slow: TCP may not notice for hours. Drop the
// connection so the session reconnects (and re-attaches) as soon as the link carries data again.
void HciSession::watchForSilence(HciReply *reply)
{
    const quint64 bytesAtSend = m_connection->bytesReceived();
    connect(reply, &HciReply::finished, this, [this, reply, bytesAtSend] {
        if (reply->error().kind() != HciError::Kind::Timeout || m_state != State::Ready
            || m_connection->bytesReceived() != bytesAtSend)
            return;
        qCWarning(lcHci).noquote() << "nothing from the server since" << reply->requestName() << "was sent; the link seems dead";
        m_connection->drop({HciError::Kind::Disconnected,
                            QCoreApplication::translate("HciSession", "The server sent nothing while %1 waited (%2); the link seems dead")
                                .arg(reply->requestName(), reply->error().message())});
    });
}

void HciSession::onConnected()
{
    if (!m_reconnecting)
        setState(State::Authorizing);
    authorize(m_reattachId);
}

void HciSession::authorize(int32_t clientId)
{
    pb::AuthorizeHciRequest request;
    request.set_clientid(clientId);
    if (!m_locale.isEmpty())
        request.set_locale(m_locale.toStdString());
    request.mutable_clientversion()->set_major(kProtocolMajor);
    request.mutable_clientversion()->set_minor(kProtocolMinor);
    HciReply *reply = sendRaw(request);
    m_handshake = reply;
    connect(reply, &HciReply::finished, this, [this, reply, clientId] {
        if (m_handshake != reply)
            return; // an attempt that was abandoned
        if (!reply->isOk()) {
            if (clientId >= 0 && reply->error().kind() == HciError::Kind::Server) {
                qCInfo(lcHci).noquote() << "the server would not re-attach session" << clientId << "("
                                        << reply->error().message() << "); starting a new session";
                m_reattachId = -1;
                authorize(-1);
                return;
            }
            handshakeFailed(reply->error());
            return;
        }
        const auto &response = reply->response<pb::AuthorizeHciResponse>();
        if (response.has_serverversion() && response.serverversion().major() != kProtocolMajor) {
            handshakeFailed({HciError::Kind::Version, QCoreApplication::translate("HciSession", "The server speaks HCI protocol %1.%2; Sortie speaks %3.%4")
                                                          .arg(response.serverversion().major())
                                                          .arg(response.serverversion().minor())
                                                          .arg(kProtocolMajor)
                                                          .arg(kProtocolMinor)});
            return;
        }
        const bool reattached = clientId >= 0 && response.clientid() == clientId;
        setClientId(response.clientid());
        if (reattached) {
            qCInfo(lcHci) << "re-attached to session" << clientId;
            becomeReady(true);
        } else {
            logIn();
        }
    });
}

void HciSession::logIn()
{
    if (!m_reconnecting)
        setState(State::LoggingIn);
    pb::LoginRequest request;
    request.set_clientid(m_clientId);
    request.set_userlogin(m_login.toStdString());
    request.set_userpassword(m_password.toStdString());
    HciReply *reply = sendRaw(request);
    m_handshake = reply;
    connect(reply, &HciReply::finished, this, [this, reply] {
        if (m_handshake != reply)
            return;
        if (!reply->isOk()) {
            const HciError &e = reply->error();
            if (e.kind() == HciError::Kind::Server)
                handshakeFailed(e.as(HciError::Kind::Authentication,
                                     QCoreApplication::translate("HciSession", "The server rejected the login '%1': %2").arg(m_login, e.message())));
            else
                handshakeFailed(e);
            return;
        }
        *m_user = reply->response<pb::LoginResponse>().user();
        m_user->clear_password();
        qCInfo(lcHci).noquote() << "logged in as" << m_login << "in session" << m_clientId;
        becomeReady(false);
    });
}

void HciSession::becomeReady(bool sameSession)
{
    m_handshake = nullptr;
    m_reattachId = m_clientId;
    m_backoff.reset();
    const bool wasReconnecting = std::exchange(m_reconnecting, false);
    setState(State::Ready);

    // On a re-attached session the server may still hold the old subscriptions: end them (errors do not
    // matter) before subscribing afresh, so no event arrives twice.
    for (HciSubscription *s : std::as_const(m_order)) {
        const int32_t old = m_subscriptions.value(s, -1);
        if (sameSession && old >= 0) {
            pb::UnsubscribeEventRequest request;
            request.set_clientid(m_clientId);
            request.set_subscriptionid(old);
            sendRaw(request);
        }
        m_subscriptions[s] = -1;
        establish(s);
    }
    emit ready();
    if (wasReconnecting)
        emit resumed(sameSession);
}

void HciSession::handshakeFailed(const HciError &error)
{
    m_handshake = nullptr;
    const bool transient = error.kind() == HciError::Kind::Timeout || error.kind() == HciError::Kind::Disconnected;
    if ((m_reconnecting && transient) || error.kind() == HciError::Kind::Disconnected) {
        // The connection's disconnected() decides (retry or give up); a timeout closes it to get there.
        m_connection->disconnectFromServer();
        return;
    }
    fail(error);
}

void HciSession::fail(const HciError &error)
{
    qCWarning(lcHci).noquote() << "session failed:" << error.toString();
    m_reconnectTimer.stop();
    m_reconnecting = false;
    m_closing = false;
    m_handshake = nullptr;
    m_lastError = error;
    forgetServerIds();
    setState(State::Disconnected); // before closing, so the close is not taken for a drop
    setClientId(-1);
    m_connection->disconnectFromServer();
    emit errorOccurred(error);
}

void HciSession::onDisconnected(const HciError &reason)
{
    if (m_state == State::Disconnected)
        return;
    if (m_closing) {
        finishClose();
        return;
    }
    m_handshake = nullptr;
    if (reason.kind() == HciError::Kind::Certificate) {
        fail(reason); // the password never went out; trying again would meet the same certificate
        return;
    }
    if (m_reattachId < 0) {
        // Never reached Ready. A server that refuses or cannot be reached is reported at once: the
        // address is probably wrong. One that hung up mid-login is likely restarting: retry a few times.
        const bool midLogin = m_state == State::Authorizing || m_state == State::LoggingIn;
        const bool retrying = m_reconnecting || (midLogin && reason.kind() == HciError::Kind::Disconnected);
        if (!retrying || m_backoff.attempts() >= m_backoff.loginAttempts()) {
            fail(reason);
            return;
        }
    }
    if (!m_reconnecting)
        qCWarning(lcHci).noquote() << "connection lost:" << reason.message() << "- reconnecting";
    m_reconnecting = true;
    m_lastError = reason;
    for (HciSubscription *s : std::as_const(m_order))
        s->setServerId(-1); // keep the old id in m_subscriptions for the re-attach clean-up
    setState(State::Reconnecting);
    scheduleReconnect();
}

void HciSession::scheduleReconnect()
{
    const auto delay = m_backoff.next();
    emit reconnectScheduled(m_backoff.attempts(), int(delay.count()));
    m_reconnectTimer.start(delay);
}

HciSubscription *HciSession::subscribe(const pb::EventSubscriptionWrapper &request)
{
    auto *subscription = new HciSubscription(request, this);
    m_subscriptions.insert(subscription, -1);
    m_order.append(subscription);
    connect(subscription, &QObject::destroyed, this, [this, subscription] { forget(subscription); });
    if (m_state == State::Ready)
        establish(subscription);
    return subscription;
}

void HciSession::establish(HciSubscription *subscription)
{
    pb::SubscribeEventRequest request;
    request.set_clientid(m_clientId);
    *request.mutable_subscription() = subscription->request();
    HciReply *reply = sendRaw(request);
    QPointer<HciSubscription> target(subscription);
    connect(reply, &HciReply::finished, this, [this, reply, target] {
        if (!target || !m_subscriptions.contains(target))
            return;
        if (!reply->isOk()) {
            if (reply->error().kind() != HciError::Kind::Disconnected)
                target->setFailed(reply->error()); // a drop is retried on the next Ready
            return;
        }
        const int32_t id = reply->response<pb::SubscribeEventResponse>().subscriptionid();
        m_subscriptions[target] = id;
        m_connection->route(id, target);
        target->setServerId(id);
    });
}

void HciSession::unsubscribe(HciSubscription *subscription)
{
    if (!subscription || !m_subscriptions.contains(subscription))
        return;
    forget(subscription);
    subscription->disconnect(this);
    subscription->deleteLater();
}

void HciSession::forget(HciSubscription *subscription)
{
    if (!m_subscriptions.contains(subscription))
        return;
    const int32_t id = m_subscriptions.take(subscription);
    m_order.removeOne(subscription);
    if (id < 0)
        return;
    m_connection->unroute(id);
    if (m_state == State::Ready) {
        pb::UnsubscribeEventRequest request;
        request.set_clientid(m_clientId);
        request.set_subscriptionid(id);
        sendRaw(request);
    }
}

QList<HciSubscription *> HciSession::subscriptions() const
{
    return m_order;
}

} // namespace sortie::hci
