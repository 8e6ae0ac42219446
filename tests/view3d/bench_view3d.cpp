// bench_view3d: the 3D view under Xvfb with OpenGL (Mesa's llvmpipe unless a GPU is there): a 10 × 10
// km area of 30 m DEM (an SRTM1 tile made here), a 1,000-waypoint route and 50 zones. Prints the
// scene's open time, frames per second and frame-time p50/p99 while orbiting, and the CPU an idle
// view takes. Figures in docs/performance.md ("3D view").
#include "ProcessStats.h"
#include "View3dScene.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <cstdio>

using namespace sortie;
using namespace sortie::test;

int main(int argc, char **argv)
{
    useXWithOpenGl();
    QGuiApplication app(argc, argv);
    const QString problem = openGlProblem();
    if (!problem.isEmpty()) {
        std::fprintf(stderr, "bench_view3d: %s\n", qPrintable(problem));
        return 1;
    }
    std::printf("renderer: %s\n", qPrintable(glRenderer()));
    View3dFixture f;
    QElapsedTimer clock;
    clock.start();
    if (!f.prepare(3601))
        return 1;
    std::printf("DEM written (SRTM1 3601 x 3601): %.0f ms\n", double(clock.elapsed()));

    // 1,000 waypoints: ten 10 km lines of 100 across the area, at 1,300 m AMSL.
    mission::Route route;
    const double dLat = 0.09, dLon = 0.13;  // ~10 km each way at 46.5° N
    for (int line = 0; line < 10; ++line)
        for (int k = 0; k < 100; ++k) {
            const double t = k / 99.0;
            const double lon = 7.5 - dLon / 2 + dLon * (line % 2 ? 1.0 - t : t);
            route.segments.push_back(waypointAt(46.5 - dLat / 2 + dLat * line / 9.0, lon, 1300.0 + 20.0 * (k % 5)));
        }
    f.document.load(route);
    // 50 zones: circles and squares over the area, floors and ceilings of three kinds.
    for (int i = 0; i < 50; ++i) {
        airspace::Zone zone;
        zone.name = QStringLiteral("Zone %1").arg(i + 1);
        const mission::GeoPoint c{46.5 - dLat / 2 + dLat * (i / 7) / 7.0, 7.5 - dLon / 2 + dLon * (i % 7) / 6.0};
        if (i % 2 == 0) {
            zone.shape = airspace::ZoneCircle{c, 250.0 + 10.0 * i};
        } else {
            const double d = 0.002;
            zone.shape = airspace::ZonePolygons{{airspace::ZonePolygon{
                {{{c.latitude - d, c.longitude - d}, {c.latitude - d, c.longitude + d}, {c.latitude + d, c.longitude + d}, {c.latitude + d, c.longitude - d}}}}}};
        }
        if (i % 3 == 1)
            zone.floor = airspace::HeightLimit{60.0, terrain::HeightReference::AboveTerrain};
        if (i % 3 != 2)
            zone.ceiling = airspace::HeightLimit{1500.0, terrain::HeightReference::Amsl};
        f.airspace->insertCustomZone(i, zone);
    }
    f.document.analyzer()->recomputeNow();

    const qint64 heapBefore = heapBytesInUse();
    clock.restart();
    if (!f.open(QSize(1280, 800)))
        return 1;
    ui::FlightScene *scene = f.flightScene();
    const double shown = double(clock.nsecsElapsed()) / 1e6;
    if (!QTest::qWaitFor([&] { return scene->hasScene(); }, 30000))
        return 1;
    const double overlay = double(clock.nsecsElapsed()) / 1e6;
    scene->waitForBuilds();
    QCoreApplication::processEvents();
    f.scene->grab();
    const double complete = double(clock.nsecsElapsed()) / 1e6;
    std::printf("scene: %d terrain, %d route, %d curtain, %d zone triangles\n", scene->terrainGeometry()->triangleCount(),
                scene->routesGeometry()->triangleCount(), scene->curtainsGeometry()->triangleCount(), scene->zonesGeometry()->triangleCount());
    std::printf("open: window shown %.0f ms, routes and zones in %.0f ms, terrain in and first frame %.0f ms\n", shown, overlay, complete);
    std::printf("heap of the 3D view: %.1f MB\n", double(heapBytesInUse() - heapBefore) / 1e6);

    // Orbit: each frame turns the camera 1.5°, the next asked for when the last was swapped.
    QQuickWindow &window = f.scene->view();
    std::vector<double> frameMs;
    QElapsedTimer frame;
    QEventLoop loop;
    const int frames = 240;
    QObject::connect(&window, &QQuickWindow::frameSwapped, &loop, [&] {
        if (frame.isValid())
            frameMs.push_back(double(frame.nsecsElapsed()) / 1e6);
        if (int(frameMs.size()) >= frames) {
            loop.quit();
            return;
        }
        frame.restart();
        QTimer::singleShot(0, &loop, [&] { scene->camera()->orbit(5.0, (frameMs.size() % 60 < 30) ? 0.5 : -0.5); });
    });
    QElapsedTimer total;
    total.start();
    frame.start();
    scene->camera()->orbit(5.0, 0.0);
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    loop.exec();
    const double seconds = double(total.nsecsElapsed()) / 1e9;
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    const auto pct = [&](double p) { return sorted.empty() ? 0.0 : sorted[std::min(sorted.size() - 1, size_t(p * double(sorted.size())))]; };
    std::printf("orbit: %zu frames in %.2f s: %.1f frames/s, frame time p50 %.1f ms, p99 %.1f ms, max %.1f ms\n", frameMs.size(), seconds,
                double(frameMs.size()) / seconds, pct(0.5), pct(0.99), sorted.empty() ? 0.0 : sorted.back());
    scene->waitForBuilds();
    std::printf("terrain rebuilds while orbiting (its detail follows the target): %d builds in all\n", scene->builds());

    // Idle: nothing changes for 5 s.
    QTest::qWait(1000);
    int idleFrames = 0;
    QObject::connect(&window, &QQuickWindow::frameSwapped, [&] { ++idleFrames; });
    const ProcessStats a = ProcessStats::of();
    QElapsedTimer idle;
    idle.start();
    QTest::qWait(5000);
    const ProcessStats b = ProcessStats::of();
    const double idleSeconds = double(idle.nsecsElapsed()) / 1e9;
    std::printf("idle: %d frames in %.1f s, CPU %.2f %% of a core\n", idleFrames, idleSeconds, 100.0 * (b.cpuSeconds - a.cpuSeconds) / idleSeconds);
    std::printf("resident: %.0f MB\n", double(b.residentKiB) / 1024.0);
    return 0;
}
