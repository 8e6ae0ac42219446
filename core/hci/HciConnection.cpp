#include "HciConnection.h"

#include "HciLog.h"
#include "HciMessageTypes.h"
#include "HciReply.h"
#include "HciSubscription.h"
#include "Messages.pb.h"

#include <QScopeGuard>
#include <QtConcurrent/QtConcurrentRun>
#include <QSslSocket>
#include <QCoreApplication>

namespace sortie::hci {
namespace {

constexpr int32_t kErrorType = 0;
constexpr int32_t kNotificationType = 1;
constexpr int32_t kOperationStatusType = 2;
constexpr int32_t kLastOperationType = 6; // 3..6: streams and cancellation, never the final answer

QString typeName(int32_t type)
{
    const auto name = HciMessageTypes::name(type);
    return name.empty() ? QCoreApplication::translate("HciConnection", "type %1").arg(type) : QString::fromLatin1(name.data(), qsizetype(name.size()));
}

QString seconds(std::chrono::milliseconds ms)
{
    return ms.count() % 1000 ? QCoreApplication::translate("HciConnection", "%1 ms").arg(ms.count()) : QStringLiteral("%1 s").arg(ms.count() / 1000);
}

} // namespace

HciConnection::HciConnection(QObject *parent)
    : QObject(parent)
    , m_socket(new QSslSocket(this))
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        if (m_tls.enabled && m_socket->state() == QAbstractSocket::ConnectedState) {
            // TCP is up but no TLS came back: a plain HCI server waits for a frame that never comes.
            closeWith({HciError::Kind::Unreachable,
                       QCoreApplication::translate("HciConnection", "%1 accepted the connection but did not begin TLS within %2: is it a plain HCI server?")
                           .arg(m_peer, seconds(m_connectTimeout))});
            return;
        }
        closeWith({HciError::Kind::Unreachable,
                   QCoreApplication::translate("HciConnection", "No answer from %1 within %2: check the address and the network").arg(m_peer, seconds(m_connectTimeout))});
    });
    connect(m_socket, &QTcpSocket::connected, this, [this] {
        if (!m_tls.enabled)
            onConnected();
    });
    connect(m_socket, &QSslSocket::encrypted, this, &HciConnection::onEncrypted);
    connect(m_socket, &QTcpSocket::readyRead, this, &HciConnection::onReadyRead);
    connect(m_socket, &QTcpSocket::errorOccurred, this, &HciConnection::onSocketError);
    connect(m_socket, &QTcpSocket::disconnected, this, [this] {
        closeWith({HciError::Kind::Disconnected, QCoreApplication::translate("HciConnection", "The server at %1 closed the connection").arg(m_peer)});
    });
}

HciConnection::~HciConnection()
{
    m_socket->disconnect(this);
    if (m_reading > 0) {
        // Deleted from a slot during the socket's readyRead: Qt touches the socket after the signal
        // returns, so it must outlive this object by one event-loop turn.
        m_socket->setParent(nullptr);
        m_socket->abort();
        m_socket->deleteLater();
    }
    const auto pending = std::exchange(m_pending, {});
    for (const auto &reply : pending)
        if (reply)
            reply->fail({HciError::Kind::Cancelled, QCoreApplication::translate("HciConnection", "The connection was closed by the application")});
}

void HciConnection::connectToServer(const QString &host, quint16 port)
{
    if (m_state != State::Unconnected)
        closeWith({HciError::Kind::Cancelled, QStringLiteral("Reconnecting")});
    m_host = host;
    m_peer = host.contains(u':') ? QStringLiteral("[%1]:%2").arg(host).arg(port) : QStringLiteral("%1:%2").arg(host).arg(port);
    m_decoder.reset();
    forgetDecodingAside();
    m_verdict = {};
    setState(State::Connecting);
    qCInfo(lcHci) << "connecting to" << m_peer << (m_tls.enabled ? "over TLS" : "in clear");
    m_connectTimer.start(m_connectTimeout);
    if (m_tls.enabled) {
        // The certificate is judged by TlsVerdict once the handshake is done, before anything is
        // written: Qt's own check would refuse a self-signed certificate before it could be remembered.
        m_socket->setPeerVerifyMode(QSslSocket::VerifyNone);
        m_socket->connectToHostEncrypted(host, port);
    } else {
        m_socket->connectToHost(host, port);
    }
}

