#include "VciConnection.h"

#include "VciLog.h"

#include <QIODevice>
#include <QCoreApplication>

namespace sortie::vci {
namespace {

QString describeRequest(VciVerb verb, const QString &uri)
{
    return QString::fromLatin1(toString(verb).data(), qsizetype(toString(verb).size())) + QLatin1Char(' ') + uri;
}

} // namespace

// i18n: not text below (the error's name, for logs and the dump)
const char *toString(VciResult::Error error)
{
    switch (error) {
    case VciResult::Error::None: return "ok";
    case VciResult::Error::Status: return "refused";
    case VciResult::Error::Timeout: return "timeout";
    case VciResult::Error::NotConnected: return "not connected";
    case VciResult::Error::ConnectionLost: return "connection lost";
    case VciResult::Error::BadResponse: return "bad response";
    case VciResult::Error::InvalidRequest: return "invalid request";
    }
    return "?";
}
// i18n: text again

VciConnection::VciConnection(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<nlohmann::json>();
    qRegisterMetaType<VciResult>();
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &VciConnection::onTimer);
}

VciConnection::~VciConnection()
{
    for (const auto &c : std::as_const(m_deviceConnections))
        disconnect(c);
}

void VciConnection::setDevice(QIODevice *device, const QString &reasonForDetach)
{
    if (device != m_device)
        attach(device, reasonForDetach);
}

void VciConnection::attach(QIODevice *device, const QString &reasonForDetach)
{
    const bool wasAttached = m_device != nullptr;
    for (const auto &c : std::as_const(m_deviceConnections))
        disconnect(c);
    m_deviceConnections.clear();
    m_device = device;
    const quint64 generation = ++m_generation;
    m_parser.reset();
    m_lineHeld = false;
    m_restoring = 0;

    const QString why = reasonForDetach.isEmpty() ? QCoreApplication::translate("VciConnection", "the connection to the vehicle was closed") : reasonForDetach;
    if (m_inFlight) {
        Pending p = std::move(*m_inFlight);
        m_inFlight.reset();
        finishLater(p, failure(p, VciResult::Error::ConnectionLost, why));
    }
    while (!m_queue.empty()) {
        Pending p = std::move(m_queue.front());
        m_queue.pop_front();
        finishLater(p, failure(p, VciResult::Error::ConnectionLost, why));
    }
    if (wasAttached) {
        qCInfo(lcVci) << "detached:" << why;
        emit detached(why);
    }
    if (!device || generation != m_generation) {
        armTimer();
        return;
    }
    m_deviceConnections << connect(device, &QIODevice::readyRead, this, &VciConnection::onReadyRead);
    m_deviceConnections << connect(device, &QIODevice::aboutToClose, this,
                                   [this] { setDevice(nullptr, QCoreApplication::translate("VciConnection", "the device was closed")); });
    m_deviceConnections << connect(device, &QObject::destroyed, this, [this] {
        m_deviceConnections.clear(); // they die with it
        attach(nullptr, QCoreApplication::translate("VciConnection", "the device was destroyed"));
    });
    emit attached();
    if (generation != m_generation)
        return;
    restoreSubscriptions();
    pump();
    if (device->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, [this, generation] {
            if (generation == m_generation)
                onReadyRead();
        }, Qt::QueuedConnection);
}

quint64 VciConnection::get(const QString &uri, QObject *context, Callback done, int timeoutMs)
{
    return request(VciVerb::Get, uri, nullptr, context, std::move(done), timeoutMs);
}

quint64 VciConnection::put(const QString &uri, const nlohmann::json &value, QObject *context, Callback done, int timeoutMs)
{
    return request(VciVerb::Put, uri, &value, context, std::move(done), timeoutMs);
}

quint64 VciConnection::subscribe(const QString &uri, QObject *context, Callback done, int timeoutMs)
{
    if (VciWriter::isValidUri(uri.toStdString()) && uri != QLatin1String("*") && !m_subscriptions.contains(uri))
        m_subscriptions.append(uri);
    return request(VciVerb::Subscribe, uri, nullptr, context, std::move(done), timeoutMs);
}

quint64 VciConnection::unsubscribe(const QString &uri, QObject *context, Callback done, int timeoutMs)
{
    if (uri == QLatin1String("*"))
        m_subscriptions.clear();
    else
        m_subscriptions.removeAll(uri);
    return request(VciVerb::Unsubscribe, uri, nullptr, context, std::move(done), timeoutMs);
}

