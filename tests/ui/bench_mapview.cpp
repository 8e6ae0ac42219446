// Frames per second drawing the map with 10,000 waypoints and 20 moving vehicles, offscreen with
// the software scene graph: while panning (route overview and zoomed in) and while dragging a
// waypoint. Each frame is a full polish + paint + render of the 1280x800 window (grabWindow).
// Panning by whole pixels mostly moves the layers' pictures; "a long way" also redraws them.
#include "CoordinateListModel.h"
#include "MapView.h"
#include "QuickScene.h"
#include "RouteLayer.h"
#include "VehicleLayer.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QStandardItemModel>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <cstdio>
#include <ctime>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 13 }
    RouteLayer { objectName: "route"; anchors.fill: parent; map: map; editable: true }
    VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map }
}
)";

enum Role { IdRole = Qt::UserRole + 1, NameRole, LatRole, LonRole, HeadingRole, HomeLatRole, HomeLonRole };

struct Fleet
{
    QStandardItemModel model;
    int tick = 0;

    Fleet()
    {
        model.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"},
                                {HeadingRole, "heading"}, {HomeLatRole, "homeLatitude"}, {HomeLonRole, "homeLongitude"}});
        for (int i = 0; i < 20; ++i) {
            auto *item = new QStandardItem;
            item->setData(QStringLiteral("v%1").arg(i), IdRole);
            item->setData(QStringLiteral("Vehicle %1").arg(i + 1), NameRole);
            item->setData(56.93 + (i % 5) * 0.01, HomeLatRole);
            item->setData(24.05 + (i / 5) * 0.02, HomeLonRole);
            model.appendRow(item);
        }
        move();
    }

    // Every vehicle flies a step around its own circle: one position and heading update each.
    void move()
    {
        ++tick;
        for (int i = 0; i < model.rowCount(); ++i) {
            const double angle = tick * 0.05 + i;
            const QModelIndex index = model.index(i, 0);
            model.setItemData(index, {{LatRole, index.data(HomeLatRole).toDouble() + 0.004 * std::sin(angle)},
                                      {LonRole, index.data(HomeLonRole).toDouble() + 0.007 * std::cos(angle)},
                                      {HeadingRole, std::fmod(angle * 57.3 + 180.0, 360.0)}});
        }
    }
};

double framesPerSecond(int frames, qint64 nanoseconds)
{
    return frames / (nanoseconds / 1e9);
}

// CPU time of the GUI thread, which polishes, paints and renders in grabWindow: on a shared
// machine it says what a frame costs even when other processes take the cores.
qint64 threadCpuNanoseconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

} // namespace

int main(int argc, char *argv[])
{
    sortie::test::useSoftwareRendering();
    QGuiApplication app(argc, argv);
    const int frames = argc > 1 ? std::max(10, std::atoi(argv[1])) : 200;
    const QString only = argc > 2 ? QString::fromLocal8Bit(argv[2]) : QString(); // run cases containing this

    sortie::test::QuickScene scene(kScene, QSize(1280, 800));
    if (!scene.isReady()) {
        std::fprintf(stderr, "scene failed: %s\n", qPrintable(scene.errors()));
        return 1;
    }
    auto *map = scene.find<MapView>(QStringLiteral("map"));
    auto *route = scene.find<RouteLayer>(QStringLiteral("route"));
    auto *vehicles = scene.find<VehicleLayer>(QStringLiteral("vehicles"));

    // A survey of 10,000 waypoints: 100 lines of 100 over about 6 x 8 km.
    CoordinateListModel waypoints;
    std::vector<QGeoCoordinate> points;
    for (int line = 0; line < 100; ++line) {
        for (int i = 0; i < 100; ++i) {
            const int along = line % 2 == 0 ? i : 99 - i;
            points.emplace_back(56.92 + line * 0.0006, 24.03 + along * 0.0012, 50);
        }
    }
    waypoints.assign(points);
    route->setModel(&waypoints);
    Fleet fleet;
    vehicles->setModel(&fleet.model);

    // Warm up: base-map tiles for the views below land in the cache.
    route->fitToMap(20);
    for (int i = 0; i < 20; ++i) {
        QTest::qWait(20);
        scene.grab();
    }

    std::printf("bench_mapview: %d frames per case, 1280x800, software scene graph, %d waypoints, %d vehicles\n",
                frames, waypoints.count(), vehicles->count());
    std::printf("%-42s %9s %10s %13s %10s\n", "case", "fps", "ms/frame", "cpu ms/frame", "waypoints");

    auto run = [&](const char *name, auto step) {
        if (!only.isEmpty() && !QString::fromLatin1(name).contains(only))
            return;
        QElapsedTimer timer;
        timer.start();
        const qint64 cpuStart = threadCpuNanoseconds();
        for (int i = 0; i < frames; ++i) {
            if (step(i))
                fleet.move();
            scene.grab();
            QCoreApplication::processEvents(); // tiles finishing on worker threads
        }
        const qint64 elapsed = timer.nsecsElapsed();
        const qint64 cpu = threadCpuNanoseconds() - cpuStart;
        std::printf("%-42s %9.1f %10.2f %13.2f %10d\n", name, framesPerSecond(frames, elapsed), elapsed / 1e6 / frames,
                    cpu / 1e6 / frames, route->visibleWaypointCount());
    };

    route->fitToMap(20);
    // Each step returns whether the vehicles move in that frame too.
    run("nothing changes (render only)", [&](int) { return false; });
    run("pan, whole route on screen", [&](int i) { map->panBy(i % 40 < 20 ? 3 : -3, 1); return true; });

    map->setCenter(QGeoCoordinate(56.95, 24.09));
    map->setZoomLevel(15.5);
    run("pan, zoomed in (part of route)", [&](int i) { map->panBy(i % 40 < 20 ? 4 : -4, 2); return true; });

    // A pan that keeps going one way: the layers' pictures run out of margin every 40-odd frames.
    run("pan a long way, zoomed in", [&](int i) { map->panBy(i % 400 < 200 ? 6 : -6, 2); return true; });

    // Zooming lays every layer out anew each frame (a pinch or a smooth wheel).
    const double zoom = map->zoomLevel();
    run("zoom in and out, vehicles moving", [&](int i) {
        map->zoomAroundPoint(QPointF(640, 400), zoom + 0.02 * (i % 100 < 50 ? i % 50 : 50 - i % 50));
        return true;
    });

    route->fitToMap(20);
    run("vehicles moving, map still", [&](int) { return true; });

    // Drag waypoint 5050 in small steps, as a hand would.
    map->setCenter(waypoints.get(5050));
    map->setZoomLevel(15);
    scene.grab();
    const QPoint start = route->waypointPosition(5050).toPoint();
    QTest::mousePress(&scene.view(), Qt::LeftButton, {}, start);
    run("drag a waypoint (zoomed in)", [&](int i) {
        QTest::mouseMove(&scene.view(), start + QPoint(10 + i % 50, 10 + (i / 2) % 30));
        return true;
    });
    QTest::mouseRelease(&scene.view(), Qt::LeftButton, {}, start + QPoint(20, 20));

    route->fitToMap(20);
    scene.grab();
    const QPoint overview = route->waypointPosition(5050).toPoint();
    QTest::mousePress(&scene.view(), Qt::LeftButton, {}, overview);
    run("drag a waypoint (whole route on screen)", [&](int i) {
        QTest::mouseMove(&scene.view(), overview + QPoint(10 + i % 50, 10 + (i / 2) % 30));
        return true;
    });
    QTest::mouseRelease(&scene.view(), Qt::LeftButton, {}, overview + QPoint(20, 20));
    return 0;
}
