#include "SbsFeed.h"

#include "TrafficLog.h"
#include "TrafficPicture.h"
#include <QCoreApplication>

namespace sortie::traffic {

SbsFeed::SbsFeed(TrafficPicture *picture, QObject *parent)
    : QObject(parent)
    , m_picture(picture)
{
    m_retry.setSingleShot(true);
    m_connectTimeout.setSingleShot(true);
    m_connectTimeout.setInterval(kConnectTimeoutMs);
    connect(&m_retry, &QTimer::timeout, this, &SbsFeed::connectNow);
    connect(&m_connectTimeout, &QTimer::timeout, this, [this] { onFailure(tr("no answer within %1 s").arg(kConnectTimeoutMs / 1000)); });
    connect(&m_socket, &QTcpSocket::connected, this, &SbsFeed::onConnected);
    connect(&m_socket, &QTcpSocket::readyRead, this, &SbsFeed::onReadyRead);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, [this] { onFailure(m_socket.errorString()); });
    connect(&m_socket, &QTcpSocket::disconnected, this, [this] { onFailure(tr("the receiver closed the connection")); });
    m_socket.setReadBufferSize(kBufferBytes);
}

// The socket says goodbye as it is destroyed, after the members its handlers use: it is not heard.
SbsFeed::~SbsFeed()
{
    m_socket.disconnect(this);
    m_socket.abort();
}

bool SbsFeed::parseAddress(const QString &address, QString *host, quint16 *port)
{
    const int colon = address.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0)
        return false;
    QString h = address.left(colon).trimmed();
    if (h.startsWith(QLatin1Char('[')) && h.endsWith(QLatin1Char(']')))
        h = h.mid(1, h.size() - 2);
    bool ok = false;
    const uint p = address.mid(colon + 1).toUInt(&ok);
    if (h.isEmpty() || !ok || p == 0 || p > 65535)
        return false;
    *host = h;
    *port = quint16(p);
    return true;
}

bool SbsFeed::setAddress(const QString &address)
{
    const QString trimmed = address.trimmed();
    QString host;
    quint16 port = 0;
    const bool valid = trimmed.isEmpty() || parseAddress(trimmed, &host, &port);
    m_retry.stop();
    m_connectTimeout.stop();
    m_socket.blockSignals(true);
    m_socket.abort();
    m_socket.blockSignals(false);
    m_reader = sbs::SbsReader();
    m_retryMs = kFirstRetryMs;
    if (m_address != trimmed) {
        m_address = trimmed;
        emit addressChanged();
    }
    m_host = host;
    m_port = port;
    m_error = valid ? QString() : tr("'%1' is not host:port").arg(trimmed);
    if (!valid)
        qCWarning(lcTraffic).noquote() << "SBS feed:" << m_error;
    setState(State::Off);
    if (valid && !trimmed.isEmpty())
        connectNow();
    emit stateChanged();
    return valid;
}

void SbsFeed::connectNow()
{
    m_reader = sbs::SbsReader();
    setState(State::Connecting);
    m_connectTimeout.start();
    m_socket.connectToHost(m_host, m_port);
}

void SbsFeed::onConnected()
{
    m_connectTimeout.stop();
    m_retryMs = kFirstRetryMs;
    m_error.clear();
    qCInfo(lcTraffic).noquote() << "SBS feed connected to" << m_address;
    setState(State::Connected);
}

void SbsFeed::onReadyRead()
{
    if (!m_turnQueued)
        readSome();
}

void SbsFeed::readSome()
{
    m_turnQueued = false;
    const QByteArray bytes = m_socket.read(kBytesPerTurn);
    if (m_socket.bytesAvailable() > 0) {
        // More is waiting: the next turn takes it, after whatever else the event loop has (a frame).
        m_turnQueued = true;
        QMetaObject::invokeMethod(this, &SbsFeed::readSome, Qt::QueuedConnection);
    }
    m_reader.push(std::string_view(bytes.constData(), size_t(bytes.size())));
    bool counted = false;
    while (auto result = m_reader.next()) {
        counted = true;
        if (const auto *message = std::get_if<sbs::SbsMessage>(&*result)) {
            ++m_messages;
            m_picture->report(reportFromSbs(*message));
        } else {
            const auto &dropped = std::get<sbs::SbsError>(*result);
            ++m_dropped;
            m_lastDropped = QCoreApplication::translate("SbsFeed", "line %1: %2").arg(dropped.line).arg(QString::fromStdString(dropped.reason));
            qCDebug(lcTraffic).noquote() << "SBS feed" << m_address << "dropped" << m_lastDropped;
        }
    }
    if (counted)
        emit countsChanged();
}

void SbsFeed::onFailure(const QString &why)
{
    if (m_state == State::Off || m_state == State::Waiting)
        return;
    m_connectTimeout.stop();
    m_error = why;
    m_socket.blockSignals(true);
    m_socket.abort();
    m_socket.blockSignals(false);
    qCWarning(lcTraffic).noquote() << "SBS feed" << m_address << ":" << why << "- again in" << m_retryMs << "ms";
    m_retry.start(m_retryMs);
    m_retryMs = std::min(m_retryMs * 2, kMaxRetryMs);
    setState(State::Waiting);
}

void SbsFeed::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged();
}

QString SbsFeed::statusText() const
{
    switch (m_state) {
    case State::Off: return m_error.isEmpty() ? tr("receiver off") : tr("receiver: %1").arg(m_error);
    case State::Connecting: return tr("receiver: connecting to %1").arg(m_address);
    case State::Connected: return tr("receiver %1").arg(m_address);
    case State::Waiting: return tr("receiver: %1; again in %2 s").arg(m_error).arg((m_retry.interval() + 999) / 1000);
    }
    return {};
}

} // namespace sortie::traffic
