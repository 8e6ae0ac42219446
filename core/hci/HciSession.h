#pragma once

#include "HciError.h"
#include "HciReconnectPolicy.h"
#include "TlsOptions.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <chrono>
#include <memory>

namespace sortie::hci {

class HciConnection;
class HciReply;
class HciSubscription;

// A logged-in HCI session: authorizes (clientId -1, protocol 2.0), logs in, and keeps the session alive.
// When the connection drops it reconnects with backoff, first re-attaching to the same server session
// (AuthorizeHci with the previous clientId) and, if the server refuses, starting a new session and
// logging in again. Subscriptions belong to the session and survive all of this: each is re-established
// and its new server id is mapped transparently. The password is kept in memory for re-login only and
// never logged.
class HciSession : public QObject
{
    Q_OBJECT
    Q_PROPERTY(State state READ state NOTIFY stateChanged)
    Q_PROPERTY(int clientId READ clientId NOTIFY clientIdChanged)
    Q_PROPERTY(QString login READ login NOTIFY stateChanged)
    Q_PROPERTY(sortie::hci::HciError lastError READ lastError NOTIFY errorOccurred)

public:
    enum class State { Disconnected, Connecting, Authorizing, LoggingIn, Ready, Reconnecting };
    Q_ENUM(State)

    explicit HciSession(QObject *parent = nullptr);
    ~HciSession() override;

    // Connects, authorizes and logs in. Failures end in Disconnected with errorOccurred(): Refused,
    // Unreachable, Authentication, Version, Licence... A connection that drops mid-login (a server
    // restarting) is retried reconnectPolicy().loginAttempts() times; a session that reached Ready
    // reconnects by itself until closed. `tls` secures this connection and every reconnect (plain
    // when not enabled); a certificate refused (Kind::Certificate) ends the session, never retried.
    void open(const QString &host, quint16 port, const QString &login, const QString &password, const tls::TlsOptions &tls = {});
    // Logs out (LogoutRequest with the clientId) and disconnects; no reconnect follows.
    void close();

    State state() const { return m_state; }
    bool isReady() const { return m_state == State::Ready; }
    int clientId() const { return m_clientId; }
    QString login() const { return m_login; }
    // The logged-in user as the server described it (LoginResponse.user).
    const pb::User &user() const { return *m_user; }
    const HciError &lastError() const { return m_lastError; }

    // Sends a request with this session's clientId filled in. Fails at once (on the next event-loop
    // turn) when the session is not Ready.
    HciReply *send(const google::protobuf::Message &request, std::chrono::milliseconds timeout = {});

    // A subscription owned by the session, established now if Ready and after every reconnect.
    HciSubscription *subscribe(const pb::EventSubscriptionWrapper &request);
    // Ends a subscription on the server and deletes it (deleting it directly does the same).
    void unsubscribe(HciSubscription *subscription);
    QList<HciSubscription *> subscriptions() const;

    HciConnection *connection() const { return m_connection; }
    HciReconnectPolicy &reconnectPolicy() { return m_backoff; }
    void setRequestTimeout(std::chrono::milliseconds timeout);
    void setConnectTimeout(std::chrono::milliseconds timeout);
    // BCP-47 tag sent in AuthorizeHciRequest (default: the system locale, e.g. "en-US").
    void setLocale(const QString &bcp47) { m_locale = bcp47; }

signals:
    void stateChanged(sortie::hci::HciSession::State state);
    void clientIdChanged(int clientId);
    void ready();
    void errorOccurred(const sortie::hci::HciError &error);
    // After an automatic reconnect reached Ready: sameSession is true when the server re-attached the
    // previous session (its locks are still ours), false when a new session had to be started.
    void resumed(bool sameSession);
    void reconnectScheduled(int attempt, int delayMs);

private:
    void onConnected();
    void onDisconnected(const HciError &reason);
    void authorize(int32_t clientId);
    void logIn();
    void becomeReady(bool sameSession);
    void handshakeFailed(const HciError &error);
    void fail(const HciError &error);
    void scheduleReconnect();
    void watchForSilence(HciReply *reply);
    void finishClose();
    void establish(HciSubscription *subscription);
    void forget(HciSubscription *subscription);
    void forgetServerIds();
    void setState(State state);
    void setClientId(int32_t id);
    HciReply *failedReply(const google::protobuf::Message &request, const HciError &error);
    HciReply *sendRaw(const google::protobuf::Message &request, std::chrono::milliseconds timeout = {});

    HciConnection *m_connection;
    HciReconnectPolicy m_backoff;
    QTimer m_reconnectTimer;
    State m_state = State::Disconnected;
    QString m_host;
    quint16 m_port = 0;
    QString m_login;
    QString m_password; // for re-login after a reconnect; never logged
    QString m_locale;
    int32_t m_clientId = -1;
    int32_t m_reattachId = -1; // the session to re-attach to on the next authorize, or -1
    bool m_reconnecting = false;
    bool m_closing = false;
    std::unique_ptr<pb::User> m_user;
    HciError m_lastError;
    QPointer<HciReply> m_handshake;
    // Subscriptions and their server ids on the current connection (-1 while not established).
    QHash<HciSubscription *, int32_t> m_subscriptions;
    QList<HciSubscription *> m_order;
};

} // namespace sortie::hci
