#include "SimDemoContent.h"

#include "Messages.pb.h"
#include "SimObjectStore.h"
#include "SimRouteProcessor.h"
#include "SimUsers.h"
#include "SimVehicleProfiles.h"

#include "AlgorithmProto.h"

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

// Every algorithm Sortie's catalog describes, as TraverseAlgorithm objects with their parameter definitions,
// so that clients build their editors from the server's description. Ones the store has are kept.
void seedAlgorithms(SimObjectStore &store, qint64 now)
{
    for (const mission::AlgorithmDefinition &definition : mission::AlgorithmCatalog::builtIn().algorithms()) {
        const std::string className = definition.className.toStdString();
        bool known = false;
        for (const auto *w : store.list(QStringLiteral("TraverseAlgorithm")))
            known = known || w->traversealgorithm().implementationclass() == className;
        if (known)
            continue;
        pb::DomainObjectWrapper w;
        *w.mutable_traversealgorithm() = mission::algorithmToProto(definition);
        for (auto &d : *w.mutable_traversealgorithm()->mutable_parameterdefinitions()) {
            d.set_id(store.allocateId());
            d.set_version(1);
        }
        store.save(QStringLiteral("TraverseAlgorithm"), w, now);
    }
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
    const int profileId = seedVehicleProfiles(store, simVehicleProfiles(), now).value(QStringLiteral("EMU Copter"));
    seedAlgorithms(store, now);
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
