#include "SimVehicle.h"

#include "Messages.pb.h"
#include "SimCommands.h"
#include "SimRouteProcessor.h"
#include "SimTerrain.h"

namespace sortie::sim {

SimVehicle::SimVehicle(const pb::Vehicle &vehicle, FlightModel model, double telemetryRateHz)
    : m_vehicle(std::make_unique<pb::Vehicle>(vehicle))
    , m_reference(std::make_unique<pb::Vehicle>())
    , m_model(std::move(model))
    , m_telemetry(telemetryRateHz)
{
    setVehicle(vehicle);
    m_availability = SimCommands::availability(m_model);
}

void SimVehicle::setVehicle(const pb::Vehicle &vehicle)
{
    *m_vehicle = vehicle;
    m_reference->Clear();
    m_reference->set_id(vehicle.id());
    m_reference->set_name(vehicle.name());
    m_reference->set_tailnumber(vehicle.tailnumber());
}

SimVehicle::~SimVehicle() = default;

int SimVehicle::id() const
{
    return m_vehicle->id();
}

bool SimVehicle::tick(double dt, qint64 nowMs, pb::TelemetryEvent *event)
{
    m_model.tick(dt);
    *event->mutable_vehicle() = *m_reference;
    if (m_terrain) {
        // The model flies above its home ground; the operator sees the height above the ground below.
        FlightModel::State reported = m_model.state();
        const double amsl = reported.altitudeAmsl();
        reported.groundElevation = m_terrain->groundOr(reported.latitude, reported.longitude, reported.groundElevation);
        reported.altitudeAgl = amsl - reported.groundElevation;
        m_telemetry.record(nowMs, reported, event);
    } else {
        m_telemetry.record(nowMs, m_model.state(), event);
    }
    const quint32 availability = SimCommands::availability(m_model);
    return std::exchange(m_availability, availability) != availability;
}

std::vector<pb::CommandDefinition> SimVehicle::commands() const
{
    return SimCommands::definitions(*m_reference, m_model);
}

pb::VehicleCommandResultDto SimVehicle::execute(const pb::Command &command)
{
    pb::VehicleCommandResultDto result;
    *result.mutable_vehicle() = *m_reference;
    const auto outcome = SimCommands::execute(m_model, command);
    result.set_commandstatus(pb::CommandStatus(outcome.status));
    if (!outcome.error.isEmpty())
        result.set_errormessage(outcome.error.toStdString());
    return result;
}

void SimVehicle::setTerrain(const SimTerrain *terrain)
{
    m_terrain = terrain;
    if (terrain)
        m_model.setGround([terrain](double lat, double lon) { return terrain->groundAt(lat, lon); });
    else
        m_model.setGround({});
}

QString SimVehicle::upload(const pb::ProcessedRoute &route)
{
    QString error;
    auto plan = SimRouteProcessor::flightPlan(route, m_model.state().groundElevation, &error);
    if (plan.empty())
        return error;
    const auto refusal = m_model.setMission(std::move(plan));
    return refusal.empty() ? QString() : QStringLiteral("%1 refused the route: %2")
                                             .arg(QString::fromStdString(m_vehicle->name()), QString::fromStdString(refusal));
}

} // namespace sortie::sim
