#pragma once
// Shared builders for the format tests: a route using every feature each format can carry.

#include "AreaScan.h"
#include "TestData.h"
#include "LocalTangentPlane.h"
#include "Mission.h"

#include <QFile>
#include <QString>

namespace sortie::mission::test {

inline QByteArray readSample(const QString &name)
{
    QFile f((QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/qgc/")) + name);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("missing sample %s", qPrintable(name));
    return f.readAll();
}

inline QString samplePath(const QString &name) { return (QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/qgc/")) + name; }

inline AreaScan squareScan(const GeoPoint &centre, double side, double altitude = 50)
{
    const LocalTangentPlane plane(centre);
    const double h = side / 2;
    AreaScan s;
    for (const PlanePoint p : {PlanePoint{-h, -h}, PlanePoint{h, -h}, PlanePoint{h, h}, PlanePoint{-h, h}})
        s.polygon.push_back(plane.unproject(p));
    s.parameters.altitude = altitude;
    s.parameters.speed = 7;
    syncDerivedFields(s.parameters);
    return s;
}

inline Waypoint waypoint(double lat, double lon, double alt, double speed = 6)
{
    Waypoint w;
    w.position = {lat, lon};
    w.altitude = alt;
    w.speed = speed;
    w.turnType = TurnType::Straight;
    return w;
}

// What MAVLink formats (WPL, .plan) can carry exactly: take-off, straight and spline waypoints,
// holds, speeds, acceptance radii, ROI, camera actions, yaw, AMSL and AGL, landing, return home.
inline Route mavlinkRoute()
{
    Route r;
    r.settings.name = QStringLiteral("Riga quay");
    r.settings.initialSpeed = 5;
    r.settings.home = HomePosition{{56.9512345678901, 24.1023456789012}, 12.5};
    Waypoint takeoff = waypoint(56.9512345678901, 24.1023456789012, 30, 5);
    takeoff.role = WaypointRole::Takeoff;
    Waypoint a = waypoint(56.952, 24.104, 40.25, 5);
    a.actions = {WaitAction{4.5, false}, CameraTriggerAction{TriggerState::SingleShot}};
    a.acceptanceRadius = 2.5;
    Waypoint b = waypoint(56.953, 24.105, 80, 7.5);
    b.altitudeType = AltitudeType::Amsl;
    b.turnType = TurnType::Spline;
    b.actions = {PoiAction{{56.954, 24.106}, 20, AltitudeType::Agl}, HeadingAction{123.5, false},
                 CameraSeriesByDistanceAction{20, 0, 0}, WaitAction{3, false}};
    Waypoint c = waypoint(56.9541, 24.1071, 45, 7.5);
    c.actions = {CameraSeriesByTimeAction{2, 10, 0}, CameraTriggerAction{TriggerState::StartRecording},
                 CameraTriggerAction{TriggerState::StopRecording}, CameraSeriesByDistanceAction{0, 0, 0},
                 CameraControlAction{60, 0, 15, std::nullopt}};
    Waypoint land = waypoint(56.955, 24.108, 0, 4);
    land.role = WaypointRole::Land;
    r.segments = {takeoff, a, b, c, land};
    r.settings.endAction = EndAction::None;
    return r;
}

} // namespace sortie::mission::test
