#pragma once

// A route and an energy profile whose figures are round, for the command-line tests of endurance
// and resuming: legs of 1000 m east at 10 m/s, 30 m up, and a quad that spends 8 Wh on each.
#include "Geodesy.h"
#include "Mission.h"

#include <QByteArray>

namespace sortie::test {

inline const mission::GeoPoint kLineOrigin{56.95, 24.1};

// `legs` legs of 1000 m east at 10 m/s, 30 m up, home at the start.
inline mission::Mission lineMission(int legs)
{
    mission::Route r;
    r.settings.name = QStringLiteral("line");
    r.settings.home = mission::HomePosition{kLineOrigin, 0};
    for (int i = 0; i <= legs; ++i) {
        mission::Waypoint w;
        w.position = mission::geodesicDirect(kLineOrigin, 90, 1000.0 * i).point;
        w.altitude = 30;
        w.speed = 10;
        r.segments.push_back(w);
    }
    mission::Mission m;
    m.name = QStringLiteral("line");
    m.routes.push_back(r);
    return m;
}

// 288 W at 10 m/s: 8 Wh per 1000 m leg. 22.5 Wh with a 20 % reserve: 18 Wh usable.
inline const QByteArray kLineQuadProfile = R"({"name": "Line quad", "batteryWh": 22.5, "reserve": 0.2, "cruiseSpeed": 10,
  "climbRate": 2, "descentRate": 1, "hoverPowerW": 360, "cruisePowerW": 288, "climbPowerW": 540, "descentPowerW": 180})";

} // namespace sortie::test
