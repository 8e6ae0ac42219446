#include "TerrainProfile.h"

#include "FlightPath.h"
#include "RouteValidator.h"
#include "TerrainFollow.h"

#include <algorithm>
#include <cmath>
#include <QCoreApplication>

namespace sortie::terrain {

ProfileRoute profileRouteOf(const mission::Route &route, mission::ScanPlanCache *cache)
{
    ProfileRoute out;
    out.name = route.settings.name;
    out.safeDistance = route.settings.profile.safeTerrainDistance;
    if (route.settings.home)
        out.home = route.settings.home->position;
    const std::vector<mission::PathPoint> path = mission::flightPath(route, cache);
    out.waypoints.reserve(path.size());
    std::vector<std::optional<double>> follow(route.segments.size());
    for (size_t s = 0; s < route.segments.size(); ++s)
        follow[s] = terrainFollowTolerance(route.segments[s]);
    for (size_t i = 0; i < path.size(); ++i) {
        const mission::PathPoint &p = path[i];
        ProfileWaypoint w;
        w.position = p.position;
        w.altitude = p.altitude;
        w.reference = p.altitudeType == mission::AltitudeType::Amsl ? HeightReference::Amsl : HeightReference::AboveTerrain;
        w.row = p.segment;
        w.role = p.role;
        w.label = p.segment >= 0 && size_t(p.segment) < route.segments.size() && mission::isAreaScan(route.segments[size_t(p.segment)])
                      ? QCoreApplication::translate("TerrainProfile", "%1, point %2").arg(mission::segmentLabel(route, p.segment)).arg(i + 1)
                      : QCoreApplication::translate("TerrainProfile", "Waypoint %1").arg(i + 1);
        // Within one following segment, the leg to its next point follows the ground.
        if (p.segment >= 0 && size_t(p.segment) < follow.size() && follow[size_t(p.segment)] && i + 1 < path.size()
            && path[i + 1].segment == p.segment)
            w.followTolerance = *follow[size_t(p.segment)];
        out.waypoints.push_back(std::move(w));
    }
    return out;
}

std::vector<mission::LegShape> legShapesOf(const ProfileRoute &route)
{
    std::vector<mission::VerticalPoint> points;
    points.reserve(route.waypoints.size());
    for (const ProfileWaypoint &w : route.waypoints)
        points.push_back({w.role, w.reference == HeightReference::AboveTerrain && !(w.altitude > 0.0)});
    return mission::flownLegs(points);
}

QString legLabel(const ProfileRoute &route, int leg)
{
    const auto name = [&](int i) {
        return i >= 0 && size_t(i) < route.waypoints.size() && !route.waypoints[size_t(i)].label.isEmpty()
                   ? route.waypoints[size_t(i)].label
                   : QCoreApplication::translate("TerrainProfile", "Waypoint %1").arg(i + 1);
    };
    return QCoreApplication::translate("TerrainProfile", "Leg %1 (%2 → %3)").arg(leg + 1).arg(name(leg), name(leg + 1));
}

TerrainProfile computeProfile(const ProfileRoute &route, ElevationService &service, double step)
{
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    TerrainProfile out;
    out.sourcesTried = service.sourceNames();
    std::vector<GeoPoint> vertices;
    vertices.reserve(route.waypoints.size());
    for (const ProfileWaypoint &w : route.waypoints)
        vertices.push_back(w.position);
    out.path = samplePath(std::move(vertices), step);
    service.samplePath(out.path, out.ground);
    const size_t n = out.path.points.size();

    bool needsHome = false;
    for (const ProfileWaypoint &w : route.waypoints)
        needsHome |= w.reference == HeightReference::AboveHome;
    if (needsHome) {
        out.homeGround = route.home ? service.sample(*route.home)
                                    : (out.ground.empty() ? GroundSample{} : out.ground[size_t(out.path.vertexSample.front())]);
    }

    // Each waypoint's ground and its altitude above the geoid.
    out.waypoints.resize(route.waypoints.size());
    for (size_t i = 0; i < route.waypoints.size(); ++i) {
        const ProfileWaypoint &w = route.waypoints[i];
        WaypointTerrain &t = out.waypoints[i];
        t.ground = out.ground[size_t(out.path.vertexSample[i])];
        switch (w.reference) {
        case HeightReference::Amsl: t.altitudeAmsl = w.altitude; break;
        case HeightReference::AboveTerrain: t.altitudeAmsl = t.ground.hasValue() ? t.ground.ground + w.altitude : kNaN; break;
        case HeightReference::AboveHome: t.altitudeAmsl = out.homeGround.hasValue() ? out.homeGround.ground + w.altitude : kNaN; break;
        }
        t.altitudeAgl = t.ground.hasValue() ? t.altitudeAmsl - t.ground.ground : kNaN;
    }

    // Each leg's ends as flown: the height of the point the rule names, over the leg's own end.
    out.legs = legShapesOf(route);
    out.legEnds.resize(out.legs.size());
    const auto amslOver = [&](size_t whose, size_t at) {
        const ProfileWaypoint &w = route.waypoints[whose];
        if (w.reference == HeightReference::AboveTerrain)
            return out.waypoints[at].ground.hasValue() ? out.waypoints[at].ground.ground + w.altitude : kNaN;
        return out.waypoints[whose].altitudeAmsl;  // AMSL, or above home: the same anywhere
    };
    const auto groundAt = [&](size_t i) { return out.waypoints[i].ground.hasValue() ? out.waypoints[i].ground.ground : kNaN; };
    for (size_t k = 0; k < out.legs.size(); ++k) {
        const mission::LegShape &leg = out.legs[k];
        LegEnds &e = out.legEnds[k];
        e.departAmsl = amslOver(leg.departHeight, leg.from);
        e.arriveAmsl = amslOver(leg.arriveHeight, leg.to);
        const int number = int(k);
        if (leg.climbAtStart)
            out.verticals.push_back({number, int(leg.from), out.path.vertexDistance[leg.from], groundAt(leg.from), e.departAmsl, true});
        if (leg.climbAtEnd)
            out.verticals.push_back({number, int(leg.to), out.path.vertexDistance[leg.to], groundAt(leg.to), e.arriveAmsl, true});
        if (leg.descentAtEnd)
            out.verticals.push_back({number, int(leg.to), out.path.vertexDistance[leg.to], e.arriveAmsl, groundAt(leg.to), false});
    }
    const auto aglOver = [&](double amsl, size_t at) { return amsl - groundAt(at); };

    // The altitude along each leg: straight between its ends; on a leg that follows the terrain,
    // straight between the points following adds (needs the ground all along it, else straight).
    std::vector<double> followed(n, kNaN);
    std::vector<double> distance, ground;
    for (size_t a = 0; a + 1 < route.waypoints.size(); ++a) {
        const double tolerance = route.waypoints[a].followTolerance;
        const size_t first = size_t(out.path.vertexSample[a]), last = size_t(out.path.vertexSample[a + 1]);
        const double agl0 = aglOver(out.legEnds[a].departAmsl, a), agl1 = aglOver(out.legEnds[a].arriveAmsl, a + 1);
        if (tolerance < 0 || last <= first + 1 || std::isnan(agl0) || std::isnan(agl1))
            continue;
        if (!std::all_of(out.ground.begin() + long(first), out.ground.begin() + long(last) + 1,
                         [](const GroundSample &g) { return g.hasValue(); }))
            continue;
        if (distance.empty()) {
            distance.resize(n);
            ground.resize(n);
            for (size_t i = 0; i < n; ++i) {
                distance[i] = out.path.points[i].distance;
                ground[i] = out.ground[i].ground;
            }
        }
        std::vector<bool> keep(n, false);
        keep[first] = keep[last] = true;
        markFollowPoints(distance, ground, tolerance, first, last, keep);
        const auto height = [&](size_t i) {
            const double f = distance[last] > distance[first] ? (distance[i] - distance[first]) / (distance[last] - distance[first]) : 0.0;
            return ground[i] + agl0 + f * (agl1 - agl0);
        };
        size_t from = first;
        for (size_t i = first + 1; i <= last; ++i) {
            if (!keep[i])
                continue;
            const double h0 = height(from), h1 = height(i);
            for (size_t j = from; j <= i; ++j) {
                const double f = distance[i] > distance[from] ? (distance[j] - distance[from]) / (distance[i] - distance[from]) : 0.0;
                followed[j] = h0 + f * (h1 - h0);
            }
            from = i;
        }
    }

    // The clearance, and what is lowest.
    out.altitudeAmsl.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const PathSamplePoint &p = out.path.points[i];
        const size_t a = size_t(p.leg), b = std::min(a + 1, out.waypoints.size() - 1);
        const double da = out.path.vertexDistance[a], db = out.path.vertexDistance[b];
        const double f = db > da ? (p.distance - da) / (db - da) : 0.0;
        const LegEnds &ends = out.legEnds[std::min(a, out.legEnds.size() - 1)];
        const double ha = ends.departAmsl, hb = ends.arriveAmsl;
        out.altitudeAmsl[i] = std::isnan(followed[i]) ? ha + f * (hb - ha) : followed[i];
        const GroundSample &g = out.ground[i];
        out.pending |= g.status == SampleStatus::Pending;
        const double c = out.altitudeAmsl[i] - g.ground;
        if (std::isnan(c))
            continue;
        const ClearancePoint here{p.leg, p.distance, p.distance - da, c};
        if (!out.minClearance || c < out.minClearance->clearance)
            out.minClearance = here;
        if (c < route.safeDistance) {
            LowStretch *open = out.lowStretches.empty() ? nullptr : &out.lowStretches.back();
            const bool continues = open && open->leg == p.leg && i > 0
                                   && out.clearance(i - 1) < route.safeDistance && out.path.points[i - 1].leg == p.leg;
            if (continues) {
                open->toDistance = p.distance;
                if (c < open->lowest.clearance)
                    open->lowest = here;
            } else {
                out.lowStretches.push_back({p.leg, p.distance, p.distance, here});
            }
        }
    }
    std::vector<ElevationSample> plain(out.ground.begin(), out.ground.end());
    out.noData = ElevationSource::noDataStretches(out.path, plain);
    return out;
}

} // namespace sortie::terrain
