#include "FlownPath.h"

#include "Geodesy.h"

#include <algorithm>
#include <cmath>

namespace sortie::airspace {

using terrain::ProfileRoute;
using terrain::ProfileWaypoint;
using terrain::TerrainProfile;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// heights() gives them in HeightReference's order.
static_assert(size_t(HeightReference::Amsl) == 0 && size_t(HeightReference::AboveTerrain) == 1
              && size_t(HeightReference::AboveHome) == 2);

// The heights at a place from its AMSL altitude and the ground there and at home (any may be NaN);
// a reference that cannot be converted keeps `own` (the route's own height in its own reference).
std::array<double, 3> heights(double amsl, double ground, double homeGround, HeightReference ownRef, double own)
{
    std::array<double, 3> h{amsl, amsl - ground, amsl - homeGround};
    if (std::isnan(h[size_t(ownRef)]))
        h[size_t(ownRef)] = own;
    return h;
}

struct Builder
{
    const ProfileRoute &route;
    const TerrainProfile *terrain;
    const LocalTangentPlane &plane;
    double homeGround = kNaN;
    FlownPath out;

    double groundAtVertex(size_t i) const
    {
        return terrain ? terrain->waypoints[i].ground.ground : kNaN;
    }
    double amslAtVertex(size_t i) const
    {
        if (terrain)
            return terrain->waypoints[i].altitudeAmsl;
        return route.waypoints[i].reference == HeightReference::Amsl ? route.waypoints[i].altitude : kNaN;
    }
    FlownPoint vertexPoint(size_t i, double along) const { return vertexPoint(i, i, along); }
    // Point `at`'s place at point `whose` height (a take-off climbs to the next point's height).
    FlownPoint vertexPoint(size_t at, size_t whose, double along) const
    {
        const ProfileWaypoint &w = route.waypoints[whose];
        FlownPoint p{route.waypoints[at].position, plane.project(route.waypoints[at].position), along};
        const double amsl = w.reference == HeightReference::AboveTerrain && at != whose ? groundAtVertex(at) + w.altitude : amslAtVertex(whose);
        p.height = heights(amsl, groundAtVertex(at), homeGround, w.reference, w.altitude);
        return p;
    }
    // The same place on the ground (the bottom of a take-off climb or landing descent).
    FlownPoint groundPoint(const FlownPoint &above, double ground) const
    {
        FlownPoint p = above;
        p.height = {ground, 0.0, ground - homeGround};
        return p;
    }

    void add(FlownLeg leg)
    {
        for (const FlownPoint &p : leg.points) {
            mission::GeoBox &b = out.bounds;
            if (b.empty) {
                b = {p.position.latitude, p.position.longitude, p.position.latitude, p.position.longitude, false};
            } else {
                b.south = std::min(b.south, p.position.latitude);
                b.north = std::max(b.north, p.position.latitude);
                b.west = std::min(b.west, p.position.longitude);
                b.east = std::max(b.east, p.position.longitude);
            }
        }
        out.legs.push_back(std::move(leg));
    }
};
} // namespace

