#include "SimDemoContent.h"

#include "Messages.pb.h"
#include "SimObjectStore.h"
#include "SimRouteProcessor.h"
#include "SimUsers.h"

namespace sortie::sim {
namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;

template<class Get>
int findByName(const SimObjectStore &store, const char *type, const std::string &name, Get get)
{
    for (const auto *w : store.list(QString::fromLatin1(type)))
        if (get(*w).name() == name)
            return get(*w).id();
    return -1;
}

void addParameter(pb::VehicleProfile &p, int id, pb::VehicleParameterType type, double value)
{
    auto *v = p.add_parameters();
    v->set_id(id);
    v->set_version(1);
    v->set_type(type);
    v->set_value(value);
}

void addDefinition(pb::TraverseAlgorithm &a, int id, const char *name, pb::ParameterType type, const char *value,
                   pb::PhysicalSemantic semantic, bool mandatory)
{
    auto *d = a.add_parameterdefinitions();
    d->set_id(id);
    d->set_version(1);
    d->set_name(name);
    d->set_type(type);
    d->set_defaultvalue(value);
    d->set_physicalsemantic(semantic);
    d->set_mandatory(mandatory);
    d->set_category(pb::PG_BASIC);
}

pb::SegmentDefinition waypointSegment(double latDeg, double lonDeg, double agl, const char *speed)
{
    pb::SegmentDefinition s;
    s.set_algorithmclassname(SimRouteProcessor::kWaypointAlgorithm);
    s.mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(latDeg * kRad);
    p->set_longitude(lonDeg * kRad);
    p->set_aglaltitude(agl);
    p->set_altitudetype(pb::AT_AGL);
    for (const auto &[name, value] : {std::pair{"speed", speed}, {"wpTurnType", "STOP_AND_TURN"}, {"avoidObstacles", "true"},
                                      {"avoidTerrain", "true"}, {"altitudeType", "AGL"}}) {
        auto *v = s.add_parametervalues();
        v->set_name(name);
        v->set_value(value);
    }
    return s;
}

int seedProfile(SimObjectStore &store, qint64 now)
{
    if (int id = findByName(store, "VehicleProfile", "EMU Copter", [](const auto &w) -> const auto & { return w.vehicleprofile(); }); id >= 0)
        return id;
    pb::DomainObjectWrapper w;
    auto *p = w.mutable_vehicleprofile();
    p->set_name("EMU Copter");
    p->set_vehicletype(pb::VT_MULTICOPTER);
    p->set_code("emu-copter");
    p->set_sealed(true);
    addParameter(*p, store.allocateId(), pb::VPT_MAX_HORIZONTAL_SPEED, 12.0);
    addParameter(*p, store.allocateId(), pb::VPT_MAX_CLIMB_RATE, 4.0);
    addParameter(*p, store.allocateId(), pb::VPT_MAX_ALTITUDE_AGL, 120.0);
    addParameter(*p, store.allocateId(), pb::VPT_WAYPOINT_ACCEPTANCE_RADIUS, 2.0);
    return store.save(QStringLiteral("VehicleProfile"), w, now).object->vehicleprofile().id();
}

void seedAlgorithm(SimObjectStore &store, qint64 now)
{
    if (findByName(store, "TraverseAlgorithm", "Waypoint", [](const auto &w) -> const auto & { return w.traversealgorithm(); }) >= 0)
        return;
    pb::DomainObjectWrapper w;
    auto *a = w.mutable_traversealgorithm();
    a->set_name("Waypoint");
    a->set_code("Waypoint");
    a->set_implementationclass(SimRouteProcessor::kWaypointAlgorithm);
    a->set_figuretype(pb::FT_POINT);
    a->set_selectfigure(false);
    addDefinition(*a, store.allocateId(), "speed", pb::PT_DOUBLE, "5.0", pb::PS_SPEED, true);
    addDefinition(*a, store.allocateId(), "wpTurnType", pb::PT_SELECTION, "STOP_AND_TURN", pb::PS_NONE, true);
    addDefinition(*a, store.allocateId(), "avoidObstacles", pb::PT_BOOLEAN, "true", pb::PS_NONE, false);
    addDefinition(*a, store.allocateId(), "avoidTerrain", pb::PT_BOOLEAN, "true", pb::PS_NONE, false);
    addDefinition(*a, store.allocateId(), "altitudeType", pb::PT_SELECTION, "AGL", pb::PS_NONE, true);
    addDefinition(*a, store.allocateId(), "cornerRadius", pb::PT_DOUBLE, "", pb::PS_DISTANCE, false);
    store.save(QStringLiteral("TraverseAlgorithm"), w, now);
}

} // namespace

