#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

// A photo the vehicle's camera took, as Sortie's VCI profile reports it on /camera/photo
// (docs/vci-profile.md, "Camera"): the last one, notified as each is taken, null before the first.
namespace sortie::vci::profile {

struct Photo
{
    int64_t sequence = 0;   // 1, 2, 3 ... since the vehicle started: a gap says photos were not heard of
    int64_t time = 0;       // ms since the epoch, the vehicle's clock, when the shutter opened
    double latitude = 0;    // radians
    double longitude = 0;   // radians
    // What the vehicle knows of how it stood; a value it does not know is absent, never 0.
    std::optional<double> altitudeAmsl; // m
    std::optional<double> altitudeAgl;  // m above the ground under it
    std::optional<double> roll, pitch, yaw; // radians, as /telemetry/attitude
    std::optional<double> gimbalTilt;   // radians: pi/2 looks straight down, 0 ahead (UgCS's convention)
    bool operator==(const Photo &) const = default;
};

nlohmann::json encodePhoto(const Photo &photo);
// The photo, or nullopt with the reason in *error (naming the key) when the body is not one: a
// sequence that is not a whole number from 1, no time, a position off the globe, a value that is not
// a finite number. Null (no photo yet) is nullopt with an empty error.
std::optional<Photo> decodePhoto(const nlohmann::json &body, std::string *error);

} // namespace sortie::vci::profile
