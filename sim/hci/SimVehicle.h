#pragma once

#include "FlightModel.h"
#include "SimTelemetry.h"

#include <QString>

#include <memory>
#include <vector>

namespace com::ugcs::ucs::proto {
class CommandDefinition;
class VehicleCommandResultDto;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// One simulated vehicle: its Vehicle object, its FlightModel, its commands and its telemetry.
class SimTerrain;

class SimVehicle
{
public:
    SimVehicle(const pb::Vehicle &vehicle, FlightModel model, double telemetryRateHz);
    ~SimVehicle();

    int id() const;
    const pb::Vehicle &vehicle() const { return *m_vehicle; }
    // {id, name, tailNumber}: how events and results refer to the vehicle.
    const pb::Vehicle &reference() const { return *m_reference; }
    const FlightModel &model() const { return m_model; }
    // The Vehicle object changed in the store (renamed, new profile...).
    void setVehicle(const pb::Vehicle &vehicle);
    const SimTelemetry &telemetry() const { return m_telemetry; }
    // Where its camera's video is (sortie-sim --rtsp-port), sent as video_stream_uri.
    void setVideoStreamUri(const QString &uri) { m_telemetry.setVideoStreamUri(uri.toStdString()); }
    // The ground under the vehicle (not owned): telemetry's altitude_agl is above it. Without one,
    // above the home ground.
    // The flight model lands on that ground and keeps above it.
    void setTerrain(const SimTerrain *terrain);

    // Advances the flight by dt seconds and fills `event` with the telemetry batch. Returns true when
    // the set of available commands changed (a CommandEvent is due).
    bool tick(double dt, qint64 nowMs, pb::TelemetryEvent *event);
    std::vector<pb::CommandDefinition> commands() const;
    pb::VehicleCommandResultDto execute(const pb::Command &command);
    // Loads an uploaded route as the vehicle's mission; returns why not, or empty.
    QString upload(const pb::ProcessedRoute &route);

private:
    std::unique_ptr<pb::Vehicle> m_vehicle;
    std::unique_ptr<pb::Vehicle> m_reference;
    FlightModel m_model;
    SimTelemetry m_telemetry;
    quint32 m_availability = 0;
    const SimTerrain *m_terrain = nullptr;
};

} // namespace sortie::sim
