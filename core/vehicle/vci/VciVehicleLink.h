#pragma once

#include "VciConnection.h"
#include "VciEndpoint.h"
#include "VciFencePlan.h"
#include "VciTransport.h"
#include "VehicleLink.h"

#include <QDeadlineTimer>
#include <QPointer>

#include <optional>

namespace sortie::terrain {
class ElevationService;
} // namespace sortie::terrain

namespace sortie::vehicle {

// A vehicle reached directly over VCI (TCP or a serial line). It keeps the line open (VciTransport
// reconnects), subscribes to every telemetry and state resource of Sortie's profile (restored after
// each reconnect), turns NOTIFYs into normalised telemetry, reads the identity from /vehicle and
// maps each command to its PUT (docs/vci-profile.md). A route is planned here (vciMissionFor), its
// heights made relative to the home the vehicle reports, over the ground `elevation` knows.
class VciVehicleLink : public VehicleLink
{
    Q_OBJECT
public:
    // `elevation` (not owned, may be nullptr) gives the ground under the points of uploaded routes.
    explicit VciVehicleLink(const vci::VciEndpoint &endpoint, terrain::ElevationService *elevation = nullptr, QObject *parent = nullptr);
    ~VciVehicleLink() override;

    vci::VciConnection *connection() { return &m_connection; }
    vci::VciTransport *transport() { return &m_transport; }
    void reconnect() { m_transport.reopen(); }
    void setCommandTimeout(int ms) { m_connection.setDefaultTimeout(ms); }
    // What makes a route's fence: the airspace's (airspace::vciFenceFor), handed in by whoever builds
    // the link's world, as the terrain is handed its DEM opener. Without one, a route goes up with an
    // empty fence when neither it nor the settings ask for one, and is refused when they do.
    void setFenceBuilder(VciFenceBuilder builder) { m_fenceBuilder = std::move(builder); }

    QString protocol() const override { return QStringLiteral("VCI"); }
    VehicleIdentity identity() const override { return m_identity; }
    State state() const override { return m_state; }
    Capabilities capabilities() const override { return MissionDownload | Parameters | GoTo | Fence | HomePosition; }

    void start() override;
    void stop() override;

    void arm(bool armed, Done done) override;
    void setMode(FlightMode mode, Done done) override;
    void takeoff(double altitude, Done done) override;
    void land(Done done) override;
    void returnHome(Done done) override;
    void goTo(double latitude, double longitude, double altitude, double speed, Done done) override;
    // The route's own fence only (the Process view); uploads go through prepareMissionWithFence.
    void prepareMission(const mission::Route &route, PrepareDone done) override;
    // The route as waypoints and its fence (VciFenceBuilder.h), carried in the prepared mission;
    // uploadMission PUTs the fence, reads it back, then PUTs the mission.
    void prepareMissionWithFence(const mission::Route &route, const FenceSettings &fence, PrepareDone done) override;
    void uploadMission(const PreparedMission &mission, UploadObserver observer, Done done) override;
    void downloadMission(MissionDone done) override;
    void readParameters(ParametersDone done) override;
    void setParameter(const QString &name, double value, Done done) override;

private:
    void onAttached();
    void onNotified(const QString &uri, const nlohmann::json &body);
    void put(std::string_view uri, const nlohmann::json &body, Done done);
    void setState(State state);
    void planMission(const mission::Route &route, const FenceSettings &fence, std::optional<double> homeAmsl, PrepareDone done,
                     QDeadlineTimer deadline);
    void sendFence(const PreparedMission &mission, Done next);
    void onFenceStatus(const nlohmann::json &body);
    void onPhoto(const nlohmann::json &body);
    static CommandResult toCommandResult(const vci::VciResult &result);

    // How long an upload waits for terrain data a source is still fetching.
    static constexpr int kTerrainWaitMs = 20000;

    vci::VciEndpoint m_endpoint;
    QPointer<terrain::ElevationService> m_elevation;
    VciFenceBuilder m_fenceBuilder;
    vci::VciTransport m_transport;
    vci::VciConnection m_connection;
    VehicleIdentity m_identity;
    State m_state = State::Disconnected;
    bool m_stopping = false;
    int m_fenceBreaches = -1; // as /fence/status last said; -1 before the first
    qint64 m_photoSequence = -1; // the last photo heard of on /camera/photo; -1 before the first
};

} // namespace sortie::vehicle
