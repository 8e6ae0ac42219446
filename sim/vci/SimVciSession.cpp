#include "SimVciSession.h"

#include "SimVciVehicle.h"
#include "VciProfile.h"

#include <QIODevice>

#include <cmath>

namespace sortie::sim {

using vci::VciVerb;

SimVciSession::SimVciSession(QIODevice *device, SimVciVehicle *vehicle, QObject *parent)
    : QObject(parent)
    , m_device(device)
    , m_vehicle(vehicle)
{
    connect(device, &QIODevice::readyRead, this, &SimVciSession::onReadyRead);
    connect(vehicle, &SimVciVehicle::changed, this, [this](const QString &uri) {
        if (m_subscriptions.contains(uri))
            notify(uri);
    });
    m_telemetry.setTimerType(Qt::PreciseTimer);
    connect(&m_telemetry, &QTimer::timeout, this, &SimVciSession::sendTelemetry);
    connect(&m_status, &QTimer::timeout, this, &SimVciSession::repeatStatus);
    m_status.start(vci::profile::kStatusRepeatMs);
    retime();
    if (device->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, &SimVciSession::onReadyRead, Qt::QueuedConnection);
}

void SimVciSession::retime()
{
    const double rate = std::clamp(m_vehicle->telemetryRate(), 0.1, 1000.0);
    const int interval = std::max(1, int(std::lround(1000.0 / rate)));
    if (!m_telemetry.isActive() || m_telemetry.interval() != interval)
        m_telemetry.start(interval);
}

void SimVciSession::reset()
{
    m_subscriptions.clear();
    m_requests.clear();
    m_parser.reset();
    m_answering = false;
}

void SimVciSession::drop()
{
    if (!m_device)
        return;
    reset();
    m_telemetry.stop();
    m_status.stop();
    m_device->close();
    emit dropped();
}

void SimVciSession::sendRaw(const QByteArray &bytes)
{
    if (m_device && m_device->isOpen())
        m_device->write(bytes);
}

void SimVciSession::onReadyRead()
{
    if (!m_device)
        return;
    const QByteArray data = m_device->readAll();
    m_parser.feed(std::string_view(data.constData(), size_t(data.size())));
    while (auto result = m_parser.next()) {
        if (auto *m = std::get_if<vci::VciMessage>(&*result)) {
            if (m->isResponse())
                continue; // it never asked anything, so there is nothing to match
            if (m->verb == VciVerb::Notify)
                continue; // never answered
        } else if (std::get<vci::VciParseError>(*result).replyStatus() == 0) {
            continue;
        }
        m_requests.push_back(std::move(*result));
    }
    answerNext();
}

void SimVciSession::answerNext()
{
    while (!m_answering && !m_requests.empty() && m_device) {
        const int delay = m_vehicle->options().answerDelayMs;
        if (delay > 0) { // the slow-answer knob
            m_answering = true;
            QTimer::singleShot(delay, this, [this] {
                m_answering = false;
                answerOne();
                answerNext();
            });
            return;
        }
        answerOne();
    }
}

void SimVciSession::answerOne()
{
    if (m_requests.empty() || !m_device)
        return;
    const vci::VciParser::Result request = std::move(m_requests.front());
    m_requests.pop_front();
    const auto *m = std::get_if<vci::VciMessage>(&request);
    const SimVciReply reply = m ? serve(*m)
                                : SimVciReply::error(std::get<vci::VciParseError>(request).replyStatus(),
                                                     std::get<vci::VciParseError>(request).message);
    std::string bytes;
    vci::VciWriter(m_vehicle->options().framing).appendResponse(bytes, reply.status, {}, reply.body ? &*reply.body : nullptr);
    send(std::move(bytes));
    if (reply.status == 200 && m && m->verb == VciVerb::Subscribe)
        notify(QString::fromStdString(m->uri)); // the current value at once
}

SimVciReply SimVciSession::serve(const vci::VciMessage &request)
{
    const QString uri = QString::fromStdString(request.uri);
    switch (request.verb) {
    case VciVerb::Subscribe:
        if (!m_vehicle->isSubscribable(request.uri))
            return SimVciReply::error(501, request.uri + " cannot be subscribed to");
        m_subscriptions.insert(uri);
        return SimVciReply::okEmpty();
    case VciVerb::Unsubscribe:
        if (request.uri == "*")
            m_subscriptions.clear();
        else
            m_subscriptions.remove(uri);
        return SimVciReply::okEmpty();
    case VciVerb::Get:
    case VciVerb::Put: {
        SimVciReply reply = m_vehicle->handle(request);
        retime(); // a PUT may have changed the telemetry rate
        return reply;
    }
    case VciVerb::Notify:
        break;
    }
    return SimVciReply::error(501, "unexpected request");
}

void SimVciSession::sendTelemetry()
{
    retime();
    for (const QString &uri : std::as_const(m_subscriptions)) {
        if (m_vehicle->isPeriodic(uri.toStdString()))
            notify(uri);
        if (!m_device)
            return;
    }
}

void SimVciSession::repeatStatus()
{
    for (std::string_view status : vci::profile::kStatus) {
        const QString uri = QString::fromLatin1(status.data(), qsizetype(status.size()));
        if (m_subscriptions.contains(uri))
            notify(uri);
        if (!m_device)
            return;
    }
}

void SimVciSession::notify(const QString &uri)
{
    const auto value = m_vehicle->resource(uri.toStdString());
    if (!value || !m_device)
        return;
    std::string bytes;
    vci::VciWriter(m_vehicle->options().framing).appendRequest(bytes, VciVerb::Notify, uri.toStdString(), &*value);
    ++m_notifications;
    const int every = m_vehicle->options().malformedEvery;
    if (every > 0 && m_notifications % quint64(every) == 0) {
        // Broken on purpose: the body loses its closing bytes and stray text follows on its own line.
        bytes.resize(bytes.size() - 3);
        bytes += "#garbage#\r\n";
    }
    send(std::move(bytes));
}

void SimVciSession::send(std::string bytes)
{
    if (!m_device || !m_device->isOpen())
        return;
    m_device->write(bytes.data(), qint64(bytes.size()));
    ++m_sent;
    const int dropAfter = m_vehicle->options().dropAfter;
    if (dropAfter > 0 && m_sent >= quint64(dropAfter))
        drop();
}

} // namespace sortie::sim
