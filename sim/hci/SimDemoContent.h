#pragma once

#include <QList>
#include <QString>

namespace sortie::sim {

class SimObjectStore;
class SimUsers;

// The objects a fresh simulator offers, named like UgCS's emulator: the vehicle profiles of
// SimVehicleProfiles.h with their camera payloads, vehicles EMU-101, EMU-102, EMU-103 (profile "EMU Copter")
// near Riga, every traverse algorithm of Sortie's catalog, the users, and a demo mission with one route. Objects already in the store (loaded from a file) are kept, matched by name.
class SimDemoContent
{
public:
    struct VehicleHome
    {
        QString name;
        double latitude;  // degrees
        double longitude; // degrees
    };
    static QList<VehicleHome> vehicleHomes(int count);

    // Returns the object ids of the vehicles, in order.
    static QList<int> seed(SimObjectStore &store, const SimUsers &users, int vehicleCount, double groundElevation,
                           bool demoMission, qint64 nowMs);
};

} // namespace sortie::sim
