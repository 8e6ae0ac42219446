// The zone layer with 2,000 zones (issue 22's benchmark load), offscreen with the software scene
// graph: frames while panning with the whole area on screen and zoomed in, zooming, and hovering
// (the tooltip's lookup). Each frame is a full polish + paint + render of the 1280x800 window
// (grabWindow); "cpu ms/frame" is the GUI thread's CPU, which says what a frame costs on a shared
// machine. The zones: 1,500 polygons of 6-40 corners and 500 circles over about 40 x 40 km.
#include "Airspace.h"
#include "MapView.h"
#include "QuickScene.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"
#include "ZoneLayer.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 10 }
    ZoneLayer { objectName: "zones"; anchors.fill: parent; map: map }
}
)";

// 2,000 zones as a GeoJSON file, the way an operator's zone file arrives.
QByteArray zonesFile()
{
    QRandomGenerator random(22);
    QJsonArray features;
    for (int i = 0; i < 2000; ++i) {
        const double lat = 56.77 + random.generateDouble() * 0.36, lon = 23.77 + random.generateDouble() * 0.66;
        const double radius = 60 + random.generateDouble() * 400;  // metres
        QJsonObject properties{{QStringLiteral("name"), QStringLiteral("Zone %1").arg(i + 1)},
                               {QStringLiteral("kind"), i % 7 == 0 ? QStringLiteral("inclusion") : QStringLiteral("exclusion")},
                               {QStringLiteral("ceiling"), 60 + i % 5 * 30}};
        QJsonObject geometry;
        if (i < 1500) {
            const int corners = 6 + int(random.bounded(35));
            QJsonArray ring;
            for (int c = 0; c <= corners; ++c) {
                const double a = 2 * std::numbers::pi * (c % corners) / corners;
                const double r = radius * (0.7 + 0.3 * std::cos(3 * a));
                ring.append(QJsonArray{lon + r * std::sin(a) / (111320.0 * std::cos(lat * std::numbers::pi / 180)),
                                       lat + r * std::cos(a) / 110540.0});
            }
            geometry = {{QStringLiteral("type"), QStringLiteral("Polygon")}, {QStringLiteral("coordinates"), QJsonArray{ring}}};
        } else {
            geometry = {{QStringLiteral("type"), QStringLiteral("Point")}, {QStringLiteral("coordinates"), QJsonArray{lon, lat}}};
            properties.insert(QStringLiteral("radius"), radius);
        }
        features.append(QJsonObject{{QStringLiteral("type"), QStringLiteral("Feature")}, {QStringLiteral("geometry"), geometry},
                                    {QStringLiteral("properties"), properties}});
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("type"), QStringLiteral("FeatureCollection")}, {QStringLiteral("features"), features}}).toJson();
}

qint64 threadCpuNanoseconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

} // namespace

int main(int argc, char *argv[])
{
    test::useSoftwareRendering();
    QGuiApplication app(argc, argv);
    const int frames = argc > 1 ? std::max(10, std::atoi(argv[1])) : 100;

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("zones.geojson"));
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(zonesFile()) < 0)
            return 1;
    }
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    mission::RouteModel route;
    mission::RouteAnalyzer analyzer(&route);
    airspace::Airspace store(&settings, &analyzer, &route, nullptr);
    QElapsedTimer load;
    load.start();
    if (!store.loadFile(path) || store.count() != 2000) {
        std::fprintf(stderr, "bench_zonelayer: %d zones loaded, 2000 expected\n", store.count());
        return 1;
    }
    const double loadMs = load.nsecsElapsed() / 1e6;

    test::QuickScene scene(kScene, QSize(1280, 800));
    if (!scene.isReady()) {
        std::fprintf(stderr, "scene failed: %s\n", qPrintable(scene.errors()));
        return 1;
    }
    auto *map = scene.find<ui::MapView>(QStringLiteral("map"));
    auto *zones = scene.find<ui::ZoneLayer>(QStringLiteral("zones"));
    QElapsedTimer first;
    first.start();
    zones->setAirspace(&store);
    scene.grab();
    const double firstMs = first.nsecsElapsed() / 1e6;
    for (int i = 0; i < 10; ++i) {  // base-map tiles land in the cache
        QTest::qWait(20);
        scene.grab();
    }

    std::printf("bench_zonelayer: %d zones (file read and checked in %.1f ms), first frame with them %.1f ms, %d frames per case, 1280x800\n",
                store.count(), loadMs, firstMs, frames);
    std::printf("%-36s %10s %13s %8s\n", "case", "ms/frame", "cpu ms/frame", "labels");
    const auto run = [&](const char *name, auto step) {
        QElapsedTimer timer;
        timer.start();
        const qint64 cpuStart = threadCpuNanoseconds();
        for (int i = 0; i < frames; ++i) {
            step(i);
            scene.grab();
            QCoreApplication::processEvents();
        }
        std::printf("%-36s %10.2f %13.2f %8d\n", name, timer.nsecsElapsed() / 1e6 / frames,
                    (threadCpuNanoseconds() - cpuStart) / 1e6 / frames, zones->labelCount());
    };
    run("nothing changes (render only)", [](int) {});
    run("pan, all 2,000 on screen", [&](int i) { map->panBy(i % 40 < 20 ? 3 : -3, 1); });
    run("zoom in and out, all on screen", [&](int i) { map->zoomAroundPoint(QPointF(640, 400), 10 + 0.02 * (i % 50)); });
    map->setZoomLevel(14);
    run("pan, zoomed in (a few dozen)", [&](int i) { map->panBy(i % 40 < 20 ? 5 : -5, 2); });
    run("hover (tooltip lookup) + render", [&](int i) { zones->hoverAt(QPointF(300 + i * 7 % 700, 200 + i * 3 % 400)); });
    return 0;
}
