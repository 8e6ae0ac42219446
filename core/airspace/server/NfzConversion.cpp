#include "NfzConversion.h"

#include "Domain.pb.h"

#include <QStringList>

#include <cmath>
#include <numbers>
#include <QCoreApplication>

namespace sortie::airspace::NfzConversion {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

std::optional<GeoPoint> position(double latitudeRad, double longitudeRad)
{
    const GeoPoint p{latitudeRad * kDegreesPerRadian, longitudeRad * kDegreesPerRadian};
    return p.isValid() ? std::optional(p) : std::nullopt;
}

HeightReference referenceOf(pb::AltitudeType type)
{
    return type == pb::AT_AGL ? HeightReference::AboveTerrain : HeightReference::Amsl;
}

QString metres(double v)
{
    return QString::number(v, 'g', 10);
}

// Floor and ceiling of a volume; false with `why` when a number is not usable. `groundFloor`: a
// base at or below 0 m AGL is the ground (no floor).
bool limitsOf(bool hasBase, double base, bool hasHeight, double height, pb::AltitudeType type, bool groundFloor, Zone &z,
              QString *why)
{
    const HeightReference reference = referenceOf(type);
    if (hasBase && !std::isfinite(base))
        return *why = QCoreApplication::translate("NfzConversion", "its baseAltitude is not a number"), false;
    if (hasHeight && (!std::isfinite(height) || height < 0))
        return *why = QCoreApplication::translate("NfzConversion", "its height %1 m is not a height (it must be 0 or more)").arg(metres(height)), false;
    const double floor = hasBase ? base : 0.0;
    const bool fromGround = groundFloor && (!hasBase || (reference == HeightReference::AboveTerrain && base <= 0));
    if (!fromGround)
        z.floor = HeightLimit{floor, reference};
    if (hasHeight)
        z.ceiling = HeightLimit{floor + height, reference};
    return true;
}

bool prismToZone(const pb::Prism &prism, Zone &z, QString *why)
{
    std::vector<GeoPoint> ring;
    for (int i = 0; i < prism.points_size(); ++i) {
        const auto &p = prism.points(i);
        const auto at = p.has_latitude() && p.has_longitude() ? position(p.latitude(), p.longitude()) : std::nullopt;
        if (!at)
            return *why = QCoreApplication::translate("NfzConversion", "point %1 of its prism is not a position (latitude and longitude in radians)").arg(i + 1), false;
        ring.push_back(*at);
    }
    if (ring.size() > 1 && ring.front() == ring.back())
        ring.pop_back();  // a closed ring: Zone's rings are open
    if (ring.size() < 3)
        return *why = QCoreApplication::translate("NfzConversion", "its prism has %n corner(s); a polygon needs 3", nullptr, int(ring.size())), false;
    z.shape = ZonePolygons{{ZonePolygon{{std::move(ring)}}}};
    return limitsOf(prism.has_basealtitude(), prism.basealtitude(), prism.has_height(), prism.height(), prism.altitudetype(), true, z, why);
}

bool coneToZone(const pb::ConeFrustum &cone, Zone &z, QString *why)
{
    const auto center = cone.has_baselatitude() && cone.has_baselongitude() ? position(cone.baselatitude(), cone.baselongitude())
                                                                              : std::nullopt;
    if (!center)
        return *why = QCoreApplication::translate("NfzConversion", "its cone frustum has no centre (baseLatitude, baseLongitude in radians)"), false;
    const double bottom = cone.baseradius(), top = cone.has_topradius() ? cone.topradius() : bottom;
    if (!cone.has_baseradius() || !std::isfinite(bottom) || bottom < 0 || !std::isfinite(top) || top < 0 || (bottom <= 0 && top <= 0))
        return *why = QCoreApplication::translate("NfzConversion", "its cone frustum's radii (base %1 m, top %2 m) are not a circle").arg(metres(bottom), metres(top)), false;
    if (bottom == top) {
        z.shape = ZoneCircle{*center, bottom};
        return limitsOf(cone.has_basealtitude(), cone.basealtitude(), cone.has_height(), cone.height(), cone.altitudetype(), true, z, why);
    }
    if (!cone.has_height())
        return *why = QCoreApplication::translate("NfzConversion", "its cone frustum has two radii but no height"), false;
    z.shape = ZoneConeFrustum{*center, bottom, top};
    // The radius changes between floor and ceiling: keep the floor even at the ground.
    return limitsOf(cone.has_basealtitude(), cone.basealtitude(), true, cone.height(), cone.altitudetype(), false, z, why);
}

std::optional<pb::AltitudeType> altitudeTypeOf(const Zone &zone, QString *why)
{
    const auto &f = zone.floor, &c = zone.ceiling;
    if (f && c && f->reference != c->reference)
        return *why = QCoreApplication::translate("NfzConversion", "its floor (%1) and ceiling (%2) are in different references; a server zone has one")
                          .arg(limitText(f, false), limitText(c, true)),
               std::nullopt;
    const HeightReference r = f ? f->reference : c ? c->reference : HeightReference::AboveTerrain;
    if (r == HeightReference::AboveHome)
        return *why = QCoreApplication::translate("NfzConversion", "its heights are above home; a server zone's are AMSL or AGL"), std::nullopt;
    if (!f && r == HeightReference::Amsl)
        return *why = QCoreApplication::translate("NfzConversion", "it starts from the ground with an AMSL ceiling; give it an AMSL floor or an AGL ceiling"),
               std::nullopt;
    return r == HeightReference::Amsl ? pb::AT_WGS84 : pb::AT_AGL;
}

template<class Volume>
void putLimits(const Zone &zone, pb::AltitudeType type, Volume *v)
{
    const double base = zone.floor ? zone.floor->metres : 0.0;
    v->set_altitudetype(type);
    v->set_basealtitude(base);
    if (zone.ceiling)
        v->set_height(zone.ceiling->metres - base);
    else
        v->clear_height();
}

} // namespace

