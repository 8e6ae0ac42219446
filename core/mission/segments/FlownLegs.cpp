#include "FlownLegs.h"

#include <algorithm>

namespace sortie::mission {

bool onGround(double altitude, AltitudeType type)
{
    return type == AltitudeType::Agl && !(altitude > 0.0);
}

std::vector<LegShape> flownLegs(const std::vector<VerticalPoint> &points)
{
    std::vector<LegShape> legs;
    if (points.empty())
        return legs;
    const size_t last = points.size() - 1;
    const auto takesOffFromGround = [&](size_t i) { return points[i].role == WaypointRole::Takeoff && points[i].onGround; };
    const auto landsOnGround = [&](size_t i) { return points[i].role == WaypointRole::Land && points[i].onGround; };
    const size_t count = std::max<size_t>(1, last);
    legs.reserve(count);
    for (size_t n = 1; n <= count; ++n) {
        LegShape leg;
        leg.leg = int(n);
        leg.from = n - 1;
        leg.to = std::min(n, last);
        leg.departHeight = leg.from;
        leg.arriveHeight = leg.to;
        leg.climbAtStart = points[leg.from].role == WaypointRole::Takeoff;
        leg.descentAtEnd = points[leg.to].role == WaypointRole::Land;
        if (leg.moves()) {
            // Up to the next point's height first, unless that point is itself on the ground.
            if (takesOffFromGround(leg.from) && !landsOnGround(leg.to))
                leg.departHeight = leg.to;
            // Across at the height it left at, then down.
            if (landsOnGround(leg.to))
                leg.arriveHeight = leg.departHeight;
            leg.climbAtEnd = leg.to == last && points[leg.to].role == WaypointRole::Takeoff;
        }
        legs.push_back(leg);
    }
    return legs;
}

std::vector<LegShape> flownLegs(const std::vector<PathPoint> &path)
{
    std::vector<VerticalPoint> points;
    points.reserve(path.size());
    for (const PathPoint &p : path)
        points.push_back({p.role, onGround(p.altitude, p.altitudeType)});
    return flownLegs(points);
}

} // namespace sortie::mission