void HciConnection::disconnectFromServer()
{
    closeWith({HciError::Kind::Disconnected, QCoreApplication::translate("HciConnection", "Disconnected from %1").arg(m_peer)});
}

void HciConnection::drop(const HciError &reason)
{
    closeWith(reason);
}

void HciConnection::onConnected()
{
    m_connectTimer.stop();
    // As the UgCS SDK does: small requests go out at once, and a dead peer is noticed by the OS.
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_socket->setSocketOption(QAbstractSocket::KeepAliveOption, 1);
    qCInfo(lcHci) << "connected to" << m_peer;
    setState(State::Connected);
    emit connected();
}

void HciConnection::onEncrypted()
{
    if (m_state != State::Connecting)
        return;
    m_verdict = tls::TlsVerdict::judge(m_tls, m_peer, m_host, m_socket->peerCertificateChain());
    if (!m_verdict.accepted()) {
        closeWith({HciError::Kind::Certificate, QCoreApplication::translate("HciConnection", "Not connected to %1 over TLS: %2").arg(m_peer, m_verdict.reason)});
        return;
    }
    QPointer<HciConnection> self(this);
    emit certificateAccepted(m_verdict);
    if (self && m_state == State::Connecting)
        onConnected();
}

void HciConnection::onSocketError()
{
    const auto error = m_socket->error();
    if (m_state == State::Unconnected)
        return;
    if (m_state == State::Connecting) {
        switch (error) {
        case QAbstractSocket::ConnectionRefusedError:
            closeWith({HciError::Kind::Refused,
                       QCoreApplication::translate("HciConnection", "%1 refused the connection").arg(m_peer)});
            return;
        case QAbstractSocket::SslHandshakeFailedError:
        case QAbstractSocket::SslInternalError:
            closeWith({HciError::Kind::Unreachable,
                       QCoreApplication::translate("HciConnection", "The TLS handshake with %1 failed (%2): does it speak TLS on that port?").arg(m_peer, m_socket->errorString())});
            return;
        case QAbstractSocket::HostNotFoundError:
            closeWith({HciError::Kind::Unreachable, QCoreApplication::translate("HciConnection", "The host in %1 cannot be found").arg(m_peer)});
            return;
        default:
            closeWith({HciError::Kind::Unreachable, QCoreApplication::translate("HciConnection", "Cannot reach %1: %2").arg(m_peer, m_socket->errorString())});
            return;
        }
    }
    if (error == QAbstractSocket::RemoteHostClosedError)
        closeWith({HciError::Kind::Disconnected, QCoreApplication::translate("HciConnection", "The server at %1 closed the connection").arg(m_peer)});
    else
        closeWith({HciError::Kind::Disconnected, QCoreApplication::translate("HciConnection", "Connection to %1 lost: %2").arg(m_peer, m_socket->errorString())});
}

void HciConnection::closeWith(const HciError &reason)
{
    if (m_state == State::Unconnected)
        return;
    m_connectTimer.stop();
    setState(State::Unconnected);
    m_socket->abort();
    m_decoder.reset();
    forgetDecodingAside();
    m_routes.clear();
    qCInfo(lcHci).noquote() << "connection to" << m_peer << "closed:" << reason.message();

    QPointer<HciConnection> self(this);
    const auto pending = std::exchange(m_pending, {});
    for (const auto &reply : pending) {
        if (reply)
            reply->fail({HciError::Kind::Disconnected,
                         QCoreApplication::translate("HciConnection", "%1 got no answer: %2").arg(reply->requestName(), reason.message())});
        if (!self)
            return;
    }
    emit disconnected(reason);
}

void HciConnection::forgetDecodingAside()
{
    ++m_generation;
    m_decodingAside = false;
}

void HciConnection::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