QString nameOf(const pb::NoFlightZone &nfz)
{
    const QString name = QString::fromStdString(nfz.name()).trimmed();
    return name.isEmpty() ? QCoreApplication::translate("NfzConversion", "NoFlightZone %1").arg(nfz.id()) : name;
}

std::optional<Zone> toZone(const pb::NoFlightZone &nfz, QString *why)
{
    Zone z;
    z.name = nameOf(nfz);
    z.kind = ZoneKind::Exclusion;
    z.source = nfz.type() == pb::NT_AERODROME ? ZoneSource::ServerAerodrome : ZoneSource::ServerCustom;
    z.origin = QCoreApplication::translate("NfzConversion", "UgCS server, NoFlightZone %1").arg(nfz.id());
    if (nfz.has_id())
        z.serverId = nfz.id();
    z.serverVersion = nfz.version();
    if (nfz.has_prism() && nfz.has_conefrustum())
        return *why = QCoreApplication::translate("NfzConversion", "it has both a prism and a cone frustum"), std::nullopt;
    if (nfz.has_prism()) {
        if (!prismToZone(nfz.prism(), z, why))
            return std::nullopt;
    } else if (nfz.has_conefrustum()) {
        if (!coneToZone(nfz.conefrustum(), z, why))
            return std::nullopt;
    } else {
        return *why = QCoreApplication::translate("NfzConversion", "it has no volume (neither a prism nor a cone frustum)"), std::nullopt;
    }
    if (z.floor && z.ceiling && z.ceiling->metres < z.floor->metres)
        return *why = QCoreApplication::translate("NfzConversion", "its ceiling is below its floor"), std::nullopt;
    if (const QString problem = shapeProblem(z); !problem.isEmpty())
        return *why = problem, std::nullopt;
    return z;
}

