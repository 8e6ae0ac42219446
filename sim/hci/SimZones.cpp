#include "SimZones.h"

#include "Messages.pb.h"
#include "NfzConversion.h"
#include "SimObjectStore.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::sim {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kEarthRadius = 6371008.8;  // metres: mean radius, enough for a box

struct Corner
{
    double latitude, longitude;  // degrees
};

pb::NoFlightZone prismZone(const char *name, pb::NfzType type, const std::vector<Corner> &corners, pb::AltitudeType altitudeType,
                           double base, double height)
{
    pb::NoFlightZone z;
    z.set_name(name);
    z.set_type(type);
    auto *prism = z.mutable_prism();
    for (const Corner &c : corners) {
        auto *p = prism->add_points();
        p->set_latitude(c.latitude * kRad);
        p->set_longitude(c.longitude * kRad);
    }
    prism->set_altitudetype(altitudeType);
    prism->set_basealtitude(base);
    prism->set_height(height);
    return z;
}

pb::NoFlightZone coneZone(const char *name, Corner center, double baseRadius, double topRadius, pb::AltitudeType altitudeType,
                          double base, double height)
{
    pb::NoFlightZone z;
    z.set_name(name);
    z.set_type(pb::NT_AERODROME);
    auto *cone = z.mutable_conefrustum();
    cone->set_baselatitude(center.latitude * kRad);
    cone->set_baselongitude(center.longitude * kRad);
    cone->set_baseradius(baseRadius);
    cone->set_topradius(topRadius);
    cone->set_altitudetype(altitudeType);
    cone->set_basealtitude(base);
    cone->set_height(height);
    return z;
}

void keep(SimObjectStore &store, const pb::NoFlightZone &zone, qint64 now)
{
    for (const auto *w : store.list(SimZones::kType))
        if (w->noflightzone().name() == zone.name())
            return;
    pb::DomainObjectWrapper w;
    *w.mutable_noflightzone() = zone;
    store.save(SimZones::kType, w, now);
}

} // namespace

const QString SimZones::kType = QStringLiteral("NoFlightZone");

void SimZones::seed(SimObjectStore &store, bool demoContent, qint64 now)
{
    keep(store, coneZone("RIX CTR", {56.9236, 23.9711}, 5000, 8000, pb::AT_WGS84, 0, 600), now);
    keep(store,
         prismZone("Spilve airfield", pb::NT_AERODROME, {{56.9860, 24.0600}, {56.9860, 24.0900}, {56.9960, 24.0900}, {56.9960, 24.0600}},
                   pb::AT_AGL, 0, 150),
         now);
    if (demoContent)
        keep(store,
             prismZone("Crane works", pb::NT_CUSTOM, {{56.9740, 24.0850}, {56.9740, 24.0880}, {56.9760, 24.0880}, {56.9760, 24.0850}},
                       pb::AT_AGL, 0, 60),
             now);
}

std::optional<SimZones::Box> SimZones::boxOf(const pb::NoFlightZone &zone)
{
    if (zone.has_prism() && zone.prism().points_size() > 0) {
        Box b{1e9, 1e9, -1e9, -1e9};
        for (const auto &p : zone.prism().points()) {
            b.minLatitude = std::min(b.minLatitude, p.latitude());
            b.maxLatitude = std::max(b.maxLatitude, p.latitude());
            b.minLongitude = std::min(b.minLongitude, p.longitude());
            b.maxLongitude = std::max(b.maxLongitude, p.longitude());
        }
        return b;
    }
    if (zone.has_conefrustum()) {
        const auto &c = zone.conefrustum();
        const double radius = std::max(c.baseradius(), c.topradius());
        const double dLat = radius / kEarthRadius;
        const double dLon = dLat / std::max(1e-6, std::cos(c.baselatitude()));
        return Box{c.baselatitude() - dLat, c.baselongitude() - dLon, c.baselatitude() + dLat, c.baselongitude() + dLon};
    }
    return std::nullopt;
}

std::vector<const pb::NoFlightZone *> SimZones::list(const SimObjectStore &store, const Box &box, const std::vector<int> &types)
{
    std::vector<const pb::NoFlightZone *> out;
    for (const auto *w : store.list(kType)) {
        const pb::NoFlightZone &zone = w->noflightzone();
        if (!types.empty() && std::find(types.begin(), types.end(), int(zone.type())) == types.end())
            continue;
        if (const auto extent = boxOf(zone); extent && extent->meets(box))
            out.push_back(&zone);
    }
    return out;
}

QString SimZones::writeRefusal(const SimObjectStore &store, int id, const pb::NoFlightZone *incoming)
{
    if (id >= 0)
        if (const auto *stored = store.find(kType, id); stored && stored->noflightzone().type() == pb::NT_AERODROME)
            return QStringLiteral("NoFlightZone %1 ('%2') is an aerodrome zone from the server's aerodrome data; it cannot be changed or deleted")
                .arg(id)
                .arg(QString::fromStdString(stored->noflightzone().name()));
    if (!incoming)
        return {};
    if (incoming->type() == pb::NT_AERODROME)
        return QStringLiteral("Aerodrome zones come from the server's aerodrome data; a client may only write custom zones (NT_CUSTOM)");
    QString why;
    if (!airspace::NfzConversion::toZone(*incoming, &why))
        return QStringLiteral("NoFlightZone '%1' cannot be stored: %2").arg(airspace::NfzConversion::nameOf(*incoming), why);
    return {};
}

} // namespace sortie::sim
