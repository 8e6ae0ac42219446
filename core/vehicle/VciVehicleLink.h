#pragma once

#include "VciConnection.h"
#include "VciEndpoint.h"
#include "VciTransport.h"
#include "VehicleLink.h"

namespace sortie::vehicle {

// A vehicle reached directly over VCI (TCP or a serial line). It keeps the line open (VciTransport
// reconnects), subscribes to every telemetry and state resource of Sortie's profile (restored after
// each reconnect), turns NOTIFYs into normalised telemetry, reads the identity from /vehicle and
// maps each command to its PUT (docs/vci-profile.md).
class VciVehicleLink : public VehicleLink
{
    Q_OBJECT
public:
    explicit VciVehicleLink(const vci::VciEndpoint &endpoint, QObject *parent = nullptr);
    ~VciVehicleLink() override;

    vci::VciConnection *connection() { return &m_connection; }
    vci::VciTransport *transport() { return &m_transport; }
    void reconnect() { m_transport.reopen(); }
    void setCommandTimeout(int ms) { m_connection.setDefaultTimeout(ms); }

    QString protocol() const override { return QStringLiteral("VCI"); }
    VehicleIdentity identity() const override { return m_identity; }
    State state() const override { return m_state; }
    Capabilities capabilities() const override { return MissionDownload | Parameters | GoTo; }

    void start() override;
    void stop() override;

    void arm(bool armed, Done done) override;
    void setMode(FlightMode mode, Done done) override;
    void takeoff(double altitude, Done done) override;
    void land(Done done) override;
    void returnHome(Done done) override;
    void goTo(double latitude, double longitude, double altitude, double speed, Done done) override;
    void prepareMission(const mission::Route &route, PrepareDone done) override;
    void uploadMission(const PreparedMission &mission, UploadObserver observer, Done done) override;
    void downloadMission(MissionDone done) override;
    void readParameters(ParametersDone done) override;
    void setParameter(const QString &name, double value, Done done) override;

private:
    void onAttached();
    void onNotified(const QString &uri, const nlohmann::json &body);
    void put(std::string_view uri, const nlohmann::json &body, Done done);
    void setState(State state);
    static CommandResult toCommandResult(const vci::VciResult &result);

    vci::VciEndpoint m_endpoint;
    vci::VciTransport m_transport;
    vci::VciConnection m_connection;
    VehicleIdentity m_identity;
    State m_state = State::Disconnected;
    bool m_stopping = false;
};

} // namespace sortie::vehicle
