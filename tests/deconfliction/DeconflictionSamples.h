#pragma once

// Routes for the deconfliction tests, laid out in metres east and north of one origin near Riga.
#include "LocalTangentPlane.h"
#include "Route.h"
#include "RouteTiming.h"

#include <vector>

namespace sortie::test {

inline const mission::LocalTangentPlane &samplePlane()
{
    static const mission::LocalTangentPlane plane({56.95, 24.1});
    return plane;
}

struct Leg
{
    double east = 0.0, north = 0.0, altitude = 50.0, speed = 10.0;
};

// Waypoints at the points given (metres east, north of the origin), each with its altitude and the
// speed of the leg that reaches it.
inline mission::Route lineRoute(const std::vector<Leg> &points)
{
    mission::Route r;
    r.settings.name = QStringLiteral("line");
    r.settings.initialSpeed = 10;
    for (const Leg &p : points) {
        mission::Waypoint w;
        w.position = samplePlane().unproject({p.east, p.north});
        w.altitude = p.altitude;
        w.speed = p.speed;
        r.segments.push_back(w);
    }
    return r;
}

// The timeline with no climb or descent rate: heights change evenly along a move, as the command line flies them.
inline mission::RouteTimeline lineTimeline(const std::vector<Leg> &points)
{
    mission::TimingParameters p;
    p.cruiseSpeed = 10;
    return mission::timeRoute(lineRoute(points), p).value();
}

} // namespace sortie::test
