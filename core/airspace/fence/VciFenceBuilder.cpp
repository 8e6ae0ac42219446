#include "VciFenceBuilder.h"

#include "Geodesy.h"
#include "Route.h"
#include "TelemetryField.h"

#include <algorithm>
#include <limits>
#include <QCoreApplication>

namespace sortie::airspace {
namespace {

namespace profile = vci::profile;
using mission::GeoPoint;
using vehicle::FenceBreachAction;
using vehicle::radiansFromDegrees;
using vehicle::GroundLookup;
using vehicle::VciFencePlan;

mission::MissionError failure(QString message)
{
    return mission::MissionError{std::move(message), {}, 0, 0, {}};
}

profile::FenceVertex vertexOf(const GeoPoint &p)
{
    return {radiansFromDegrees(p.latitude), radiansFromDegrees(p.longitude)};
}

std::vector<profile::FenceVertex> ringOf(const std::vector<GeoPoint> &ring)
{
    std::vector<profile::FenceVertex> out;
    out.reserve(ring.size());
    for (const GeoPoint &p : ring)
        out.push_back(vertexOf(p));
    return out;
}

// Where the ground under a zone is sampled for its AGL limits.
std::vector<GeoPoint> samplesOf(const Zone &zone)
{
    std::vector<GeoPoint> points;
    const auto round = [&points](const GeoPoint &c, double radius) {
        points.push_back(c);
        for (int k = 0; k < 8; ++k)
            points.push_back(mission::geodesicDirect(c, 45.0 * k, radius).point);
    };
    if (const auto *p = std::get_if<airspace::ZonePolygons>(&zone.shape)) {
        for (const auto &part : p->parts)
            for (const auto &ring : part.rings)
                points.insert(points.end(), ring.begin(), ring.end());
    } else if (const auto *c = std::get_if<airspace::ZoneCircle>(&zone.shape)) {
        round(c->center, c->radius);
    } else if (const auto *cone = std::get_if<airspace::ZoneConeFrustum>(&zone.shape)) {
        round(cone->center, std::max(cone->bottomRadius, cone->topRadius));
    }
    return points;
}

struct GroundRange
{
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
};

std::optional<GroundRange> groundUnder(const Zone &zone, const GroundLookup &ground)
{
    if (!ground)
        return std::nullopt;
    GroundRange range;
    for (const GeoPoint &p : samplesOf(zone)) {
        const auto h = ground(p);
        if (!h)
            return std::nullopt;
        range.lowest = std::min(range.lowest, *h);
        range.highest = std::max(range.highest, *h);
    }
    return range;
}

std::string nameOf(const QString &name)
{
    std::string s = name.toStdString();
    if (s.size() > profile::kMaxFenceNameLength) {
        s.resize(profile::kMaxFenceNameLength);
        while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0) == 0x80) // no half UTF-8 character
            s.pop_back();
        if (!s.empty() && (static_cast<unsigned char>(s.back()) & 0x80))
            s.pop_back();
    }
    return s;
}

struct Limits
{
    std::optional<profile::FenceLimit> floor, ceiling;
};

// The zone's limits in a reference the vehicle measures; an error when it cannot be done safely.
mission::Result<Limits> limitsOf(const Zone &zone, const GroundLookup &ground, QStringList *notices)
{
    Limits out;
    const bool keepOut = zone.kind == ZoneKind::Exclusion;
    const bool agl = (zone.floor && zone.floor->reference == terrain::HeightReference::AboveTerrain)
                     || (zone.ceiling && zone.ceiling->reference == terrain::HeightReference::AboveTerrain);
    const std::optional<GroundRange> range = agl ? groundUnder(zone, ground) : std::nullopt;
    if (agl && !range) {
        if (!keepOut)
            return failure(QCoreApplication::translate("VciFenceBuilder", "zone '%1': its AGL limits need the ground under it, which no terrain source has; "
                                                     "a vehicle cannot be given it")
                                             .arg(zone.name));
        notices->append(QCoreApplication::translate("VciFenceBuilder", "zone '%1': no ground under it, so its AGL limits were dropped (the vehicle keeps out of the whole column)")
                            .arg(zone.name));
    }
    const auto convert = [&](const std::optional<HeightLimit> &limit, bool isFloor) -> std::optional<profile::FenceLimit> {
        if (!limit)
            return std::nullopt;
        switch (limit->reference) {
        case terrain::HeightReference::Amsl: return profile::FenceLimit{limit->metres, profile::FenceReference::Amsl};
        case terrain::HeightReference::AboveHome: return profile::FenceLimit{limit->metres, profile::FenceReference::Home};
        case terrain::HeightReference::AboveTerrain:
            if (!range)
                return std::nullopt;
            // Grow what keeps out, shrink what keeps in.
            const bool low = keepOut == isFloor;
            return profile::FenceLimit{limit->metres + (low ? range->lowest : range->highest), profile::FenceReference::Amsl};
        }
        return std::nullopt;
    };
    out.floor = convert(zone.floor, true);
    out.ceiling = convert(zone.ceiling, false);
    if (out.floor && out.ceiling && out.floor->reference == out.ceiling->reference && !(out.ceiling->altitude > out.floor->altitude))
        return failure(QCoreApplication::translate("VciFenceBuilder", "zone '%1': over ground from %2 to %3 m its AGL limits leave no room in AMSL")
                                         .arg(zone.name)
                                         .arg(range ? range->lowest : 0.0, 0, 'f', 0)
                                         .arg(range ? range->highest : 0.0, 0, 'f', 0));
    return out;
}

