#include "CameraProto.h"

#include "Domain.pb.h"

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

std::optional<Camera> cameraFromPayload(const pb::PayloadProfile &payload)
{
    if (payload.has_payloadtype() && payload.payloadtype() != pb::PT_CAMERA)
        return std::nullopt;
    Camera c;
    c.name = QString::fromStdString(payload.name());
    c.minTriggerIntervalS = 0;
    int found = 0;
    for (const auto &p : payload.parameters()) {
        switch (p.type()) {
        case pb::PPT_TRUE_FOCAL_LENGTH: c.focalLengthMm = p.value() * 1000.0; found |= 1; break;
        case pb::PPT_SENSOR_WIDTH: c.sensorWidthMm = p.value() * 1000.0; found |= 2; break;
        case pb::PPT_SENSOR_HEIGHT: c.sensorHeightMm = p.value() * 1000.0; found |= 4; break;
        case pb::PPT_SENSOR_HORIZONTAL_PIXELS: c.imageWidthPx = int(p.value()); found |= 8; break;
        case pb::PPT_SENSOR_VERTICAL_PIXELS: c.imageHeightPx = int(p.value()); found |= 16; break;
        case pb::PPT_MIN_TRIGGERING_INTERVAL: c.minTriggerIntervalS = p.value(); break;
        default: break;
        }
    }
    if (found != 31 || !c.isValid())
        return std::nullopt;
    return c;
}

std::vector<ProfileCamera> profileCameras(const pb::VehicleProfile &profile, const std::function<const pb::PayloadProfile *(int)> &find)
{
    std::vector<ProfileCamera> out;
    for (const auto &link : profile.payloadprofiles()) {
        const pb::PayloadProfile *payload = &link.payloadprofile();
        if (payload->parameters_size() == 0 && find)
            if (const pb::PayloadProfile *found = find(payload->id()))
                payload = found;
        if (const std::optional<Camera> camera = cameraFromPayload(*payload))
            out.push_back({payload->id(), *camera});
    }
    return out;
}

pb::PayloadProfile payloadFromCamera(const Camera &camera, int id)
{
    pb::PayloadProfile out;
    if (id)
        out.set_id(id);
    out.set_name(camera.name.toStdString());
    out.set_payloadtype(pb::PT_CAMERA);
    auto add = [&](pb::PayloadParameterType type, double value) {
        auto *p = out.add_parameters();
        p->set_type(type);
        p->set_value(value);
    };
    add(pb::PPT_TRUE_FOCAL_LENGTH, camera.focalLengthMm / 1000.0);
    add(pb::PPT_SENSOR_WIDTH, camera.sensorWidthMm / 1000.0);
    add(pb::PPT_SENSOR_HEIGHT, camera.sensorHeightMm / 1000.0);
    add(pb::PPT_SENSOR_HORIZONTAL_PIXELS, camera.imageWidthPx);
    add(pb::PPT_SENSOR_VERTICAL_PIXELS, camera.imageHeightPx);
    if (camera.minTriggerIntervalS > 0)
        add(pb::PPT_MIN_TRIGGERING_INTERVAL, camera.minTriggerIntervalS);
    return out;
}

} // namespace sortie::mission
