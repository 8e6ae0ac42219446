#include "VciTransport.h"

#include "VciLog.h"

#include <QPointer>
#include <QSerialPort>
#include <QSslSocket>
#include <QCoreApplication>

namespace sortie::vci {

VciTransport::VciTransport(const VciEndpoint &endpoint, QObject *parent)
    : QObject(parent)
    , m_endpoint(endpoint)
{
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &VciTransport::attempt);
}

VciTransport::~VciTransport()
{
    if (m_device) {
        m_device->disconnect(this);
        delete m_device;
    }
}

void VciTransport::setRetryDelays(int firstMs, int maxMs)
{
    m_firstDelay = m_delay = std::max(1, firstMs);
    m_maxDelay = std::max(m_firstDelay, maxMs);
}

void VciTransport::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void VciTransport::open()
{
    if (m_state != State::Closed)
        return;
    m_delay = m_firstDelay;
    attempt();
}

void VciTransport::close()
{
    m_retry.stop();
    drop(QCoreApplication::translate("VciTransport", "closed by the operator"));
    setState(State::Closed);
}

void VciTransport::reopen()
{
    m_retry.stop();
    drop(QCoreApplication::translate("VciTransport", "reconnecting at the operator's request"));
    m_delay = m_firstDelay;
    attempt();
}

void VciTransport::attempt()
{
    setState(State::Opening);
    if (m_endpoint.kind == VciEndpoint::Kind::Tcp) {
        auto *socket = new QSslSocket(this);
        m_device = socket;
        if (m_endpoint.tls)
            connect(socket, &QSslSocket::encrypted, this, &VciTransport::onEncrypted);
        else
            connect(socket, &QTcpSocket::connected, this, &VciTransport::onOpened);
        connect(socket, &QAbstractSocket::errorOccurred, this, [this, socket] { onFailed(socket, socket->errorString()); });
        connect(socket, &QAbstractSocket::disconnected, this,
                [this, socket] { onFailed(socket, QCoreApplication::translate("VciTransport", "the vehicle closed the connection")); });
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        if (m_endpoint.tls) {
            // Judged by TlsVerdict after the handshake (Qt's own check would refuse what could be remembered).
            socket->setPeerVerifyMode(QSslSocket::VerifyNone);
            socket->connectToHostEncrypted(m_endpoint.host, m_endpoint.port);
        } else {
            socket->connectToHost(m_endpoint.host, m_endpoint.port);
        }
        return;
    }
    auto *port = new QSerialPort(this);
    m_device = port;
    port->setPortName(m_endpoint.device);
    port->setBaudRate(m_endpoint.baudRate);
    port->setDataBits(m_endpoint.dataBits);
    port->setParity(m_endpoint.parity);
    port->setStopBits(m_endpoint.stopBits);
    port->setFlowControl(m_endpoint.flowControl);
    if (!port->open(QIODevice::ReadWrite)) {
        onFailed(port, QCoreApplication::translate("VciTransport", "cannot open %1: %2").arg(m_endpoint.device, port->errorString()));
        return;
    }
    connect(port, &QSerialPort::errorOccurred, this, [this, port](QSerialPort::SerialPortError e) {
        if (e != QSerialPort::NoError && e != QSerialPort::TimeoutError)
            onFailed(port, port->errorString());
    });
    onOpened();
}

void VciTransport::onEncrypted()
{
    auto *socket = qobject_cast<QSslSocket *>(m_device);
    if (!socket || m_state != State::Opening)
        return;
    const QString peer = QStringLiteral("%1:%2").arg(m_endpoint.host.contains(u':') ? u'[' + m_endpoint.host + u']' : m_endpoint.host).arg(m_endpoint.port);
    m_verdict = tls::TlsVerdict::judge({true, m_endpoint.pinnedSha256, m_store}, peer, m_endpoint.host, socket->peerCertificateChain());
    if (!m_verdict.accepted()) {
        onFailed(socket, QCoreApplication::translate("VciTransport", "not connected over TLS: %1").arg(m_verdict.reason));
        return;
    }
    QPointer<QSslSocket> alive(socket);
    emit certificateAccepted(m_verdict);
    if (alive && m_device == socket && m_state == State::Opening)
        onOpened();
}

void VciTransport::onOpened()
{
    m_delay = m_firstDelay;
    m_lastError.clear();
    setState(State::Open);
    qCInfo(lcVci) << "opened" << m_endpoint.toString();
    emit opened(m_device);
}

void VciTransport::onFailed(QIODevice *device, const QString &reason)
{
    if (device != m_device || m_state == State::Closed)
        return; // a late signal from a device already dropped
    const bool wasOpen = m_state == State::Open;
    m_lastError = reason;
    drop(reason);
    if (!wasOpen) {
        qCInfo(lcVci) << "cannot open" << m_endpoint.toString() << ":" << reason;
        emit attemptFailed(reason);
    }
    setState(State::Retrying);
    m_retry.start(m_delay);
    m_delay = std::min(m_delay * 2, m_maxDelay);
}

void VciTransport::drop(const QString &reason)
{
    if (!m_device)
        return;
    QIODevice *device = m_device;
    const bool wasOpen = m_state == State::Open;
    m_device = nullptr;
    device->disconnect(this);
    if (wasOpen) {
        qCInfo(lcVci) << "lost" << m_endpoint.toString() << ":" << reason;
        emit lost(reason);
    }
    device->close();
    device->deleteLater();
}

} // namespace sortie::vci
