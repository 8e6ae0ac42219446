#include "SceneBuilder.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace sortie::scene3d {

SceneMeshes buildScene(const SceneInput &input)
{
    QElapsedTimer clock;
    clock.start();
    SceneMeshes out;
    out.frame = input.frame;
    out.builtOn = QThread::currentThread();
    static const HeightGrid none;
    const HeightGrid &grid = input.grid ? *input.grid : none;
    if (input.withTerrain)
        out.terrain = buildTerrain(grid, input.frame, input.terrain);
    for (const RouteInput &r : input.routes) {
        RouteMesh m = buildRoute(r.path, input.frame, grid, r.style);
        out.routes.append(m.path);
        out.curtains.append(m.curtain);
        out.waypoints.push_back(std::move(m.waypoints));
        out.paths.push_back(std::move(m.points));
    }
    // Zones wholly beyond the terrain (by more than its own size) are left out: a server's or a
    // file's zones may cover a country.
    const double margin = std::max(grid.width(), grid.depth());
    for (const ZoneInput &z : input.zones) {
        ZoneMesh m = buildZone(z.zone, input.frame, grid, z.style);
        if (!grid.empty() && !m.outline.empty()) {
            double w = m.outline.front().x, e = w, s = m.outline.front().y, n = s;
            for (const mission::PlanePoint &p : m.outline) {
                w = std::min(w, p.x);
                e = std::max(e, p.x);
                s = std::min(s, p.y);
                n = std::max(n, p.y);
            }
            if (e < grid.east0 - margin || w > grid.east0 + grid.width() + margin || n < grid.north0 - margin
                || s > grid.north0 + grid.depth() + margin)
                continue;
        }
        out.zones.append(m.mesh);
    }
    out.buildMs = double(clock.nsecsElapsed()) / 1e6;
    return out;
}

struct SceneBuilder::Running
{
    QFutureWatcher<SceneMeshes> watcher;
};

SceneBuilder::SceneBuilder(QObject *parent) : QObject(parent), m_job(std::make_unique<Running>())
{
    connect(&m_job->watcher, &QFutureWatcher<SceneMeshes>::finished, this, &SceneBuilder::finish);
}

void SceneBuilder::finish()
{
    if (!m_running || !m_job->watcher.isFinished())
        return;  // handled already (waitForIdle), or a signal of an earlier job
    m_running = false;
    if (m_next) {
        // a newer request came while this one was building: this result is stale
        std::unique_ptr<SceneInput> next = std::move(m_next);
        start(std::move(*next));
        return;
    }
    m_latest = std::make_shared<const SceneMeshes>(m_job->watcher.result());
    emit built();
}

SceneBuilder::~SceneBuilder()
{
    m_next.reset();
    m_job->watcher.waitForFinished();
}

void SceneBuilder::waitForIdle()
{
    while (m_running) {
        m_job->watcher.waitForFinished();
        finish();
    }
}

void SceneBuilder::build(SceneInput input)
{
    if (m_running) {
        m_next = std::make_unique<SceneInput>(std::move(input));
        return;
    }
    start(std::move(input));
}

void SceneBuilder::start(SceneInput input)
{
    m_running = true;
    m_job->watcher.setFuture(QtConcurrent::run([in = std::move(input)] { return buildScene(in); }));
}

} // namespace sortie::scene3d
