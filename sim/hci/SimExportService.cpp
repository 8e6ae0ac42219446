#include "SimExportService.h"

#include "DjiDroneModels.h"
#include "HciRequestDispatcher.h"
#include "HciRouteMapper.h"
#include "Messages.pb.h"
#include "ProcessedPlan.h"
#include "SimLog.h"
#include "SimWorld.h"
#include "WpmlFormat.h"

namespace sortie::sim {

using namespace sortie::mission;
using namespace sortie::mission::formats;

SimExportService::SimExportService(SimServices services)
    : m_s(services)
{
}

void SimExportService::install(HciRequestDispatcher &d)
{
    d.add(pb::ExportRouteToWpmlRequest::default_instance(), HciRequestDispatcher::Access::LoggedIn,
          [this](SimCall &c) { exportRouteToWpml(c); });
}

void SimExportService::exportRouteToWpml(SimCall &call)
{
    const auto &r = static_cast<const pb::ExportRouteToWpmlRequest &>(call.request);
    const pb::ProcessedRoute &processed = r.route();
    const pb::Route &planned = processed.route();

    std::string profileName = planned.vehicleprofile().name();
    if (profileName.empty())
        if (const auto *stored = m_s.world.store().find(QStringLiteral("VehicleProfile"), planned.vehicleprofile().id()))
            profileName = stored->vehicleprofile().name();
    const DjiDroneModel *model = findDjiDroneModel(QString::fromStdString(profileName));
    if (!model) {
        call.respond.error(QStringLiteral("WPML is for DJI aircraft: the route's vehicle profile \"%1\" is not one (use %2)")
                               .arg(QString::fromStdString(profileName), djiDroneKeys()));
        return;
    }

    const Result<HciRouteImport> imported = routeFromHci(planned);
    if (!imported) {
        call.respond.error(QStringLiteral("The route cannot be read: %1").arg(imported.error().toString()));
        return;
    }
    const Route &plannedRoute = imported->route;
    const ProcessedPlan plan = processedPlanFromHci(processed, &plannedRoute);
    if (!plan.flyable() || plan.waypoints.empty()) {
        call.respond.error(QStringLiteral("The route is not processed: send ProcessRouteRequest and export its result"));
        return;
    }

    // The flown path, AMSL, with the planned waypoints' actions on the first point of their segment.
    Route route;
    route.settings = plannedRoute.settings;
    double speed = plannedRoute.settings.initialSpeed > 0 ? plannedRoute.settings.initialSpeed : 5.0;
    for (size_t i = 0; i < plan.waypoints.size(); ++i) {
        const ProcessedWaypoint &pw = plan.waypoints[i];
        if (pw.speed > 0)
            speed = pw.speed;
        Waypoint w;
        w.position = pw.position;
        w.altitude = pw.altitudeAmsl;
        w.altitudeType = AltitudeType::Amsl;
        w.speed = speed;
        w.turnType = pw.turnType;
        w.acceptanceRadius = pw.acceptanceRadius;
        w.role = pw.role;
        const ProcessedSegment &segment = plan.segments[size_t(pw.segment)];
        if (int(i) == segment.firstWaypoint && segment.routeRow >= 0 && size_t(segment.routeRow) < plannedRoute.segments.size())
            if (const Waypoint *source = asWaypoint(plannedRoute.segments[size_t(segment.routeRow)]))
                w.actions = source->actions;
        route.segments.push_back(std::move(w));
    }

    WpmlExportOptions options;
    options.drone = model->key;
    options.heightMode = r.altitudemode() == pb::W_AMSL ? WpmlHeightMode::Egm96 : WpmlHeightMode::RelativeToTakeoff;
    options.takeoffAltitudeAmsl = plan.waypoints.front().groundElevation;
    options.climbOver = plan.waypoints.front().position;
    options.timestampMs = SimWorld::now();
    const Result<WpmlExport> out = writeWpml(route, options);
    if (!out) {
        call.respond.error(out.error().message);
        return;
    }
    qCInfo(lcSim).noquote() << "exported a route as WPML for" << model->name << "-" << out->waypointCount << "waypoints,"
                            << out->kmz.size() << "bytes";
    pb::ExportRouteToWpmlResponse response;
    response.set_routedata(out->kmz.toStdString());
    call.respond.reply(response);
}

} // namespace sortie::sim