int32_t HciConnection::nextInstanceId()
{
    // Unique among outstanding requests; -1 is the notification id, so never use it.
    for (;;) {
        const int32_t id = m_nextInstanceId;
        m_nextInstanceId = id == std::numeric_limits<int32_t>::max() ? 0 : id + 1;
        if (id >= 0 && !m_pending.contains(id))
            return id;
    }
}

HciReply *HciConnection::send(const google::protobuf::Message &request, std::chrono::milliseconds timeout)
{
    const auto type = HciMessageTypes::number(request.GetDescriptor());
    auto *reply = new HciReply(-1, type.value_or(-1), this);
    if (!type) {
        reply->failLater({HciError::Kind::Protocol,
                          QCoreApplication::translate("HciConnection", "%1 is not an HCI message").arg(QString::fromStdString(request.GetDescriptor()->name()))});
        return reply;
    }
    if (m_state != State::Connected) {
        reply->failLater({HciError::Kind::Disconnected,
                          QCoreApplication::translate("HciConnection", "%1 not sent: not connected to the server").arg(typeName(*type))});
        return reply;
    }
    const int32_t id = nextInstanceId();
    m_outBuffer.clear();
    if (!appendHciFrame(m_outBuffer, id, request)) {
        reply->failLater({HciError::Kind::Protocol,
                          QCoreApplication::translate("HciConnection", "%1 not sent: missing %2")
                              .arg(typeName(*type), QString::fromStdString(request.InitializationErrorString()))});
        return reply;
    }
    reply->m_instanceId = id;
    m_pending.insert(id, reply);
    const auto limit = timeout.count() > 0 ? timeout : m_defaultTimeout;
    connect(&reply->m_timeout, &QTimer::timeout, this, [this, id] { onTimeout(id); });
    connect(reply, &QObject::destroyed, this, [this, id, reply] {
        // A caller may delete a reply it no longer wants; a late answer is then reported as unmatched.
        if (m_pending.value(id) == nullptr || m_pending.value(id) == reply)
            m_pending.remove(id);
    });
    reply->m_timeout.start(limit);
    qCDebug(lcHci).noquote() << "->" << id << typeName(*type) << m_outBuffer.size() << "bytes";
    m_socket->write(m_outBuffer.data(), qint64(m_outBuffer.size()));
    return reply;
}

void HciConnection::onTimeout(int32_t instanceId)
{
    const QPointer<HciReply> reply = m_pending.take(instanceId);
    if (!reply)
        return;
    qCWarning(lcHci).noquote() << reply->requestName() << instanceId << "timed out";
    reply->fail({HciError::Kind::Timeout, QCoreApplication::translate("HciConnection", "No answer to %1 within %2")
                                              .arg(reply->requestName(), seconds(std::chrono::milliseconds(reply->m_timeout.interval())))});
}

void HciConnection::route(int32_t subscriptionId, HciSubscription *subscription)
{
    m_routes.insert(subscriptionId, subscription);
}

void HciConnection::unroute(int32_t subscriptionId)
{
    m_routes.remove(subscriptionId);
}

void HciConnection::onReadyRead()
{
    if (m_decodingAside)
        return; // the bytes wait in the socket until the big frame before them is decoded
    QPointer<HciConnection> self(this);
    ++m_reading;
    const auto done = qScopeGuard([&] {
        if (self)
            --m_reading;
    });
    if (!takeFrames())
        return;
    while (m_state == State::Connected && !m_decodingAside && m_socket->bytesAvailable() > 0) {
        const QByteArray chunk = m_socket->read(64 * 1024);
        m_bytesReceived += quint64(chunk.size());
        m_decoder.feed(std::string_view(chunk.constData(), size_t(chunk.size())));
        if (!takeFrames())
            return;
    }
}

bool HciConnection::takeFrames()
{
    QPointer<HciConnection> self(this);
    while (!m_decodingAside) {
        if (auto whole = m_decoder.takeWhole(kDecodeAsideFromBytes)) {
            decodeAside(std::move(*whole));
            return true;
        }
        auto result = m_decoder.next();
        if (!result)
            return true;
        handle(*result);
        // A slot may have closed or deleted the connection; stop before touching anything more.
        if (!self || m_state != State::Connected)
            return false;
    }
    return true;
}

