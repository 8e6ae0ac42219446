#pragma once

#include "FlightLogWriter.h"

#include <QObject>
#include <QTimer>

#include <memory>

class QSettings;

namespace sortie::hci {
class HciClient;
class HciSession;
}
namespace sortie::client {
class ConnectionController;
class VehicleFleet;
}

namespace sortie::flightlog {

class FleetRecording;
class FlightRecorder;

// `sortie-log record`: logs in to an HCI server and records every vehicle it has until `seconds`
// have passed (0: until stop()), then closes the log. A login that fails before the first success
// ends it with an error; a connection lost later is recorded while the session reconnects.
class ServerRecording : public QObject
{
    Q_OBJECT

public:
    struct Options
    {
        QString server;   // host:port, or tls://host:port
        QString user;
        QString password;
        QString path;
        int seconds = 0;
        RecordingLimits limits;
        // Over TLS: the SHA-256 fingerprint the server's certificate must have (else the system's
        // trust store, then the certificate remembered in `settings` on first use).
        QString serverPin;
        // Not over TLS, to a server that is not this computer: the password goes in clear only
        // when the operator said so on the command line; without it the recording is refused.
        bool allowCleartext = false;
        QSettings *settings = nullptr;  // the remembered certificates (not owned); null: none
    };

    explicit ServerRecording(Options options, QObject *parent = nullptr);
    ~ServerRecording() override;

    bool start(QString *error);
    void stop(); // closes the log cleanly; finished() follows
    FlightRecorder *recorder() const { return m_recorder.get(); }

signals:
    void message(const QString &line); // progress for the operator
    void finished(int exitCode, const QString &error);

private:
    void fail(const QString &error);

    Options m_options;
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_client;
    std::unique_ptr<client::ConnectionController> m_connection;
    std::unique_ptr<client::VehicleFleet> m_fleet;
    std::unique_ptr<FlightRecorder> m_recorder;
    std::unique_ptr<FleetRecording> m_recording;
    QTimer m_deadline;
    bool m_wasReady = false;
    bool m_done = false;
};

} // namespace sortie::flightlog
