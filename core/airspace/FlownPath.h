#pragma once

#include "LocalTangentPlane.h"
#include "Route.h"
#include "TerrainProfile.h"

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::airspace {

using mission::GeoPoint;
using mission::LocalTangentPlane;
using mission::PlanePoint;
using terrain::HeightReference;

// One point of the flown path in 3D: where (on the route's tangent plane), how far along its leg,
// and its height in each reference (indexed by HeightReference; NaN where it is unknown, e.g. AMSL
// over ground no source knows). Two consecutive points at one place are a vertical move (a take-off
// climb, a landing descent).
struct FlownPoint
{
    GeoPoint position;
    PlanePoint at;
    double along = 0.0;  // metres from the leg's start along the flown path
    std::array<double, 3> height{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::quiet_NaN()};
    double in(HeightReference r) const { return height[size_t(r)]; }
    // The same place, distance and heights (an unknown height equals an unknown one).
    bool sameAs(const FlownPoint &o) const
    {
        const auto same = [](double a, double b) { return a == b || (a != a && b != b); };
        return at.x == o.at.x && at.y == o.at.y && along == o.along && same(height[0], o.height[0]) && same(height[1], o.height[1])
            && same(height[2], o.height[2]);
    }
};

// One leg as `sortie-plan profile` numbers it (from 1; the flight home is the leg after the last),
// its height piecewise linear between its points: the straight climb between two waypoints, the
// points terrain following adds, the take-off climb at its start, the landing descent at its end.
struct FlownLeg
{
    int leg = 1;
    int row = -1;           // the route row it ends at (what selecting it selects), -1 for home
    double start = 0.0;     // metres from the route's start to the leg's start
    double length = 0.0;    // horizontal metres (WGS-84 geodesic)
    std::vector<FlownPoint> points;
    bool sameShape(const FlownLeg &o) const
    {
        if (length != o.length || points.size() != o.points.size())
            return false;
        for (size_t i = 0; i < points.size(); ++i)
            if (!points[i].sameAs(o.points[i]))
                return false;
        return true;
    }
};

struct FlownPath
{
    LocalTangentPlane plane{GeoPoint{}};
    std::vector<FlownLeg> legs;
    mission::GeoBox bounds;  // of every point
};

// How the path is flown beyond its points.
struct FlightEnds
{
    std::optional<GeoPoint> returnHome;  // the route ends by flying home at its last height and landing
};

// The flown path in 3D from the profile's view of a route (its points, their heights and
// references, where it takes off and lands). With `terrain` (computeProfile over the same route)
// heights are converted through the ground and terrain-following legs follow it; without, each
// point knows only its own reference's height, interpolated along a leg. `plane` fixes the frame
// (keep one while re-checking an edited route); none: the tangent plane at the route's centre.
FlownPath flownPath(const terrain::ProfileRoute &route, const terrain::TerrainProfile *terrain, const FlightEnds &ends = {},
                    const LocalTangentPlane *plane = nullptr);

// The same for a route: its flown path (segments planned), take-off, landing and the flight home.
FlownPath flownPath(const mission::Route &route, const terrain::TerrainProfile *terrain = nullptr,
                    mission::ScanPlanCache *cache = nullptr, const LocalTangentPlane *plane = nullptr);
FlightEnds flightEndsOf(const mission::Route &route);

} // namespace sortie::airspace