void HciConnection::decodeAside(HciRawFrame frame)
{
    // Parsing tens of MiB takes long enough to freeze the window: another thread decodes the frame
    // while this one goes on, and the frames after it wait, so answers keep the stream's order.
    m_decodingAside = true;
    const quint64 generation = m_generation;
    QtConcurrent::run([frame = std::move(frame)] { return std::make_shared<HciFrameDecoder::Result>(HciFrameDecoder::decode(frame)); })
        .then(this, [this, generation](const std::shared_ptr<HciFrameDecoder::Result> &result) {
            if (generation != m_generation)
                return; // decoded for a connection that has since closed
            m_decodingAside = false;
            ++m_framesDecodedAside;
            QPointer<HciConnection> self(this);
            handle(*result);
            if (self && m_state == State::Connected)
                onReadyRead(); // the frames and bytes that waited
        });
}

void HciConnection::handle(HciFrameDecoder::Result &result)
{
    if (auto *frame = std::get_if<HciFrame>(&result)) {
        ++m_framesReceived;
        dispatch(*frame);
        return;
    }
    const auto &dropped = std::get<HciDroppedFrame>(result);
    dropFrame(QCoreApplication::translate("HciConnection", "%1 at byte %2: %3")
                  .arg(QString::fromLatin1(toString(dropped.reason)))
                  .arg(dropped.offset)
                  .arg(QString::fromStdString(dropped.detail)));
}

void HciConnection::dropFrame(const QString &reason)
{
    ++m_framesDropped;
    qCWarning(lcHci).noquote() << "dropped frame from" << m_peer << "-" << reason;
    emit frameDropped(reason);
}

void HciConnection::dispatch(HciFrame &frame)
{
    const int32_t type = frame.header.type;
    const int32_t id = frame.header.instanceId;
    if (id == kHciNotificationInstance) {
        QPointer<HciConnection> self(this);
        if (type == kNotificationType)
            dispatchNotification(frame);
        else
            dropFrame(QCoreApplication::translate("HciConnection", "%1 with instance id -1 is not a notification").arg(typeName(type)));
        if (self) // a subscriber may have deleted us
            m_decoder.recycle(std::move(frame.message));
        return;
    }
    const QPointer<HciReply> reply = m_pending.value(id);
    if (!reply) {
        dropFrame(QCoreApplication::translate("HciConnection", "%1 for instance id %2, which no request waits for (answered after its timeout?)")
                      .arg(typeName(type))
                      .arg(id));
        return;
    }
    if (type == kOperationStatusType) {
        const auto &status = static_cast<const pb::OperationStatus &>(*frame.message);
        if (status.progressstack_size() > 0) {
            const auto &top = status.progressstack(0);
            emit reply->progress(QString::fromStdString(top.title()), top.progress(), top.maxprogress());
        }
        return;
    }
    if (type > kOperationStatusType && type <= kLastOperationType) {
        qCDebug(lcHci).noquote() << "ignored" << typeName(type) << "for request" << id;
        return;
    }
    m_pending.remove(id);
    qCDebug(lcHci).noquote() << "<-" << id << typeName(type);
    if (type == kErrorType) {
        reply->fail(HciError::fromServer(static_cast<const pb::Error &>(*frame.message)));
        return;
    }
    const auto expected = HciMessageTypes::responseFor(reply->requestType());
    if (expected && *expected != type) {
        reply->fail({HciError::Kind::Protocol, QCoreApplication::translate("HciConnection", "The server answered %1 with %2 instead of %3")
                                                   .arg(reply->requestName(), typeName(type), typeName(*expected))});
        return;
    }
    reply->succeed(std::move(frame.message));
}

void HciConnection::dispatchNotification(const HciFrame &frame)
{
    const auto &notification = static_cast<const pb::Notification &>(*frame.message);
    const QPointer<HciSubscription> target = m_routes.value(notification.subscriptionid());
    if (target) {
        target->deliver(notification);
        return;
    }
    ++m_unrouted;
    emit unroutedNotification(notification);
}

} // namespace sortie::hci