quint64 VciConnection::request(VciVerb verb, const QString &uri, const nlohmann::json *body, QObject *context, Callback done,
                               int timeoutMs)
{
    Pending p;
    p.id = m_nextId++;
    p.verb = verb;
    p.uri = uri;
    if (body)
        p.body = *body;
    p.context = context;
    p.hasContext = context != nullptr;
    if (verb == VciVerb::Subscribe) {
        // A subscription the vehicle refuses is not restored after a reconnect.
        p.done = [this, uri, done = std::move(done)](const VciResult &r) {
            if (r.error == VciResult::Error::Status)
                m_subscriptions.removeAll(uri);
            if (done)
                done(r);
        };
    } else {
        p.done = std::move(done);
    }
    const int timeout = timeoutMs < 0 ? m_defaultTimeout : timeoutMs;
    p.deadline = timeout == 0 ? QDeadlineTimer(QDeadlineTimer::Forever) : QDeadlineTimer(timeout);
    const quint64 id = p.id;

    if (!VciWriter::isValidUri(uri.toStdString()) || (uri == QLatin1String("*") && verb != VciVerb::Unsubscribe)) {
        finishLater(p, failure(p, VciResult::Error::InvalidRequest, QCoreApplication::translate("VciConnection", "\"%1\" is not a valid VCI URI").arg(uri)));
    } else if (verb == VciVerb::Notify) {
        finishLater(p, failure(p, VciResult::Error::InvalidRequest, QCoreApplication::translate("VciConnection", "a ground station does not send NOTIFY")));
    } else if (!m_device) {
        finishLater(p, failure(p, VciResult::Error::NotConnected, QCoreApplication::translate("VciConnection", "not connected to the vehicle")));
    } else {
        m_queue.push_back(std::move(p));
        pump();
        armTimer();
    }
    return id;
}

void VciConnection::setRequestHandler(VciVerb verb, Handler handler)
{
    if (handler)
        m_handlers[verb] = std::move(handler);
    else
        m_handlers.erase(verb);
}

int VciConnection::pendingRequests() const
{
    return int(m_queue.size()) + (m_inFlight ? 1 : 0);
}

void VciConnection::pump()
{
    while (m_device && !m_inFlight && !m_lineHeld && !m_queue.empty()) {
        Pending p = std::move(m_queue.front());
        m_queue.pop_front();
        if (p.deadline.hasExpired()) {
            ++m_stats.timeouts;
            finishLater(p, failure(p, VciResult::Error::Timeout, QCoreApplication::translate("VciConnection", "no answer in time (it waited behind other requests)")));
            continue;
        }
        std::string bytes;
        m_writer.appendRequest(bytes, p.verb, p.uri.toStdString(), p.body ? &*p.body : nullptr);
        m_inFlight = std::move(p);
        ++m_stats.requestsSent;
        write(bytes);
    }
    armTimer();
}

void VciConnection::write(const std::string &bytes)
{
    if (!m_device)
        return;
    const qint64 n = m_device->write(bytes.data(), qint64(bytes.size()));
    if (n != qint64(bytes.size())) {
        const QString why = QCoreApplication::translate("VciConnection", "writing to the vehicle failed: %1").arg(m_device->errorString());
        qCWarning(lcVci) << why;
        setDevice(nullptr, why);
        return;
    }
    m_stats.bytesOut += quint64(n);
}

void VciConnection::onReadyRead()
{
    // At most kReadTurnBytes a turn of the event loop: the JSON reader builds a body as its bytes
    // come, so a 16 MiB body that is all there at once (after a stall, from a fast link) is read over
    // a few dozen turns, and the window repaints between them.
    const quint64 generation = m_generation;
    qint64 budget = kReadTurnBytes;
    while (m_device && generation == m_generation && budget > 0) {
        const QByteArray data = m_device->read(std::min<qint64>(budget, 64 * 1024));
        if (data.isEmpty())
            return;
        budget -= data.size();
        m_stats.bytesIn += quint64(data.size());
        m_parser.feed(std::string_view(data.constData(), size_t(data.size())));
        while (generation == m_generation) {
            auto result = m_parser.next();
            if (!result)
                break;
            if (auto *message = std::get_if<VciMessage>(&*result))
                handle(std::move(*message));
            else
                handle(std::get<VciParseError>(*result));
        }
    }
    if (m_device && generation == m_generation && m_device->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, [this, generation] {
            if (generation == m_generation)
                onReadyRead();
        }, Qt::QueuedConnection);
}

void VciConnection::handle(VciMessage &&m)
{
    ++m_stats.messagesIn;
    if (m.isResponse()) {
        if (m_inFlight) {
            Pending p = std::move(*m_inFlight);
            m_inFlight.reset();
            VciResult r = resultFor(p, std::move(m));
            complete(p, r);
        } else if (m_lineHeld) {
            ++m_stats.lateReplies;
            m_lineHeld = false;
            qCInfo(lcVci) << "dropped a late answer to a request that had timed out:" << m.status;
        } else {
            const QString why = QCoreApplication::translate("VciConnection", "the vehicle sent an answer (%1) to no request").arg(m.status);
            qCWarning(lcVci) << why;
            emit protocolError(why);
        }
        pump();
        return;
    }
    if (m.verb == VciVerb::Notify) {
        ++m_stats.notifications;
        emit notified(QString::fromStdString(m.uri), m.body);
        return;
    }
    const auto handler = m_handlers.find(m.verb);
    if (handler != m_handlers.end()) {
        const VciReply reply = handler->second(m);
        answer(reply.status, reply.body);
        return;
    }
    answer(501, nlohmann::json{{"error", "Sortie serves no " // i18n: not text (an answer to the vehicle)
                                                   + std::string(toString(m.verb)) + " " + m.uri}});
}

