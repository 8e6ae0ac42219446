#include "Camera.h"

#include "Domain.pb.h"

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

const std::vector<Camera> &builtInCameras()
{
    // Sensor width × height (mm), focal length (mm), pixels, shortest interval (s) where published.
    static const std::vector<Camera> cameras{
        {QStringLiteral("DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)"), 13.2, 8.8, 8.8, 5472, 3648, 0.0},
        {QStringLiteral("DJI Phantom 4 (FC330)"), 6.17, 4.55, 3.61, 4000, 3000, 0.0},
        {QStringLiteral("DJI Mavic 2 Pro (Hasselblad L1D-20c)"), 13.2, 8.8, 10.26, 5472, 3648, 0.0},
        {QStringLiteral("DJI Mavic 3 Enterprise (wide)"), 17.3, 13.0, 12.29, 5280, 3956, 0.7},
        {QStringLiteral("DJI Zenmuse P1 24 mm"), 35.9, 24.0, 24.0, 8192, 5460, 0.7},
        {QStringLiteral("DJI Zenmuse P1 35 mm"), 35.9, 24.0, 35.0, 8192, 5460, 0.7},
        {QStringLiteral("Sony RX1R II"), 35.9, 24.0, 35.0, 7952, 5304, 0.0},
        {QStringLiteral("senseFly S.O.D.A."), 13.2, 8.8, 10.6, 5472, 3648, 0.0},
        {QStringLiteral("MicaSense RedEdge-MX"), 4.8, 3.6, 5.4, 1280, 960, 1.0},
        {QStringLiteral("GoPro Hero3 Black Edition"), 6.17, 4.55, 2.8, 4000, 3000, 1.0},
    };
    return cameras;
}

std::optional<Camera> builtInCamera(const QString &name)
{
    for (const Camera &c : builtInCameras())
        if (c.name == name)
            return c;
    return std::nullopt;
}

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
