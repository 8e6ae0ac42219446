#pragma once

#include "Camera.h"

#include <functional>
#include <optional>
#include <vector>

namespace com::ugcs::ucs::proto {
class PayloadProfile;
class VehicleProfile;
}

namespace sortie::mission {

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
