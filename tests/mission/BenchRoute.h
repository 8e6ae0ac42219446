#pragma once

// The large route the benchmarks share: a lawnmower of `n` waypoints over about 5 x 5 km near Riga
// (rows of 100 points 50 m apart), with a wait and a camera series every 50 waypoints.
#include "LocalTangentPlane.h"
#include "Route.h"

namespace sortie::mission {

inline Route benchRoute(int n)
{
    Route r;
    r.settings.name = QStringLiteral("bench");
    r.settings.maxAltitude = 200;
    r.settings.profile.maxHorizontalSpeed = 15;
    r.segments.reserve(size_t(n));
    const LocalTangentPlane plane({56.95, 24.1});
    for (int i = 0; i < n; ++i) {
        const int row = i / 100, col = (row % 2) ? 99 - i % 100 : i % 100;
        Waypoint w;
        w.position = plane.unproject({col * 50.0 - 2500, row * 50.0 - 2500});
        w.altitude = 60 + (i % 7);
        w.speed = 8;
        w.turnType = TurnType::Straight;
        if (i % 50 == 0)
            w.actions = {WaitAction{2, false}, CameraSeriesByDistanceAction{20, 0, 0}};
        r.segments.push_back(std::move(w));
    }
    return r;
}

} // namespace sortie::mission