std::optional<pb::NoFlightZone> toNfz(const Zone &zone, const pb::NoFlightZone *before, QString *why)
{
    if (zone.kind != ZoneKind::Exclusion)
        return *why = QCoreApplication::translate("NfzConversion", "the server's no-fly zones keep vehicles out; an inclusion zone cannot be one"), std::nullopt;
    if (zone.source == ZoneSource::ServerAerodrome || (before && before->type() == pb::NT_AERODROME))
        return *why = QCoreApplication::translate("NfzConversion", "aerodrome zones are the server's own; only custom zones are changed"), std::nullopt;
    if (zone.floor && zone.ceiling && zone.ceiling->metres < zone.floor->metres)
        return *why = QCoreApplication::translate("NfzConversion", "its ceiling is below its floor"), std::nullopt;
    const auto type = altitudeTypeOf(zone, why);
    if (!type)
        return std::nullopt;
    pb::NoFlightZone nfz;
    if (before)
        nfz = *before;
    if (zone.serverId) {
        nfz.set_id(*zone.serverId);
        nfz.set_version(zone.serverVersion);
    } else {
        nfz.clear_id();
        nfz.clear_version();
    }
    nfz.set_name(zone.name.toStdString());
    nfz.set_type(pb::NT_CUSTOM);
    if (const auto *polygons = std::get_if<ZonePolygons>(&zone.shape)) {
        if (polygons->parts.size() != 1 || polygons->parts[0].rings.size() != 1) {
            // In steps: lupdate 6.4 does not come back from this message written as one nested call.
            const int parts = int(polygons->parts.size());
            const int rings = parts == 0 ? 0 : int(polygons->parts[0].rings.size());
            const QString ringText = QCoreApplication::translate("NfzConversion", "%n ring(s)", nullptr, rings);
            *why = QCoreApplication::translate("NfzConversion", "a server zone is one polygon without holes (this one has %n part(s), %1)",
                                               nullptr, parts)
                       .arg(ringText);
            return std::nullopt;
        }
        const auto &ring = polygons->parts[0].rings[0];
        if (ring.size() < 3)
            return *why = QCoreApplication::translate("NfzConversion", "its polygon has %n corner(s); it needs 3", nullptr, int(ring.size())), std::nullopt;
        nfz.clear_conefrustum();
        pb::Prism *prism = nfz.mutable_prism();
        prism->clear_points();
        for (const GeoPoint &g : ring) {
            auto *p = prism->add_points();
            p->set_latitude(g.latitude / kDegreesPerRadian);
            p->set_longitude(g.longitude / kDegreesPerRadian);
        }
        putLimits(zone, *type, prism);
        return nfz;
    }
    nfz.clear_prism();
    pb::ConeFrustum *cone = nfz.mutable_conefrustum();
    GeoPoint center;
    if (const auto *circle = std::get_if<ZoneCircle>(&zone.shape)) {
        center = circle->center;
        cone->set_baseradius(circle->radius);
        cone->set_topradius(circle->radius);
    } else {
        const auto &frustum = std::get<ZoneConeFrustum>(zone.shape);
        if (!zone.ceiling)
            return *why = QCoreApplication::translate("NfzConversion", "a cone frustum needs a ceiling"), std::nullopt;
        center = frustum.center;
        cone->set_baseradius(frustum.bottomRadius);
        cone->set_topradius(frustum.topRadius);
    }
    cone->set_baselatitude(center.latitude / kDegreesPerRadian);
    cone->set_baselongitude(center.longitude / kDegreesPerRadian);
    putLimits(zone, *type, cone);
    return nfz;
}

std::vector<Zone> toZones(const google::protobuf::RepeatedPtrField<pb::NoFlightZone> &zones, QStringList *problems)
{
    std::vector<Zone> out;
    out.reserve(size_t(zones.size()));
    for (const pb::NoFlightZone &nfz : zones) {
        QString why;
        if (auto zone = toZone(nfz, &why)) {
            out.push_back(std::move(*zone));
            continue;
        }
        const QString name = QString::fromStdString(nfz.name()).trimmed();
        problems->append(QCoreApplication::translate("NfzConversion", "NoFlightZone %1%2 was left out: %3")
                             .arg(nfz.id())
                             .arg(name.isEmpty() ? QString() : QStringLiteral(" ('%1')").arg(name), why));
    }
    return out;
}

} // namespace sortie::airspace::NfzConversion
