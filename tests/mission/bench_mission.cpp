// Mission benchmark: a 10,000-waypoint route saved and loaded as .sortie, its statistics and
// validation, one waypoint move and its undo, a 1 km² area scan, and a step of dragging a corner
// of a 5 km² photogrammetry area on that route (edit + the preview's plan). Prints each figure with its
// target; exits 1 if a target is missed. Run: build/tests/mission/bench_mission
#include "BenchClock.h"
#include "AlgorithmCatalog.h"
#include "AreaScanPlanner.h"
#include "BenchRoute.h"
#include "LocalTangentPlane.h"
#include "MissionFiles.h"
#include "RouteAnalyzer.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "RouteStatistics.h"
#include "SegmentPreview.h"
#include "SegmentPlanning.h"
#include "RouteValidator.h"
#include "SortieFormat.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QGeoCoordinate>
#include <QTemporaryDir>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <thread>
#include <ctime>
#include <vector>

using namespace sortie::mission;
using namespace sortie::mission::formats;

namespace {
using sortie::test::judge;
using sortie::test::loadAverage;
using sortie::test::median;
using sortie::test::threadCpuMs;
using sortie::test::Timing;

bool report(const char *what, Timing t, double targetMs)
{
    const auto verdict = judge(t, targetMs);
    std::printf("%-40s %10.4f ms wall %10.4f ms cpu", what, t.wallMs, t.cpuMs);
    if (targetMs > 0)
        std::printf("   (target < %g ms)%s", targetMs, verdict.note);
    std::printf("\n");
    return verdict.met;
}

}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    constexpr int kWaypoints = 10000;
    bool ok = true;
    std::printf("Sortie mission benchmark (%d waypoints; median of repeated runs; load average %.2f on %u cores)\n", kWaypoints,
                loadAverage(), std::thread::hardware_concurrency());

    Route route;
    report("build the route", median(5, [&] { route = benchRoute(kWaypoints); }), 0);
    Mission mission;
    mission.routes.push_back(route);

    QByteArray bytes;
    report("encode .sortie", median(5, [&] { bytes = writeSortie(mission); }), 0);
    std::printf("%-40s %10.2f MB\n", ".sortie size", bytes.size() / 1e6);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bench.sortie"));
    report("save .sortie (validate, encode, write)", median(5, [&] {
        if (!saveMission(mission, path).ok()) std::abort();
    }), 0);
    Mission loaded;
    ok &= report("load .sortie (read, parse, decode)", median(9, [&] {
        Result<LoadedMission> m = loadMission(path);
        if (!m) std::abort();
        loaded = std::move(m).value().mission;
    }), 100);
    if (!(loaded.routes.at(0).segments == route.segments))
        std::printf("load did not give the route back\n"), ok = false;

    ScanPlanCache cache;
    RouteStatistics st;
    ok &= report("statistics", median(21, [&] { st = computeStatistics(route, &cache); }), 5);
    std::printf("%-40s %10.1f km, %.0f s\n", "  length, flight time", st.lengthMeters / 1000, st.flightTimeSeconds);
    ValidationReport vr;
    ok &= report("validation", median(21, [&] { vr = validateRoute(route, &cache); }), 5);
    std::printf("%-40s %10d errors, %d warnings\n", "  result", vr.errorCount(), vr.warningCount());

    RouteModel model;
    QUndoStack stack;
    RouteEditor editor(&model, &stack);
    model.resetRoute(route);
    RouteAnalyzer analyzer(&model);  // attached, as in the client: edits only schedule it
    const int moves = 20000;
    QElapsedTimer t;
    const double c0 = threadCpuMs();
    t.start();
    for (int i = 0; i < moves; ++i) {
        const int row = (i * 7919) % kWaypoints;
        const GeoPoint p = std::get<Waypoint>(model.segment(row)).position;
        editor.moveWaypoints({row}, {QGeoCoordinate(p.latitude + 1e-5, p.longitude)});
        stack.undo();
    }
    ok &= report("move one waypoint and undo it", {t.nsecsElapsed() / 1e6 / moves, (threadCpuMs() - c0) / moves}, 0.1);
    if (!(model.route().segments == route.segments))
        std::printf("undo did not restore the route\n"), ok = false;

    AreaScan scan;
    const LocalTangentPlane plane({56.95, 24.1});
    for (const PlanePoint p : {PlanePoint{-500, -500}, PlanePoint{500, -500}, PlanePoint{500, 500}, PlanePoint{-500, 500}})
        scan.polygon.push_back(plane.unproject(p));
    scan.parameters.altitude = 60;
    AreaScanOutcome outcome;
    ok &= report("1 km² area scan", median(21, [&] { outcome = planAreaScan(scan); }), 10);
    std::printf("%-40s %10zu transects, %d photos\n", "  result", outcome.plan->transects.size(), outcome.plan->photoCount);

    // Dragging a corner of a 5 km² photogrammetry area (≥ 2,000 photos) on the 10,000-waypoint
    // route: each mouse move is an EditStep::Continuing edit through the RouteEditor, then the
    // map's preview plans the path (SegmentPreview, what the map draws). One step must fit a frame.
    {
        RouteModel dragModel;
        QUndoStack dragStack;
        RouteEditor dragEditor(&dragModel, &dragStack);
        dragModel.resetRoute(route);
        RouteAnalyzer dragAnalyzer(&dragModel);  // attached, as in the client: edits only schedule it
        SegmentPreview preview(&dragModel, &dragEditor);
        QList<QGeoCoordinate> corners;
        for (const PlanePoint p : {PlanePoint{-1118, -1118}, PlanePoint{1118, -1118}, PlanePoint{1118, 1118}, PlanePoint{-1118, 1118}}) {
            const GeoPoint g = plane.unproject(p);
            corners << QGeoCoordinate(g.latitude, g.longitude);
        }
        const int row = dragEditor.addSegment(QStringLiteral("PhotogrammetryAlgorithm"), corners);
        dragEditor.setParameter({row}, QStringLiteral("camera"), QStringLiteral("DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)"));
        dragEditor.setParameter({row}, QStringLiteral("groundSampleDistance"), 2.0);
        preview.setRow(row);
        const SegmentPlanOutcome o = planAlgorithmSegment(std::get<AlgorithmSegment>(dragModel.segment(row)), AlgorithmCatalog::builtIn());
        if (!o.ok() || o.plan->photos < 2000)
            std::printf("the photogrammetry area plans %d photos (needs 2000): %s\n", o.ok() ? o.plan->photos : 0,
                        o.ok() ? "" : qPrintable(o.errors.front())), ok = false;
        const GeoPoint start = plane.unproject({1118, 1118});
        const int stepsBefore = dragStack.count();
        int step = 0;
        const Timing t = median(31, [&] {
            ++step;
            if (!dragEditor.moveVertex(row, 2, QGeoCoordinate(start.latitude + step * 2e-6, start.longitude + step * 2e-6), EditStep::Continuing))
                std::abort();
            if (preview.path().isEmpty())
                std::abort();
        });
        ok &= report("drag a corner of 5 km² photogrammetry", t, 16);
        std::printf("%-40s %10d photos, %lld path points, %d plans, %d undo step(s) for the drag\n", "  result", o.ok() ? o.plan->photos : 0,
                    (long long)preview.path().size(), preview.planCount(), dragStack.count() - stepsBefore);
    }
    std::printf(ok ? "all targets met\n" : "TARGETS MISSED\n");
    return ok ? 0 : 1;
}
