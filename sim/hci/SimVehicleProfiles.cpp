#include "SimVehicleProfiles.h"

#include "CameraProto.h"
#include "Messages.pb.h"
#include "SimObjectStore.h"

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

std::vector<SimVehicleProfileSpec> emulatorProfiles()
{
    // UgCS's emulator profile carries a GoPro Hero3 Black (its demo data); the survey emulator a 1" 20 MP
    // mapping camera and a multispectral one, for photogrammetry at realistic heights.
    SimVehicleProfileSpec copter{QStringLiteral("EMU Copter"), QStringLiteral("emu-copter"), pb::VT_MULTICOPTER, 12, 4, 120, 2,
                                 {*mission::builtInCamera(QStringLiteral("GoPro Hero3 Black Edition"))}};
    SimVehicleProfileSpec survey{QStringLiteral("EMU Survey Copter"), QStringLiteral("emu-survey-copter"), pb::VT_MULTICOPTER, 15, 5, 120, 2,
                                 {*mission::builtInCamera(QStringLiteral("DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)")),
                                  *mission::builtInCamera(QStringLiteral("MicaSense RedEdge-MX"))}};
    return {copter, survey};
}

std::vector<SimVehicleProfileSpec> simVehicleProfiles()
{
    std::vector<SimVehicleProfileSpec> all;
    for (auto family : {emulatorProfiles})
        for (auto &p : family())
            all.push_back(std::move(p));
    return all;
}

namespace {

template<class Get>
int findByName(const SimObjectStore &store, const char *type, const std::string &name, Get get)
{
    for (const auto *w : store.list(QString::fromLatin1(type)))
        if (get(*w).name() == name)
            return get(*w).id();
    return -1;
}

int seedPayload(SimObjectStore &store, const mission::Camera &camera, qint64 now)
{
    const std::string name = camera.name.toStdString();
    if (int id = findByName(store, "PayloadProfile", name, [](const auto &w) -> const auto & { return w.payloadprofile(); }); id >= 0)
        return id;
    pb::DomainObjectWrapper w;
    *w.mutable_payloadprofile() = mission::payloadFromCamera(camera);
    w.mutable_payloadprofile()->set_sealed(true);
    for (auto &p : *w.mutable_payloadprofile()->mutable_parameters()) {
        p.set_id(store.allocateId());
        p.set_version(1);
    }
    return store.save(QStringLiteral("PayloadProfile"), w, now).object->payloadprofile().id();
}

void addParameter(pb::VehicleProfile &p, int id, pb::VehicleParameterType type, double value)
{
    auto *v = p.add_parameters();
    v->set_id(id);
    v->set_version(1);
    v->set_type(type);
    v->set_value(value);
}

} // namespace

QMap<QString, int> seedVehicleProfiles(SimObjectStore &store, const std::vector<SimVehicleProfileSpec> &profiles, qint64 now)
{
    QMap<QString, int> ids;
    for (const SimVehicleProfileSpec &spec : profiles) {
        const std::string name = spec.name.toStdString();
        if (int id = findByName(store, "VehicleProfile", name, [](const auto &w) -> const auto & { return w.vehicleprofile(); }); id >= 0) {
            ids.insert(spec.name, id);
            continue;
        }
        pb::DomainObjectWrapper w;
        auto *p = w.mutable_vehicleprofile();
        p->set_name(name);
        p->set_vehicletype(spec.type);
        p->set_code(spec.code.toStdString());
        p->set_sealed(true);
        addParameter(*p, store.allocateId(), pb::VPT_MAX_HORIZONTAL_SPEED, spec.maxHorizontalSpeed);
        addParameter(*p, store.allocateId(), pb::VPT_MAX_CLIMB_RATE, spec.maxClimbRate);
        addParameter(*p, store.allocateId(), pb::VPT_MAX_ALTITUDE_AGL, spec.maxAltitudeAgl);
        addParameter(*p, store.allocateId(), pb::VPT_WAYPOINT_ACCEPTANCE_RADIUS, spec.acceptanceRadius);
        for (const mission::Camera &camera : spec.cameras) {
            const int payloadId = seedPayload(store, camera, now);
            auto *link = p->add_payloadprofiles();
            link->set_id(store.allocateId());
            link->set_version(1);
            *link->mutable_payloadprofile() = store.find(QStringLiteral("PayloadProfile"), payloadId)->payloadprofile();
        }
        ids.insert(spec.name, store.save(QStringLiteral("VehicleProfile"), w, now).object->vehicleprofile().id());
    }
    return ids;
}

std::vector<mission::ProfileCamera> profileCameras(const pb::VehicleProfile &profile, const SimObjectStore *store)
{
    return mission::profileCameras(profile, [store](int id) -> const pb::PayloadProfile * {
        const auto *stored = store ? store->find(QStringLiteral("PayloadProfile"), id) : nullptr;
        return stored ? &stored->payloadprofile() : nullptr;
    });
}

} // namespace sortie::sim