FlownPath flownPath(const ProfileRoute &route, const TerrainProfile *terrain, const FlightEnds &ends, const LocalTangentPlane *plane)
{
    const size_t n = route.waypoints.size();
    if (terrain && terrain->waypoints.size() != n)
        terrain = nullptr;  // not this route's profile
    std::vector<GeoPoint> vertices;
    vertices.reserve(n);
    for (const ProfileWaypoint &w : route.waypoints)
        vertices.push_back(w.position);
    const LocalTangentPlane own(plane ? plane->origin() : (vertices.empty() ? GeoPoint{} : LocalTangentPlane::centroidOf(vertices)));
    Builder b{route, terrain, plane ? *plane : own, kNaN, {}};
    b.out.plane = b.plane;
    if (terrain && terrain->homeGround.hasValue())
        b.homeGround = terrain->homeGround.ground;
    if (n == 0)
        return std::move(b.out);

    // Each leg's length from its own ends (not a difference of running sums, whose last bits change
    // when an earlier leg does): an unchanged leg stays equal, and the checker keeps its findings.
    std::vector<double> lengthOf(n, 0.0), startOf(n, 0.0);
    for (size_t i = 1; i < n; ++i) {
        lengthOf[i] = mission::geodesicDistance(vertices[i - 1], vertices[i]);
        startOf[i] = terrain ? terrain->path.vertexDistance[i] : startOf[i - 1] + lengthOf[i];
    }
    // Distances along a leg to the micrometre, for the same reason.
    const auto micrometres = [](double v) { return std::round(v * 1e6) / 1e6; };

    // Joined by the one rule (FlownLegs.h): a take-off climbs straight up to the next point's height
    // before the leg, a landing is reached at the height the leg left at and descended to straight
    // down. A lone point is one leg that goes nowhere (its take-off and landing), as the time model has it.
    const std::vector<mission::LegShape> shapes = terrain ? terrain->legs : terrain::legShapesOf(route);
    const size_t legCount = shapes.size();
    std::vector<FlownLeg> legs(legCount);
    for (size_t k = 0; k < legCount; ++k) {
        const mission::LegShape &shape = shapes[k];
        const size_t a = shape.from, z = shape.to;
        FlownLeg &leg = legs[k];
        leg.leg = shape.leg;
        leg.row = route.waypoints[z].row;
        leg.start = startOf[a];
        leg.length = z > a ? lengthOf[z] : 0.0;
        const FlownPoint departing = b.vertexPoint(a, shape.departHeight, 0.0);
        if (shape.climbAtStart)
            leg.points.push_back(b.groundPoint(departing, b.groundAtVertex(a)));
        leg.points.push_back(departing);
        const ProfileWaypoint &wa = route.waypoints[shape.departHeight], &wz = route.waypoints[shape.arriveHeight];
        // Between the ends: the profile's samples where the ground is known there (they carry the
        // terrain following and the ground an AGL zone is measured from); straight otherwise.
        if (terrain && z > a) {
            const size_t first = size_t(terrain->path.vertexSample[a]), last = size_t(terrain->path.vertexSample[z]);
            for (size_t s = first + 1; s < last; ++s) {
                const terrain::GroundSample &g = terrain->ground[s];
                if (!g.hasValue())
                    continue;
                const terrain::PathSamplePoint &sp = terrain->path.points[s];
                const double along = micrometres(sp.distance - startOf[a]);
                const double f = leg.length > 0 ? along / leg.length : 0.0;
                const double own = wa.reference == wz.reference ? wa.altitude + f * (wz.altitude - wa.altitude) : kNaN;
                FlownPoint p{sp.position, b.plane.project(sp.position), along};
                p.height = heights(terrain->altitudeAmsl[s], g.ground, b.homeGround, wz.reference, own);
                leg.points.push_back(p);
            }
        }
        leg.points.push_back(b.vertexPoint(z, shape.arriveHeight, leg.length));
        if (wa.reference != wz.reference) {
            // Frames differ along the leg: the own-reference heights are not comparable across it.
            const size_t firstAbove = shape.climbAtStart ? 1 : 0;
            for (size_t i = firstAbove; i < leg.points.size(); ++i)
                for (size_t r = 0; r < 3; ++r)
                    if (std::isnan(leg.points[firstAbove].height[r]) || std::isnan(leg.points.back().height[r]))
                        leg.points[i].height[r] = kNaN;
        }
        if (shape.climbAtEnd || shape.descentAtEnd)
            leg.points.push_back(b.groundPoint(leg.points.back(), b.groundAtVertex(z)));
    }
    for (FlownLeg &leg : legs)
        b.add(std::move(leg));

    if (ends.returnHome) {
        // Straight home at the last height (in its own reference), then down to the ground there.
        const FlownPoint last = b.vertexPoint(n - 1, 0.0);
        const ProfileWaypoint &w = route.waypoints[n - 1];
        FlownLeg home;
        home.leg = int(legCount) + 1;
        home.row = -1;
        home.start = startOf[n - 1];
        home.length = mission::geodesicDistance(w.position, *ends.returnHome);
        FlownPoint at{*ends.returnHome, b.plane.project(*ends.returnHome), home.length};
        const double ground = b.homeGround;  // the ground at home
        double amsl = kNaN;
        switch (w.reference) {
        case HeightReference::Amsl: amsl = w.altitude; break;
        case HeightReference::AboveTerrain: amsl = ground + w.altitude; break;
        case HeightReference::AboveHome: amsl = b.homeGround + w.altitude; break;
        }
        at.height = heights(amsl, ground, b.homeGround, w.reference, w.altitude);
        home.points = {last, at, b.groundPoint(at, ground)};
        b.add(std::move(home));
    }
    return std::move(b.out);
}

FlightEnds flightEndsOf(const mission::Route &route)
{
    FlightEnds ends;
    if (route.settings.endAction == mission::EndAction::ReturnHome && route.settings.home)
        ends.returnHome = route.settings.home->position;
    return ends;
}

FlownPath flownPath(const mission::Route &route, const TerrainProfile *terrain, mission::ScanPlanCache *cache, const LocalTangentPlane *plane)
{
    return flownPath(terrain::profileRouteOf(route, cache), terrain, flightEndsOf(route), plane);
}

} // namespace sortie::airspace
