#pragma once

#include "SimVciReply.h"
#include "VciParser.h"
#include "VciWriter.h"

#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <deque>

class QIODevice;

namespace sortie::sim {

class SimVciVehicle;

// One client of a simulated vehicle, on one device (a TCP socket or the pty): reads requests with
// core's parser, answers them in order (after the vehicle's answer delay, a test knob), and sends
// NOTIFY for what the client subscribed to: telemetry at the vehicle's rate, state on change.
// Broken requests get 400 or 501 as the parser says; the vehicle never sends requests of its own but
// NOTIFY, so it never waits for the client. The knobs malformedEvery and dropAfter break its output.
class SimVciSession : public QObject
{
    Q_OBJECT
public:
    SimVciSession(QIODevice *device, SimVciVehicle *vehicle, QObject *parent = nullptr);

    QIODevice *device() const { return m_device; }
    QSet<QString> subscriptions() const { return m_subscriptions; }
    quint64 notificationsSent() const { return m_notifications; }
    // Forgets the client's state (the pty's client closed the line).
    void reset();
    // Closes the connection now (the "dropped connection" knob).
    void drop();
    // Writes bytes as they are, for tests of the client's error handling.
    void sendRaw(const QByteArray &bytes);

signals:
    void dropped();

private:
    void onReadyRead();
    void answerNext();
    void answerOne();
    SimVciReply serve(const vci::VciMessage &request);
    void sendTelemetry();
    void repeatStatus();
    void notify(const QString &uri);
    void send(std::string bytes);
    void retime();

    QPointer<QIODevice> m_device;
    SimVciVehicle *m_vehicle;
    vci::VciParser m_parser;
    std::deque<vci::VciParser::Result> m_requests; // waiting to be answered, in order
    bool m_answering = false;
    QSet<QString> m_subscriptions;
    QTimer m_telemetry;
    QTimer m_status; // repeats the status resources (profile::kStatus)
    quint64 m_notifications = 0, m_sent = 0;
};

} // namespace sortie::sim
