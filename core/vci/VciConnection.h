#pragma once

#include "VciParser.h"
#include "VciResult.h"
#include "VciWriter.h"

#include <QDeadlineTimer>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>
#include <optional>

class QIODevice;

namespace sortie::vci {

// What Sortie answers to a request the vehicle sends (other than NOTIFY).
struct VciReply
{
    int status = 200;
    std::optional<nlohmann::json> body;
};

// The VCI protocol over any open QIODevice (QTcpSocket, QSerialPort, a pty): requests and their
// answers, notifications, subscriptions.
//
// The spec allows one outstanding request per direction, so our requests wait in a queue and go out
// one at a time. Each has a timeout counted from when it was queued. A request that timed out still
// holds the line until its late answer arrives (and is dropped) or `lateReplyGrace` passes, so a late
// answer is never taken for the next request's.
//
// The vehicle's NOTIFY requests are delivered at any time (notified()) and never answered. Its other
// requests go to the handler for their verb, or are answered 501; malformed ones get 400 or 501.
//
// Subscriptions are remembered: every SUBSCRIBE that was not refused is sent again whenever a device
// is attached, so a reconnect restores them. The device is not owned; attach a new one after a
// reconnect (VciTransport does this).
class VciConnection : public QObject
{
    Q_OBJECT
public:
    using Callback = std::function<void(const VciResult &)>;
    using Handler = std::function<VciReply(const VciMessage &)>;

    struct Stats
    {
        quint64 bytesIn = 0, bytesOut = 0, messagesIn = 0, notifications = 0, parseErrors = 0;
        quint64 requestsSent = 0, timeouts = 0, lateReplies = 0, requestsAnswered = 0;
    };

    explicit VciConnection(QObject *parent = nullptr);
    ~VciConnection() override;

    // Attaches an open device (nullptr detaches). Requests waiting or outstanding on the previous
    // device fail with ConnectionLost; remembered subscriptions are sent on the new one.
    void setDevice(QIODevice *device, const QString &reasonForDetach = QString());
    QIODevice *device() const { return m_device; }
    bool isAttached() const { return m_device != nullptr; }

    // Each returns a request id. `done` runs once, later (never inside the call), unless `context`
    // was given and has been destroyed. timeoutMs < 0 uses defaultTimeout().
    quint64 get(const QString &uri, QObject *context = nullptr, Callback done = {}, int timeoutMs = -1);
    quint64 put(const QString &uri, const nlohmann::json &value, QObject *context = nullptr, Callback done = {}, int timeoutMs = -1);
    quint64 subscribe(const QString &uri, QObject *context = nullptr, Callback done = {}, int timeoutMs = -1);
    quint64 unsubscribe(const QString &uri, QObject *context = nullptr, Callback done = {}, int timeoutMs = -1); // "*": all
    quint64 request(VciVerb verb, const QString &uri, const nlohmann::json *body, QObject *context, Callback done, int timeoutMs = -1);

    void setRequestHandler(VciVerb verb, Handler handler);
    QStringList subscriptions() const { return m_subscriptions; }
    int pendingRequests() const;

    void setDefaultTimeout(int ms) { m_defaultTimeout = ms; }
    int defaultTimeout() const { return m_defaultTimeout; }
    void setLateReplyGrace(int ms) { m_lateReplyGrace = ms; }
    void setFraming(VciFraming framing) { m_writer.setFraming(framing); }
    const Stats &stats() const { return m_stats; }
    // The most read from the device in one turn of the event loop.
    static constexpr qint64 kReadTurnBytes = 1024 * 1024;

signals:
    void attached();
    void detached(const QString &reason);
    void notified(const QString &uri, const nlohmann::json &body);
    // Every remembered subscription has been answered after an attach (some may have been refused).
    void subscriptionsRestored();
    // Something the vehicle sent could not be used; the connection goes on.
    void protocolError(const QString &message);

private:
    struct Pending
    {
        quint64 id = 0;
        VciVerb verb = VciVerb::Get;
        QString uri;
        std::optional<nlohmann::json> body;
        QPointer<QObject> context;
        bool hasContext = false;
        Callback done;
        QDeadlineTimer deadline;
    };

    void attach(QIODevice *device, const QString &reasonForDetach);
    void onReadyRead();
    void handle(VciMessage &&message);
    void handle(const VciParseError &error);
    void answer(int status, const std::optional<nlohmann::json> &body);
    void pump();
    void write(const std::string &bytes);
    void complete(Pending pending, VciResult result);
    void finishLater(Pending pending, VciResult result);
    void onTimer();
    void armTimer();
    void restoreSubscriptions();
    void noteSubscriptionResult(VciVerb verb, const QString &uri, const VciResult &result);
    VciResult resultFor(const Pending &pending, VciMessage &&response) const;
    static VciResult failure(const Pending &pending, VciResult::Error error, const QString &why);

    QIODevice *m_device = nullptr;  // not owned; forgotten when it closes or is destroyed
    QList<QMetaObject::Connection> m_deviceConnections;
    quint64 m_generation = 0;       // bumped on every attach/detach, so stale work can tell
    VciParser m_parser;
    VciWriter m_writer;
    std::deque<Pending> m_queue;
    std::optional<Pending> m_inFlight;
    bool m_lineHeld = false;        // a timed-out request still holds the line
    QDeadlineTimer m_heldUntil;
    QTimer m_timer;
    quint64 m_nextId = 1;
    int m_defaultTimeout = 5000;
    int m_lateReplyGrace = 3000;
    QStringList m_subscriptions;
    int m_restoring = 0;            // re-subscriptions still unanswered after an attach
    std::map<VciVerb, Handler> m_handlers;
    Stats m_stats;
};

} // namespace sortie::vci
