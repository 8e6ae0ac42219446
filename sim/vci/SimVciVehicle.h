#pragma once

#include "VciProfile.h"

#include "FlightModel.h"
#include "SimFence.h"
#include "SimShutter.h"
#include "SimVciOptions.h"
#include "SimVciReply.h"
#include "VciMessage.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <map>
#include <optional>
#include <string>

namespace sortie::sim {

// A simulated vehicle that speaks Sortie's VCI profile (docs/vci-profile.md): it flies a FlightModel,
// serves the profile's resources as JSON and obeys PUTs. Protocol-free: SimVciSession does the wire.
class SimVciVehicle : public QObject
{
    Q_OBJECT
public:
    explicit SimVciVehicle(const SimVciOptions &options, QObject *parent = nullptr);

    const SimVciOptions &options() const { return m_options; }
    SimVciOptions &knobs() { return m_options; } // tests change the knobs while it runs
    const FlightModel &model() const { return m_model; }
    const SimFence &fence() const { return m_fence; }
    const SimShutter &shutter() const { return m_shutter; } // every photo taken, for tests

    // Answers a GET or PUT on one of the profile's URIs.
    SimVciReply handle(const vci::VciMessage &request);
    // The current value of a resource, as GET and NOTIFY carry it; nullopt for an unknown URI.
    std::optional<nlohmann::json> resource(const std::string &uri) const;
    bool isSubscribable(const std::string &uri) const;
    bool isPeriodic(const std::string &uri) const; // telemetry, sent at the telemetry rate

    double telemetryRate() const { return m_parameters.at("telemetry_rate"); }

signals:
    // A state resource (armed, mode, mission, progress, a parameter) changed.
    void changed(const QString &uri);

private:
    void tick();
    void checkChanges();
    int64_t now() const; // ms since the epoch on the vehicle's clock (SimVciOptions::simulatedClock)
    SimVciReply put(const std::string &uri, const vci::VciMessage &request);
    SimVciReply putFence(const nlohmann::json &body);
    void enforceFence();
    SimVciReply putParameter(const std::string &name, const vci::VciMessage &request);
    nlohmann::json progress() const;
    nlohmann::json parameters() const;
    static SimVciReply refusedOrOk(const FlightModel::Refusal &refusal, nlohmann::json value);
    void runCameraActions(int waypoint); // the camera and gimbal actions of a waypoint reached
    SimShutter::Clock shutterClock() const { return {m_simulatedSeconds, now()}; }

    SimVciOptions m_options;
    FlightModel m_model;
    SimFence m_fence;
    SimShutter m_shutter;
    QTimer m_tick;
    QElapsedTimer m_clock;
    int64_t m_startMs = 0;          // wall clock when the vehicle started
    double m_simulatedSeconds = 0;  // since then, on the vehicle's clock
    std::vector<vci::profile::Waypoint> m_missionAsSent; // the accepted mission with its actions, for GET
    std::map<std::string, double> m_parameters;     // the writable ones
    std::map<std::string, nlohmann::json> m_lastState; // last value of each state resource, to see changes
};

} // namespace sortie::sim
