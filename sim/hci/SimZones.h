#pragma once

#include "HciProto.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class SimObjectStore;

// The simulator's no-fly zones: NoFlightZone objects in the store, written as a UgCS server holds
// them (radians, metres, a Prism or a ConeFrustum). Aerodrome zones (NT_AERODROME) are the
// server's own data: two near the demo area, "RIX CTR" (a cone frustum over Riga airport, 5 km
// at 0 m AMSL widening to 8 km at 600 m AMSL) and "Spilve airfield" (a prism from the ground to
// 150 m AGL, 0.9 km north of the demo route). With the demo content, one custom zone (NT_CUSTOM)
// "Crane works", from the ground to 60 m AGL east of the demo route. Zones already in the store
// (a store file) are kept, matched by name.
class SimZones
{
public:
    static const QString kType;  // "NoFlightZone"

    // A box in radians, as GetNfzListRequest and EnvironmentEvent carry it.
    struct Box
    {
        double minLatitude, minLongitude, maxLatitude, maxLongitude;
        bool meets(const Box &o) const
        {
            return minLatitude <= o.maxLatitude && o.minLatitude <= maxLatitude && minLongitude <= o.maxLongitude
                && o.minLongitude <= maxLongitude;
        }
    };

    static void seed(SimObjectStore &store, bool demoContent, qint64 nowMs);
    // The zone's horizontal extent; nullopt when it has no usable shape.
    static std::optional<Box> boxOf(const pb::NoFlightZone &zone);
    // The zones of the given types (none: every type) whose extent meets the box.
    static std::vector<const pb::NoFlightZone *> list(const SimObjectStore &store, const Box &box, const std::vector<int> &types);
    // Why a client may not create, change (`incoming`) or delete (none) zone `id` (-1: a new one);
    // empty when it may. Aerodrome zones are refused, and so is a zone that is not a usable volume.
    static QString writeRefusal(const SimObjectStore &store, int id, const pb::NoFlightZone *incoming);
};

} // namespace sortie::sim
