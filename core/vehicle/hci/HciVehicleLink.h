#pragma once

#include "HciRoutePass.h"
#include "VehicleLink.h"

#include <QPointer>

#include <memory>

namespace com::ugcs::ucs::proto {
class EventWrapper;
class Vehicle;
} // namespace com::ugcs::ucs::proto

namespace sortie::hci {
class HciClient;
class HciReply;
class HciSubscription;
} // namespace sortie::hci

namespace sortie::vehicle {

// A vehicle reached through a UgCS server over HCI. Telemetry comes from a telemetry subscription for
// this vehicle (the session keeps it across reconnects); commands go as SendCommand and missions as
// ProcessRoute (prepareMission) then UploadRoute (uploadMission), commands and uploads inside the
// vehicle's lock as the UgCS SDK does it (hci::underLock; another operator's lock makes them fail
// with that operator's name). The link's state follows the session. Mission progress comes from the
// server's RoutePass objects (an object-modification subscription, and the list once connected),
// reported as the same Mission* telemetry fields a VCI vehicle sends; a malformed RoutePass is
// dropped with errorOccurred naming why.
// HCI cannot read a vehicle's mission back or change its parameters; readParameters() gives the
// vehicle profile's values (VPT_* names).
class HciVehicleLink : public VehicleLink
{
    Q_OBJECT
public:
    HciVehicleLink(hci::HciClient *client, const com::ugcs::ucs::proto::Vehicle &vehicle, QObject *parent = nullptr);
    ~HciVehicleLink() override;

    int vehicleObjectId() const;

    QString protocol() const override { return QStringLiteral("HCI"); }
    VehicleIdentity identity() const override { return m_identity; }
    State state() const override { return m_state; }
    Capabilities capabilities() const override { return GoTo; }

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
    using Work = std::function<void(Done finish)>;
    void command(const QString &code, const QVariantMap &arguments, Done done);
    void underLock(const QString &what, Work work, Done done);
    void onEvent(const com::ugcs::ucs::proto::EventWrapper &event);
    void onRoutePassEvent(const com::ugcs::ucs::proto::EventWrapper &event);
    void readRoutePasses();
    void report(const HciRoutePassTracker::Outcome &outcome);
    void updateState();
    void failLater(Done done, const QString &why);
    template<class F>
    void onFinished(hci::HciReply *reply, F &&f);

    hci::HciClient *m_client;
    std::unique_ptr<com::ugcs::ucs::proto::Vehicle> m_vehicle;
    QPointer<hci::HciSubscription> m_subscription;
    QPointer<hci::HciSubscription> m_routePassSubscription;
    HciRoutePassTracker m_routePass;
    bool m_routePassSeen = false; // an event arrived: a list read earlier is older
    VehicleIdentity m_identity;
    State m_state = State::Disconnected;
    bool m_started = false;
};

} // namespace sortie::vehicle
