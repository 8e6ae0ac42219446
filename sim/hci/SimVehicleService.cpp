#include "SimVehicleService.h"

#include "HciRequestDispatcher.h"
#include "HciServerConnection.h"
#include "Messages.pb.h"
#include "SimRouteProcessor.h"
#include "SimVehicleProfiles.h"
#include "SimRouteTerrain.h"
#include "SimRouteZones.h"
#include "SimSessionTable.h"
#include "SimVehicle.h"
#include "SimWorld.h"

#include "AlgorithmCatalog.h"

#include <QTimer>

namespace sortie::sim {

SimVehicleService::SimVehicleService(SimServices services)
    : m_s(services)
{
}

void SimVehicleService::install(HciRequestDispatcher &d)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::SendCommandRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { sendCommand(c); });
    d.add(pb::UploadRouteRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { uploadRoute(c); });
    d.add(pb::ProcessRouteRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { processRoute(c); });
    d.add(pb::GetParametersSelectionValuesRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { selectionValues(c); });
    d.add(pb::GetTelemetryRequest::default_instance(), A::LoggedIn, [this](SimCall &c) { telemetry(c); });
}

QString SimVehicleService::lockedBy(const SimCall &call, int vehicleId) const
{
    const auto owner = m_s.world.locks().holder(QStringLiteral("Vehicle"), vehicleId);
    if (!owner || owner->clientId == call.session->clientId)
        return {};
    return owner->login;
}

void SimVehicleService::sendCommand(SimCall &call)
{
    const auto &r = static_cast<const pb::SendCommandRequest &>(call.request);
    // Either one command for a list of vehicles, or a list of commands per vehicle.
    std::vector<std::pair<int, std::vector<const pb::Command *>>> work;
    if (r.has_command())
        for (const auto &v : r.vehicles())
            work.push_back({v.id(), {&r.command()}});
    for (const auto &dto : r.commands()) {
        std::vector<const pb::Command *> commands;
        for (const auto &c : dto.commands())
            commands.push_back(&c);
        work.push_back({dto.vehicle().id(), std::move(commands)});
    }
    if (work.empty()) {
        call.respond.error(QStringLiteral("SendCommandRequest names no command or no vehicle"));
        return;
    }
    for (const auto &[id, commands] : work)
        if (!m_s.world.vehicle(id)) {
            call.respond.error(QStringLiteral("Vehicle %1 does not exist").arg(id));
            return;
        }

    pb::SendCommandResponse response;
    for (const auto &[id, commands] : work) {
        SimVehicle *vehicle = m_s.world.vehicle(id);
        pb::VehicleCommandResultDto result;
        if (const QString owner = lockedBy(call, id); !owner.isEmpty()) {
            *result.mutable_vehicle() = vehicle->reference();
            result.set_commandstatus(pb::CS_REJECTED);
            result.set_errormessage(QStringLiteral("%1 is locked by user '%2' in another session")
                                        .arg(QString::fromStdString(vehicle->vehicle().name()), owner).toStdString());
        } else {
            for (const pb::Command *command : commands) {
                result = vehicle->execute(*command);
                if (result.commandstatus() != pb::CS_SUCCEEDED)
                    break;
            }
        }
        *response.add_commandresults() = std::move(result);
    }
    call.respond.reply(response);
}

void SimVehicleService::uploadRoute(SimCall &call)
{
    const auto &r = static_cast<const pb::UploadRouteRequest &>(call.request);
    SimVehicle *vehicle = m_s.world.vehicle(r.vehicle().id());
    if (!vehicle) {
        call.respond.error(QStringLiteral("Vehicle %1 does not exist").arg(r.vehicle().id()));
        return;
    }
    if (const QString owner = lockedBy(call, vehicle->id()); !owner.isEmpty()) {
        call.respond.error(QStringLiteral("%1 is locked by user '%2' in another session")
                               .arg(QString::fromStdString(vehicle->vehicle().name()), owner));
        return;
    }
    QString error;
    const auto plan = SimRouteProcessor::flightPlan(r.processedroute(), vehicle->model().state().groundElevation, &error);
    if (plan.empty()) {
        call.respond.error(error);
        return;
    }
    // The transfer takes a while, as to a real autopilot: one progress report per step, then the answer.
    const int steps = std::clamp(int(plan.size()), 4, 20);
    const QString title = QStringLiteral("Uploading route to %1").arg(QString::fromStdString(vehicle->vehicle().name()));
    const int vehicleId = vehicle->id();
    auto route = std::make_shared<pb::ProcessedRoute>(r.processedroute());
    const SimResponder respond = call.respond;
    SimWorld &world = m_s.world;
    for (int step = 0; step <= steps; ++step) {
        QTimer::singleShot(m_uploadStepMs * step, &call.connection, [=, &world] {
            respond.progress(title, step, steps);
            if (step < steps)
                return;
            SimVehicle *target = world.vehicle(vehicleId);
            const QString refusal = target ? target->upload(*route) : QStringLiteral("The vehicle is gone");
            if (refusal.isEmpty()) {
                world.routePasses().uploaded(*target, *route, SimWorld::now());
                respond.reply(pb::UploadRouteResponse());
            } else
                respond.error(refusal);
        });
    }
}

