#pragma once

#include <QtGlobal>

namespace sortie::sim {

class SimObjectStore;

// The DJI vehicle profiles a UgCS server offers beside its emulators, named as UgCS names them
// ("DJI Matrice 350 RTK", "DJI Mavic 3 Enterprise"): platform DJI, the airframe's limits (speed,
// climb and descent rates, altitude limit, waypoint count, acceptance radius) from the same
// catalogue the WPML export checks routes against (DjiDroneModels). ProcessRoute checks a route
// planned for one against them, and ExportRouteToWpml writes it for that aircraft. Profiles already
// in the store (loaded from a file) are kept, matched by name.
class SimDjiProfiles
{
public:
    static void seed(SimObjectStore &store, qint64 nowMs);
};

} // namespace sortie::sim
