#pragma once

#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace com::ugcs::ucs::proto {
class PayloadProfile;
class VehicleProfile;
}

namespace sortie::mission {

// A survey camera. Sizes in millimetres, as camera makers publish them (UgCS's payload profiles
// carry metres: see cameraFromPayload). With the camera's top facing forward the image's width
// runs across the flight direction and its height along it.
struct Camera
{
    QString name = QStringLiteral("Generic 1\" 20 MP");
    double sensorWidthMm = 13.2;
    double sensorHeightMm = 8.8;
    double focalLengthMm = 8.8;
    int imageWidthPx = 5472;
    int imageHeightPx = 3648;
    double minTriggerIntervalS = 0.0;  // shortest time between two photos; 0 = not known

    // Positive sensor size, focal length and resolution: what photogrammetry needs.
    bool isValid() const
    {
        return sensorWidthMm > 0 && sensorHeightMm > 0 && focalLengthMm > 0 && imageWidthPx > 0 && imageHeightPx > 0;
    }
    bool operator==(const Camera &) const = default;
};

// A camera payload of a vehicle profile, as a segment's `camera` parameter names it (by id or name).
struct ProfileCamera
{
    int id = 0;
    Camera camera;
    bool operator==(const ProfileCamera &) const = default;
};

// Common survey cameras with their makers' published sensor size, focal length and resolution.
const std::vector<Camera> &builtInCameras();
// The built-in camera of that name, if any.
std::optional<Camera> builtInCamera(const QString &name);

// The camera a UgCS payload profile describes (PT_CAMERA with focal length, sensor size and
// resolution; PPT_* values in SI metres and seconds), or nullopt when it is not a complete camera.
std::optional<Camera> cameraFromPayload(const com::ugcs::ucs::proto::PayloadProfile &payload);
// The complete cameras among a vehicle profile's payloads, in its order (the first is the default
// a segment without `camera` flies). A payload link carrying only an id is looked up with `find`.
std::vector<ProfileCamera> profileCameras(const com::ugcs::ucs::proto::VehicleProfile &profile,
                                          const std::function<const com::ugcs::ucs::proto::PayloadProfile *(int id)> &find = {});
// The payload profile a server lists for a camera (metres, PT_CAMERA).
com::ugcs::ucs::proto::PayloadProfile payloadFromCamera(const Camera &camera, int id = 0);

} // namespace sortie::mission