namespace {
// The route's own copy of its profile when it carries one, else the stored profile of that id.
const pb::VehicleProfile *routeProfile(const pb::Route &route, const SimObjectStore &store)
{
    if (route.vehicleprofile().parameters_size() > 0)
        return &route.vehicleprofile();
    const auto *stored = store.find(QStringLiteral("VehicleProfile"), route.vehicleprofile().id());
    return stored ? &stored->vehicleprofile() : nullptr;
}
}

void SimVehicleService::processRoute(SimCall &call)
{
    const auto &r = static_cast<const pb::ProcessRouteRequest &>(call.request);
    const auto &route = r.route();
    SimRouteLimits limits;
    if (const pb::VehicleProfile *profile = routeProfile(route, m_s.world.store())) {
        limits = SimRouteLimits::of(*profile);
        limits.cameras = profileCameras(*profile, &m_s.world.store());
    }
    pb::ProcessRouteResponse response;
    *response.mutable_processedroute() = SimRouteProcessor::process(route, limits, m_s.world.groundElevation());
    // The route itself goes back with its processing, as a UgCS server's does: an unsaved route
    // (the SDK's ExportRouteToWpml sample) is known to later requests only through it.
    *response.mutable_processedroute()->mutable_route() = route;
    const auto *storedProfile = m_s.world.store().find(QStringLiteral("VehicleProfile"), route.vehicleprofile().id());
    SimRouteTerrain::apply(*response.mutable_processedroute(), m_s.world.terrain(),
                           SimRouteTerrain::safeDistance(route.vehicleprofile(), storedProfile ? &storedProfile->vehicleprofile() : nullptr));
    SimRouteZones::apply(*response.mutable_processedroute(), route, m_s.world.store(), m_s.world.terrain());
    response.set_hash(SimRouteProcessor::hash(route));
    call.respond.reply(response);
}

// The values of an algorithm's selection parameters for a route: the cameras of the route's profile
// (value = payload profile id, as UgCS clients send it; the first is the default), and each other
// selection's choices from the catalog with its default marked. selectionId = the parameter's name.
void SimVehicleService::selectionValues(SimCall &call)
{
    const auto &r = static_cast<const pb::GetParametersSelectionValuesRequest &>(call.request);
    const QString className = QString::fromStdString(r.algorithm().implementationclass());
    const mission::AlgorithmDefinition *algorithm = mission::AlgorithmCatalog::builtIn().byClassName(className);
    if (!algorithm) {
        call.respond.error(QStringLiteral("The simulator has no algorithm '%1'").arg(className));
        return;
    }
    const pb::VehicleProfile *profile = routeProfile(r.route(), m_s.world.store());
    pb::GetParametersSelectionValuesResponse response;
    for (const mission::ParameterDefinition &p : algorithm->parameters) {
        if (p.type != mission::ParameterType::Selection)
            continue;
        auto *selection = response.add_selections();
        selection->set_selectionid(p.name.toStdString());
        if (p.name == QLatin1String("camera")) {
            const auto cameras = profile ? profileCameras(*profile, &m_s.world.store()) : std::vector<mission::ProfileCamera>{};
            for (size_t i = 0; i < cameras.size(); ++i) {
                auto *item = selection->add_items();
                item->set_value(std::to_string(cameras[i].id));
                item->set_description(cameras[i].camera.name.toStdString());
                item->set_markdefault(i == 0);
            }
            continue;
        }
        for (const mission::ParameterChoice &c : p.choices) {
            auto *item = selection->add_items();
            item->set_value(c.value.toStdString());
            item->set_description(c.displayName.toStdString());
            item->set_markdefault(c.value == p.defaultValue);
        }
    }
    call.respond.reply(response);
}

void SimVehicleService::telemetry(SimCall &call)
{
    const auto &r = static_cast<const pb::GetTelemetryRequest &>(call.request);
    const SimVehicle *vehicle = m_s.world.vehicle(r.vehicle().id());
    if (!vehicle) {
        call.respond.error(QStringLiteral("Vehicle %1 does not exist").arg(r.vehicle().id()));
        return;
    }
    pb::GetTelemetryResponse response;
    vehicle->telemetry().history(r.fromtime(), r.has_totime() ? r.totime() : SimWorld::now(), std::max(1, r.limit()), &response);
    call.respond.reply(response);
}

} // namespace sortie::sim