void VciConnection::handle(const VciParseError &e)
{
    ++m_stats.parseErrors;
    const QString why = QCoreApplication::translate("VciConnection", "unreadable message from the vehicle at byte %1: %2").arg(e.offset).arg(QString::fromStdString(e.message));
    qCWarning(lcVci) << why;
    if (e.kindKnown && e.kind == VciMessageKind::Response) {
        if (m_inFlight) {
            Pending p = std::move(*m_inFlight);
            m_inFlight.reset();
            complete(p, failure(p, VciResult::Error::BadResponse, why));
        } else {
            m_lineHeld = false;
        }
        pump();
    } else if (const int status = e.replyStatus()) {
        answer(status, nlohmann::json{{"error", e.message}});
    }
    emit protocolError(why);
}

void VciConnection::answer(int status, const std::optional<nlohmann::json> &body)
{
    std::string bytes;
    m_writer.appendResponse(bytes, status, {}, body ? &*body : nullptr);
    ++m_stats.requestsAnswered;
    write(bytes);
}

VciResult VciConnection::resultFor(const Pending &p, VciMessage &&m) const
{
    VciResult r;
    r.statusCode = m.status;
    r.reason = QString::fromStdString(m.reason);
    if (m.jsonBody)
        r.body = std::move(m.body);
    if (m.status / 100 == 2)
        return r;
    r.error = VciResult::Error::Status;
    r.message = QCoreApplication::translate("VciConnection", "%1: the vehicle answered %2 %3").arg(describeRequest(p.verb, p.uri)).arg(m.status).arg(r.reason);
    if (r.body.is_object() && r.body.contains("error") && r.body["error"].is_string())
        r.message += QStringLiteral(": ") + QString::fromStdString(r.body["error"].get<std::string>());
    return r;
}

VciResult VciConnection::failure(const Pending &p, VciResult::Error error, const QString &why)
{
    VciResult r;
    r.error = error;
    r.message = describeRequest(p.verb, p.uri) + QStringLiteral(": ") + why;
    return r;
}

void VciConnection::complete(Pending p, VciResult result)
{
    if (p.hasContext && !p.context)
        return;
    if (p.done)
        p.done(result);
}

void VciConnection::finishLater(Pending p, VciResult result)
{
    QMetaObject::invokeMethod(this, [this, p = std::move(p), result = std::move(result)]() mutable {
        complete(std::move(p), std::move(result));
    }, Qt::QueuedConnection);
}

void VciConnection::onTimer()
{
    if (m_inFlight && m_inFlight->deadline.hasExpired()) {
        Pending p = std::move(*m_inFlight);
        m_inFlight.reset();
        ++m_stats.timeouts;
        m_lineHeld = true; // until its late answer comes or the grace passes
        m_heldUntil = QDeadlineTimer(m_lateReplyGrace);
        complete(p, failure(p, VciResult::Error::Timeout, QCoreApplication::translate("VciConnection", "the vehicle did not answer in time")));
    }
    if (m_lineHeld && m_heldUntil.hasExpired()) {
        m_lineHeld = false;
        qCInfo(lcVci) << "no late answer came; sending the next request";
    }
    std::vector<Pending> expired;
    for (auto it = m_queue.begin(); it != m_queue.end();) {
        if (it->deadline.hasExpired()) {
            expired.push_back(std::move(*it));
            it = m_queue.erase(it);
        } else {
            ++it;
        }
    }
    for (Pending &p : expired) {
        ++m_stats.timeouts;
        complete(p, failure(p, VciResult::Error::Timeout, QCoreApplication::translate("VciConnection", "no answer in time (it waited behind other requests)")));
    }
    pump();
}

void VciConnection::armTimer()
{
    qint64 next = -1;
    auto consider = [&next](const QDeadlineTimer &d) {
        if (d.isForever())
            return;
        const qint64 left = std::max<qint64>(0, d.remainingTime());
        next = next < 0 ? left : std::min(next, left);
    };
    if (m_inFlight)
        consider(m_inFlight->deadline);
    if (m_lineHeld)
        consider(m_heldUntil);
    for (const Pending &p : m_queue)
        consider(p.deadline);
    if (next < 0)
        m_timer.stop();
    else
        m_timer.start(int(std::min<qint64>(next, INT_MAX)));
}

void VciConnection::restoreSubscriptions()
{
    if (m_subscriptions.isEmpty())
        return;
    m_restoring = int(m_subscriptions.size());
    const quint64 generation = m_generation;
    const QStringList uris = m_subscriptions;
    for (const QString &uri : uris) {
        request(VciVerb::Subscribe, uri, nullptr, this, [this, generation, uri](const VciResult &r) {
            if (r.error == VciResult::Error::Status)
                m_subscriptions.removeAll(uri);
            if (generation == m_generation && m_restoring > 0 && --m_restoring == 0)
                emit subscriptionsRestored();
        });
    }
}

} // namespace sortie::vci
