#pragma once
// The survey the resume tests fly: a take-off at home, an area scan over a field east of it with
// the camera every so many metres, and a landing back at home.
#include "LocalTangentPlane.h"
#include "Route.h"

namespace sortie::test {

inline const mission::GeoPoint kResumeHome{56.9500, 24.1000};

inline mission::Route resumeTestRoute(double widthMetres = 240, double lengthMetres = 160)
{
    const mission::LocalTangentPlane plane(kResumeHome);
    mission::Route route;
    route.settings.name = QStringLiteral("Field 7");
    route.settings.safeAltitude = 30;
    route.settings.initialSpeed = 8;
    mission::Waypoint takeoff;
    takeoff.position = kResumeHome;
    takeoff.altitude = 60;
    takeoff.role = mission::WaypointRole::Takeoff;
    route.segments.emplace_back(takeoff);
    mission::AreaScan scan;
    for (const auto &[x, y] : {std::pair{60.0, 40.0}, {60.0 + widthMetres, 40.0}, {60.0 + widthMetres, 40.0 + lengthMetres}, {60.0, 40.0 + lengthMetres}})
        scan.polygon.push_back(plane.unproject({x, y}));
    scan.parameters.altitude = 60;
    scan.parameters.frontOverlapPercent = 75;
    scan.parameters.sideOverlapPercent = 65;
    scan.parameters.speed = 8;
    scan.parameters.turnaroundMeters = 10;
    route.segments.emplace_back(scan);
    mission::Waypoint land = takeoff;
    land.role = mission::WaypointRole::Land;
    route.segments.emplace_back(land);
    return route;
}

} // namespace sortie::test
