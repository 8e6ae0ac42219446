#include "SimRoutePasses.h"

#include "Messages.pb.h"
#include "SimLog.h"
#include "SimObjectStore.h"
#include "SimVehicle.h"

namespace sortie::sim {
namespace {

const QString kRoutePass = QStringLiteral("RoutePass");
constexpr double kRad = 3.14159265358979323846 / 180.0;

} // namespace

SimRoutePasses::SimRoutePasses(SimObjectStore &store)
    : m_store(store)
{
}

void SimRoutePasses::clearStale()
{
    for (const pb::DomainObjectWrapper *w : m_store.list(kRoutePass))
        m_store.remove(kRoutePass, w->routepass().id());
    m_passes.clear();
}

void SimRoutePasses::remove(int vehicleId)
{
    const auto it = m_passes.find(vehicleId);
    if (it == m_passes.end())
        return;
    m_store.remove(kRoutePass, it->second.objectId);
    m_passes.erase(it);
}

void SimRoutePasses::uploaded(const SimVehicle &vehicle, const pb::ProcessedRoute &route, qint64 nowMs)
{
    remove(vehicle.id());
    pb::DomainObjectWrapper wrapper;
    pb::RoutePass *pass = wrapper.mutable_routepass();
    *pass->mutable_vehicle() = vehicle.reference();
    if (route.route().has_id())
        pass->mutable_route()->set_id(route.route().id());
    if (route.route().has_name())
        pass->mutable_route()->set_name(route.route().name());
    pass->set_uploadtime(nowMs);
    pass->set_waypointcount(int(vehicle.model().mission().size()));
    if (!route.modificationuuid().empty())
        pass->set_routemodificationuuid(route.modificationuuid());
    const auto saved = m_store.save(kRoutePass, wrapper, nowMs);
    if (!saved.object) {
        qCWarning(lcSim).noquote() << "cannot keep the route pass:" << saved.error;
        return;
    }
    m_passes[vehicle.id()] = {saved.object->routepass().id(), -1, vehicle.model().missionVersion()};
}

void SimRoutePasses::follow(const SimVehicle &vehicle)
{
    const auto it = m_passes.find(vehicle.id());
    if (it == m_passes.end())
        return;
    Pass &pass = it->second;
    const FlightModel &model = vehicle.model();
    const FlightModel::State &s = model.state();
    if (model.missionVersion() != pass.missionVersion || s.missionComplete) {
        remove(vehicle.id()); // fully processed (or no longer on board)
        return;
    }
    if (s.currentWaypoint < 0 || s.currentWaypoint == pass.waypointIndex || s.currentWaypoint >= int(model.mission().size()))
        return;
    const pb::DomainObjectWrapper *stored = m_store.find(kRoutePass, pass.objectId);
    if (!stored) { // deleted over HCI by someone
        m_passes.erase(it);
        return;
    }
    pb::DomainObjectWrapper wrapper = *stored;
    pb::RoutePass *object = wrapper.mutable_routepass();
    const FlightModel::Waypoint &w = model.mission()[size_t(s.currentWaypoint)];
    object->set_waypointindex(s.currentWaypoint);
    object->set_latitude(w.latitude * kRad);
    object->set_longitude(w.longitude * kRad);
    object->set_altitude(s.groundElevation + w.altitudeAgl);
    const auto saved = m_store.save(kRoutePass, wrapper, object->uploadtime());
    if (!saved.object) {
        qCWarning(lcSim).noquote() << "cannot update the route pass:" << saved.error;
        return;
    }
    pass.waypointIndex = s.currentWaypoint;
}

} // namespace sortie::sim
