#include "ServerRecording.h"

#include "ConnectionController.h"
#include "ServerAddress.h"
#include "FleetRecording.h"
#include "FlightRecorder.h"
#include "HciClient.h"
#include "HciSession.h"
#include "VehicleFleet.h"

namespace sortie::flightlog {

ServerRecording::ServerRecording(Options options, QObject *parent)
    : QObject(parent)
    , m_options(std::move(options))
{
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &ServerRecording::stop);
}

ServerRecording::~ServerRecording()
{
    m_recording.reset();
    m_fleet.reset(); // the vehicles go before the recorder that watches them
    m_recorder.reset();
    m_connection.reset();
    m_client.reset();
    m_session.reset();
}

bool ServerRecording::start(QString *error)
{
    m_recorder = std::make_unique<FlightRecorder>(FlightRecorder::Options{m_options.path, m_options.limits, 500});
    if (!m_recorder->start(error))
        return false;
    m_session = std::make_unique<hci::HciSession>();
    m_client = std::make_unique<hci::HciClient>(m_session.get());
    m_connection = std::make_unique<client::ConnectionController>(m_session.get(), m_options.settings);
    if (!m_options.serverPin.isEmpty()) {
        const auto target = client::ServerAddress::parse(m_options.server);
        const auto *address = std::get_if<client::ServerAddress>(&target);
        if (!address || !address->tls || !m_connection->certificates().pin(address->peer(), m_options.serverPin)) {
            if (error)
                *error = tr("a pinned certificate needs a tls://host:port server and a SHA-256 fingerprint");
            m_recorder->stop();
            return false;
        }
    }
    // No one is at a prompt: the command line has answered whether the password may go in clear.
    connect(m_connection.get(), &client::ConnectionController::cleartextQuestionChanged, this, [this] {
        if (!m_connection->isAskingCleartext())
            return;
        if (m_options.allowCleartext) {
            m_connection->answerCleartext(true);
            return;
        }
        const QString server = m_options.server;
        fail(tr("%1 is not this computer and the connection is not secured: the password would cross the network in clear. "
                "Record over TLS (--server tls://%1), or pass --allow-cleartext to send it in clear.").arg(server));
    });
    connect(m_connection.get(), &client::ConnectionController::certificateNoteChanged, this, [this] {
        if (!m_connection->certificateNote().isEmpty())
            emit message(m_connection->certificateNote());
    });
    m_fleet = std::make_unique<client::VehicleFleet>(m_client.get());
    m_recording = std::make_unique<FleetRecording>(m_fleet.get(), m_recorder.get(), m_session.get());
    connect(m_connection.get(), &client::ConnectionController::ready, this, [this] {
        if (!m_wasReady)
            emit message(tr("logged in to %1 as %2; recording to %3").arg(m_connection->server(), m_connection->user(), m_recorder->path()));
        m_wasReady = true;
    });
    connect(m_connection.get(), &client::ConnectionController::errorChanged, this, [this] {
        if (m_connection->errorString().isEmpty())
            return;
        if (!m_wasReady)
            fail(m_connection->errorString());
        else
            emit message(tr("server: %1").arg(m_connection->errorString()));
    });
    connect(m_fleet.get(), &client::VehicleFleet::countChanged, this, [this] {
        const int n = m_fleet->count();
        emit message(n == 1 ? tr("1 vehicle") : tr("%1 vehicles").arg(n));
    });
    connect(m_recorder.get(), &FlightRecorder::errorChanged, this, [this] { fail(m_recorder->errorString()); });
    if (!m_connection->connectToServer(m_options.server, m_options.user, m_options.password)) {
        if (error)
            *error = m_connection->errorString();
        m_recorder->stop();
        return false;
    }
    if (m_options.seconds > 0)
        m_deadline.start(m_options.seconds * 1000);
    return true;
}

void ServerRecording::stop()
{
    if (m_done)
        return;
    m_done = true;
    m_deadline.stop();
    m_connection->disconnectFromServer();
    m_recorder->stop();
    emit message(tr("log closed: %1").arg(m_recorder->path()));
    emit finished(0, {});
}

void ServerRecording::fail(const QString &error)
{
    if (m_done)
        return;
    m_done = true;
    m_deadline.stop();
    if (m_connection)
        m_connection->disconnectFromServer();
    if (m_recorder)
        m_recorder->stop();
    emit finished(1, error);
}

} // namespace sortie::flightlog