mission::Result<void> addZone(const Zone &zone, const GroundLookup &ground, profile::Fence *fence, QStringList *notices)
{
    auto limits = limitsOf(zone, ground, notices);
    if (!limits)
        return limits.error();
    const bool keepOut = zone.kind == ZoneKind::Exclusion;
    profile::FenceItem item;
    item.kind = keepOut ? profile::FenceKind::Exclusion : profile::FenceKind::Inclusion;
    item.name = nameOf(zone.name);
    item.floor = limits->floor;
    item.ceiling = limits->ceiling;
    if (const auto *p = std::get_if<airspace::ZonePolygons>(&zone.shape)) {
        bool closedHoles = false;
        for (const auto &part : p->parts) {
            if (part.rings.empty())
                continue;
            profile::FenceItem outer = item;
            outer.polygon = ringOf(part.rings.front());
            fence->items.push_back(std::move(outer));
            for (size_t h = 1; h < part.rings.size(); ++h) {
                if (keepOut) {
                    closedHoles = true;
                    continue;
                }
                profile::FenceItem hole = item; // a hole in what keeps in keeps out, at the same heights
                hole.kind = profile::FenceKind::Exclusion;
                hole.name = nameOf(QCoreApplication::translate("VciFenceBuilder", "%1 (hole %2)").arg(zone.name).arg(h));
                hole.polygon = ringOf(part.rings[h]);
                fence->items.push_back(std::move(hole));
            }
        }
        if (closedHoles)
            notices->append(QCoreApplication::translate("VciFenceBuilder", "zone '%1': its holes are closed on the vehicle (a fence polygon has none)").arg(zone.name));
    } else if (const auto *c = std::get_if<airspace::ZoneCircle>(&zone.shape)) {
        item.center = vertexOf(c->center);
        item.radius = c->radius;
        fence->items.push_back(std::move(item));
    } else if (const auto *cone = std::get_if<airspace::ZoneConeFrustum>(&zone.shape)) {
        item.center = vertexOf(cone->center);
        item.radius = keepOut ? std::max(cone->bottomRadius, cone->topRadius) : std::min(cone->bottomRadius, cone->topRadius);
        if (!(item.radius > 0))
            return failure(QCoreApplication::translate("VciFenceBuilder", "zone '%1': a cone that narrows to a point cannot keep a vehicle in").arg(zone.name));
        notices->append(QCoreApplication::translate("VciFenceBuilder", "zone '%1': its cone is a cylinder of radius %2 m on the vehicle").arg(zone.name).arg(item.radius, 0, 'f', 0));
        fence->items.push_back(std::move(item));
    }
    return {};
}

} // namespace

const ZoneSet *fenceZonesOf(const vehicle::FenceSettings &settings)
{
    return dynamic_cast<const FenceZoneSet *>(settings.zones.get());
}

mission::Result<VciFencePlan> vciFenceFor(const mission::Route &route, const vehicle::FenceSettings &settings, const mission::GeoBox &routeBox,
                                          const GroundLookup &ground)
{
    VciFencePlan plan;
    plan.fence.breachAction = vehicle::profileBreachAction(settings.breachAction);
    std::vector<Zone> zones = zonesOfFence(route.fence, QCoreApplication::translate("VciFenceBuilder", "route fence"), ZoneSource::VehicleFence,
                                           route.settings.name);
    const size_t own = zones.size();
    const ZoneSet *carried = fenceZonesOf(settings);
    if (settings.zones && !carried)
        return failure(QCoreApplication::translate("VciFenceBuilder", "the fence cannot be made: its zones are not the airspace's"));
    if (carried && !routeBox.empty)
        for (int i : carried->near(routeBox))
            zones.push_back(carried->zones()[size_t(i)]);
    for (const Zone &zone : zones)
        if (auto added = addZone(zone, ground, &plan.fence, &plan.notices); !added)
            return added.error();
    if (const std::string problem = profile::fenceLimitProblem(plan.fence); !problem.empty())
        return failure(QCoreApplication::translate("VciFenceBuilder", "the fence cannot be sent: %1").arg(QString::fromStdString(problem)));
    if (!plan.fence.empty())
        plan.notices.prepend(QCoreApplication::translate("VciFenceBuilder", "fence: %1 of the route's own, %n airspace zone(s) near it; on a breach the vehicle will %2",
                                                             nullptr, int(zones.size() - own))
                                 .arg(own)
                                 .arg(settings.breachAction == FenceBreachAction::Return ? QCoreApplication::translate("VciFenceBuilder", "return home")
                                      : settings.breachAction == FenceBreachAction::Land ? QCoreApplication::translate("VciFenceBuilder", "land")
                                                                                         : QCoreApplication::translate("VciFenceBuilder", "hold")));
    return plan;
}

} // namespace sortie::airspace
