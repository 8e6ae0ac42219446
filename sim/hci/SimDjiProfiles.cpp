#include "SimDjiProfiles.h"

#include "DjiDroneModels.h"
#include "Messages.pb.h"
#include "SimObjectStore.h"
#include "WpmlFormat.h"

namespace sortie::sim {
namespace {

namespace pb = com::ugcs::ucs::proto;
using mission::formats::DjiDroneModel;

bool exists(const SimObjectStore &store, const std::string &name)
{
    for (const auto *w : store.list(QStringLiteral("VehicleProfile")))
        if (w->vehicleprofile().name() == name)
            return true;
    return false;
}

void add(pb::VehicleProfile &p, SimObjectStore &store, pb::VehicleParameterType type, double value)
{
    auto *v = p.add_parameters();
    v->set_id(store.allocateId());
    v->set_version(1);
    v->set_type(type);
    v->set_value(value);
}

} // namespace

void SimDjiProfiles::seed(SimObjectStore &store, qint64 nowMs)
{
    for (const char *key : {"m350", "m3e"}) {
        const DjiDroneModel &m = *mission::formats::findDjiDroneModel(QLatin1String(key));
        const std::string name = m.name.toStdString();
        if (exists(store, name))
            continue;
        pb::DomainObjectWrapper w;
        auto *p = w.mutable_vehicleprofile();
        p->set_name(name);
        p->set_vehicletype(pb::VT_MULTICOPTER);
        p->set_code(("dji-" + m.key).toStdString());
        p->set_sealed(true);
        p->mutable_platform()->set_code(("dji-" + m.key).toStdString());
        p->mutable_platform()->set_name(name);
        p->mutable_platform()->set_autopilottype("DJI");
        add(*p, store, pb::VPT_MAX_HORIZONTAL_SPEED, m.maxHorizontalSpeed);
        add(*p, store, pb::VPT_DEFAULT_HORIZONTAL_SPEED, 5.0);
        add(*p, store, pb::VPT_MAX_CLIMB_RATE, m.maxClimbRate);
        add(*p, store, pb::VPT_DEFAULT_CLIMB_RATE, 3.0);
        add(*p, store, pb::VPT_DEFAULT_DESCENT_RATE, std::min(3.0, m.maxDescentRate));
        add(*p, store, pb::VPT_MAX_ALTITUDE_AGL, m.maxAltitudeLimit);
        add(*p, store, pb::VPT_MAX_WAYPOINTS, mission::formats::kWpmlMaxWaypoints);
        add(*p, store, pb::VPT_WAYPOINT_ACCEPTANCE_RADIUS, 1.0);
        store.save(QStringLiteral("VehicleProfile"), w, nowMs);
    }
}

} // namespace sortie::sim
