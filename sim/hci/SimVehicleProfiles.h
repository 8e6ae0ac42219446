#pragma once

#include "Domain.pb.h"
#include "SegmentPlanner.h"

#include <QMap>
#include <QString>

#include <vector>

namespace sortie::sim {

class SimObjectStore;

// A vehicle profile the simulator offers, with the camera payloads it carries (as UgCS's emulator
// profile carries a GoPro Hero3 Black, so photogrammetry can be planned against it).
struct SimVehicleProfileSpec
{
    QString name;
    QString code;
    com::ugcs::ucs::proto::VehicleType type = com::ugcs::ucs::proto::VT_MULTICOPTER;
    double maxHorizontalSpeed = 12;  // m/s
    double maxClimbRate = 4;         // m/s
    double maxAltitudeAgl = 120;     // m
    double acceptanceRadius = 2;     // m
    std::vector<mission::Camera> cameras;
};

// The profiles by family, each family in its own function and file; simVehicleProfiles() lists every
// family, so adding one is a function and a line there.
std::vector<SimVehicleProfileSpec> emulatorProfiles();
std::vector<SimVehicleProfileSpec> simVehicleProfiles();

// Saves the profiles and their payload profiles (PayloadProfile objects, linked from each
// VehicleProfile.payloadProfiles) that the store lacks, matched by name. Returns profile ids by name.
QMap<QString, int> seedVehicleProfiles(SimObjectStore &store, const std::vector<SimVehicleProfileSpec> &profiles, qint64 nowMs);

// The profile's camera payloads with their ids, the form route processing resolves `camera` against.
// Links that carry only a payload id are looked up in `store` when one is given.
std::vector<mission::ProfileCamera> profileCameras(const com::ugcs::ucs::proto::VehicleProfile &profile,
                                                   const SimObjectStore *store = nullptr);

} // namespace sortie::sim