QList<SimDemoContent::VehicleHome> SimDemoContent::vehicleHomes(int count)
{
    // Riga, around the port's north pier; further vehicles line up 150 m apart.
    QList<VehicleHome> homes = {{QStringLiteral("EMU-101"), 56.97620, 24.07300},
                                {QStringLiteral("EMU-102"), 56.97500, 24.07700},
                                {QStringLiteral("EMU-103"), 56.97750, 24.07900}};
    for (int i = int(homes.size()); i < count; ++i)
        homes.append({QStringLiteral("EMU-%1").arg(101 + i), 56.9740 - 0.00135 * (i - 2), 24.0700});
    return homes.mid(0, count);
}

QList<int> SimDemoContent::seed(SimObjectStore &store, const SimUsers &users, int vehicleCount, double ground,
                                bool demoMission, qint64 now)
{
    for (const SimUser &u : users.all()) {
        pb::DomainObjectWrapper w;
        auto *user = w.mutable_user();
        user->set_id(u.id);
        user->set_version(1);
        user->set_login(u.login.toStdString());
        user->set_role(u.administrator ? pb::UR_ADMINISTRATOR : pb::UR_OPERATOR);
        store.insert(QStringLiteral("User"), w);
    }
    const int profileId = seedProfile(store, now);
    seedAlgorithm(store, now);
    const auto *profile = store.find(QStringLiteral("VehicleProfile"), profileId);

    QList<int> ids;
    const auto homes = vehicleHomes(vehicleCount);
    for (int i = 0; i < homes.size(); ++i) {
        const std::string name = homes[i].name.toStdString();
        int id = findByName(store, "Vehicle", name, [](const auto &w) -> const auto & { return w.vehicle(); });
        if (id < 0) {
            pb::DomainObjectWrapper w;
            auto *v = w.mutable_vehicle();
            v->set_vehicleid(3405691582LL + i);
            v->set_name(name);
            v->set_tailnumber(name);
            v->set_type(pb::VT_MULTICOPTER);
            v->set_altitudeorigin(ground);
            auto *platform = v->mutable_platform();
            platform->set_code("emu-copter");
            platform->set_name("Emulator Copter");
            platform->set_autopilottype("EMULATOR");
            *v->mutable_profile() = profile->vehicleprofile();
            v->set_emulator(true);
            v->set_serialnumber(name + "-0001");
            v->set_source(pb::VS_VSM);
            id = store.save(QStringLiteral("Vehicle"), w, now).object->vehicle().id();
        }
        ids.append(id);
    }

    if (demoMission && findByName(store, "Mission", "Riga port survey", [](const auto &w) -> const auto & { return w.mission(); }) < 0) {
        pb::DomainObjectWrapper m;
        m.mutable_mission()->set_name("Riga port survey");
        m.mutable_mission()->set_description("Quay inspection, north pier (simulator demo)");
        m.mutable_mission()->mutable_owner()->set_id(users.all().value(0).id);
        const auto mission = store.save(QStringLiteral("Mission"), m, now).object;
        pb::DomainObjectWrapper r;
        auto *route = r.mutable_route();
        route->set_name("Riga port - 4 WP");
        route->mutable_mission()->set_id(mission->mission().id());
        route->mutable_vehicleprofile()->set_id(profileId);
        route->set_safealtitude(30);
        route->set_maxaltitude(120);
        route->set_initialspeed(5);
        route->set_maxspeed(10);
        route->set_checkaerodromenfz(true);
        route->set_checkcustomnfz(false);
        *route->add_segments() = waypointSegment(56.97650, 24.07350, 40, "5.0");
        *route->add_segments() = waypointSegment(56.97800, 24.07600, 50, "6.0");
        *route->add_segments() = waypointSegment(56.97700, 24.07950, 50, "6.0");
        *route->add_segments() = waypointSegment(56.97580, 24.07500, 40, "5.0");
        store.save(QStringLiteral("Route"), r, now);
    }
    return ids;
}

} // namespace sortie::sim
