#include "HciServerConnection.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimLog.h"

#include <QTcpSocket>

namespace sortie::sim {

HciServerConnection::HciServerConnection(QTcpSocket *socket, HciRequestDispatcher &dispatcher, SimFaults &faults, QObject *parent)
    : QObject(parent)
    , m_socket(socket)
    , m_dispatcher(dispatcher)
    , m_faults(faults)
    , m_peer(QStringLiteral("%1:%2").arg(socket->peerAddress().toString()).arg(socket->peerPort()))
{
    m_socket->setParent(this);
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(300); // an incomplete reorder batch still goes out
    connect(&m_flushTimer, &QTimer::timeout, this, &HciServerConnection::flushHeld);
    connect(m_socket, &QTcpSocket::readyRead, this, &HciServerConnection::onReadyRead);
    connect(m_socket, &QTcpSocket::disconnected, this, [this] {
        if (!std::exchange(m_closed, true))
            emit closed();
    });
    qCInfo(lcSim).noquote() << "client connected from" << m_peer;
    // Over TLS the first request may have come with the handshake, before readyRead was connected.
    if (m_socket->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, &HciServerConnection::onReadyRead, Qt::QueuedConnection);
}

HciServerConnection::~HciServerConnection()
{
    m_socket->disconnect(this);
}

bool HciServerConnection::isOpen() const
{
    return !m_closed && m_socket->state() == QAbstractSocket::ConnectedState;
}

void HciServerConnection::drop()
{
    m_held.clear();
    m_socket->abort();
    if (!std::exchange(m_closed, true))
        emit closed();
}

void HciServerConnection::onReadyRead()
{
    while (!m_closed && m_socket->bytesAvailable() > 0) {
        const QByteArray chunk = m_socket->read(64 * 1024);
        m_decoder.feed(std::string_view(chunk.constData(), size_t(chunk.size())));
        while (!m_closed) {
            auto result = m_decoder.next();
            if (!result)
                break;
            if (auto *frame = std::get_if<hci::HciFrame>(&*result)) {
                if (m_faults.disconnectOn.contains(frame->header.type)) {
                    qCInfo(lcSim) << "fault: dropping the connection on request type" << frame->header.type;
                    drop();
                    return;
                }
                m_dispatcher.dispatch(*this, *frame);
            } else {
                m_dispatcher.rejectDropped(*this, std::get<hci::HciDroppedFrame>(*result));
            }
        }
    }
}

void HciServerConnection::write(const std::string &bytes)
{
    if (!m_closed)
        m_socket->write(bytes.data(), qint64(bytes.size()));
}

void HciServerConnection::sendAnswer(int32_t instanceId, int32_t requestType, const google::protobuf::Message &answer)
{
    if (m_closed)
        return;
    if (m_faults.dropAnswersTo.contains(requestType) || m_faults.dropNextAnswers > 0) {
        if (m_faults.dropNextAnswers > 0)
            --m_faults.dropNextAnswers;
        qCInfo(lcSim) << "fault: not answering request" << instanceId << "of type" << requestType;
        return;
    }
    std::string bytes;
    if (!hci::appendHciFrame(bytes, instanceId, answer)) {
        qCWarning(lcSim) << "cannot encode the answer to request" << instanceId << answer.InitializationErrorString().c_str();
        return;
    }
    if (m_faults.malformedBeforeAnswers > 0) {
        --m_faults.malformedBeforeAnswers;
        bytes = malformedFrame(instanceId) + bytes;
    }
    if (m_faults.delayMs > 0) {
        QTimer::singleShot(m_faults.delayMs, this, [this, bytes = std::move(bytes), instanceId]() mutable {
            release(std::move(bytes), instanceId);
        });
        return;
    }
    release(std::move(bytes), instanceId);
}

void HciServerConnection::release(std::string bytes, int32_t instanceId)
{
    if (m_faults.reverseBatch <= 1) {
        write(bytes);
        return;
    }
    m_held.push_back(std::move(bytes));
    if (int(m_held.size()) >= m_faults.reverseBatch)
        flushHeld();
    else
        m_flushTimer.start();
    Q_UNUSED(instanceId)
}

void HciServerConnection::flushHeld()
{
    m_flushTimer.stop();
    for (auto it = m_held.rbegin(); it != m_held.rend(); ++it)
        write(*it);
    m_held.clear();
}

void HciServerConnection::sendProgress(int32_t instanceId, const google::protobuf::Message &status)
{
    std::string bytes;
    if (hci::appendHciFrame(bytes, instanceId, status))
        write(bytes);
}

void HciServerConnection::sendNotification(const pb::Notification &notification)
{
    // A client that stopped reading must not make the server buffer without bound: past a few
    // megabytes of unsent data, events for it are dropped (answers still queue).
    constexpr qint64 kMaxBacklog = 8 * 1024 * 1024;
    if (m_socket->bytesToWrite() > kMaxBacklog)
        return;
    std::string bytes;
    if (hci::appendHciFrame(bytes, hci::kHciNotificationInstance, notification))
        write(bytes);
}

// One of five kinds of frame a client must drop and survive, in turn.
std::string HciServerConnection::malformedFrame(int32_t instanceId)
{
    switch (m_malformedKind++ % 5) {
    case 0: return hci::encodeRawHciFrame(instanceId, 21, std::string("\x08\x01", 2), 0x4851);           // bad signature
    case 1: return hci::encodeRawHciFrame(instanceId, 21, std::string("\x08\x01", 2), hci::kHciSignature, 2); // bad version
    case 2: return hci::encodeRawHciFrame(instanceId, 7, std::string("\x08\x01", 2));                     // unmapped type
    case 3: return hci::encodeRawHciFrame(instanceId, 21, std::string("\x0f\xff\xff", 3));               // invalid protobuf
    default: return hci::encodeRawHciFrame(instanceId, 21, std::string());                               // missing required clientId
    }
}

} // namespace sortie::sim
