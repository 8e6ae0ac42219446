#pragma once

#include <QString>

#include <optional>
#include <vector>
#include <QCoreApplication>

namespace sortie::mission {

// A survey camera. Sizes in millimetres, as camera makers publish them (UgCS's payload profiles
// carry metres: see CameraProto.h). With the camera's top facing forward the image's width
// runs across the flight direction and its height along it.
struct Camera
{
    QString name = QCoreApplication::translate("Camera", "Generic 1\" 20 MP");
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

// The camera the `camera` value names among the profile's (by id, then by name), then among the
// built-in cameras by name; an empty value takes the profile's first camera.
std::optional<Camera> resolveCamera(const QString &value, const std::vector<ProfileCamera> &cameras);

} // namespace sortie::mission
