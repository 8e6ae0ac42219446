#pragma once

#include "FlightLog.h"
#include "VehicleTypes.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::flightlog {

// A photo in the flight log: an event of kind "photo" at the photo's time (the vehicle's clock),
// its text the photo as one JSON object (docs/flightlog.md, "Photo events"): {"sequence": 12,
// "latitude": deg, "longitude": deg, "altitudeAmsl": m, "altitudeAgl": m, "roll": deg, "pitch": deg,
// "yaw": deg, "gimbalTilt": deg}; a value the vehicle did not report is left out.
inline constexpr const char *kPhotoEventKind = "photo";

QString photoEventText(const vehicle::CameraPhoto &photo);
// The photo an event holds; nullopt for another kind, or a text that is no photo (no sequence or no
// finite position).
std::optional<vehicle::CameraPhoto> photoOfEvent(const FlightLog::Event &event);
// Every photo event of a vehicle (its index in the log), in time order.
std::vector<vehicle::CameraPhoto> photosOf(const FlightLog &log, int vehicle);

} // namespace sortie::flightlog
