#pragma once

#include "HeightGrid.h"
#include "RouteMesh.h"
#include "SceneFrame.h"
#include "TerrainMesh.h"
#include "ZoneMesh.h"

#include <QObject>
#include <QThread>

#include <memory>
#include <vector>

namespace sortie::scene3d {

struct RouteInput
{
    airspace::FlownPath path;
    RouteStyle style;
};

struct ZoneInput
{
    airspace::Zone zone;
    ZoneStyle style;
};

// Everything a scene is made of, as values: a snapshot the builder's thread reads alone.
struct SceneInput
{
    SceneFrame frame;
    std::shared_ptr<const HeightGrid> grid;  // sampled once, shared by every build of the scene
    TerrainOptions terrain;
    std::vector<RouteInput> routes;
    std::vector<ZoneInput> zones;
    bool withTerrain = true;  // false: routes and zones only (the terrain kept from an earlier build)
};

struct SceneMeshes
{
    SceneFrame frame;
    TerrainMesh terrain;
    Mesh routes;    // every route's tube and markers, opaque
    Mesh curtains;  // translucent
    Mesh zones;     // translucent
    std::vector<std::vector<WaypointMark>> waypoints;  // per route, as given
    std::vector<std::vector<QVector3D>> paths;         // per route
    QThread *builtOn = nullptr;                          // the thread that built it (not the GUI's)
    double buildMs = 0.0;
};

SceneMeshes buildScene(const SceneInput &input);

// Builds scenes on Qt's thread pool (QtConcurrent), the newest request winning: a request made
// while one is building is kept and built after it; older results are dropped. `built` is emitted
// on the builder's thread.
class SceneBuilder : public QObject
{
    Q_OBJECT

public:
    explicit SceneBuilder(QObject *parent = nullptr);
    ~SceneBuilder() override;

    void build(SceneInput input);
    bool busy() const { return m_running; }
    std::shared_ptr<const SceneMeshes> latest() const { return m_latest; }
    // Blocks until the newest request is built (`built` emitted from here then).
    void waitForIdle();

signals:
    void built();

private:
    void start(SceneInput input);
    void finish();
    struct Running;
    std::unique_ptr<Running> m_job;
    std::unique_ptr<SceneInput> m_next;
    bool m_running = false;
    std::shared_ptr<const SceneMeshes> m_latest;
};

} // namespace sortie::scene3d
