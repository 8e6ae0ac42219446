#pragma once
// A real route with a server identity (route 42 at version 3, as a UgCS server would send it),
// made from a QGroundControl WPL sample, and the edits the autosave tests make to it.

#include "HciRouteMapper.h"
#include "TestData.h"
#include "Messages.pb.h"
#include "MissionFiles.h"
#include "RouteDocument.h"

#include <QGeoCoordinate>

namespace sortie::test {

inline mission::Route serverRoute()
{
    auto loaded = mission::formats::loadMission((QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/qgc/100Waypoints.waypoints.txt")));
    if (!loaded)
        qFatal("%s", qPrintable(loaded.error().toString()));
    mission::Route route = loaded->mission.routes.front();
    route.segments.resize(12);
    route.settings.name = QStringLiteral("Autosave sample");
    com::ugcs::ucs::proto::Route message = mission::routeToHci(route);
    message.set_id(42);
    message.set_version(3);
    auto imported = mission::routeFromHci(message);
    if (!imported)
        qFatal("%s", qPrintable(imported.error().toString()));
    return imported->route;
}

// Three undo steps: a waypoint added at the end, WP 2 dragged, WP 3's altitude set to 100 m.
inline void editRoute(client::RouteDocument &doc)
{
    const QModelIndex second = doc.model()->index(1);
    const double lat = second.data(mission::RouteModel::LatitudeRole).toDouble();
    const double lon = second.data(mission::RouteModel::LongitudeRole).toDouble();
    doc.editor()->addWaypoint(QGeoCoordinate(lat + 0.002, lon + 0.003));
    doc.editor()->moveWaypoints({1}, {QGeoCoordinate(lat + 0.0003, lon)});
    doc.editor()->setAltitude({2}, 100);
}

} // namespace sortie::test
