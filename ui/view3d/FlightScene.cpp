#include "FlightScene.h"

#include "Airspace.h"
#include "ElevationService.h"
#include "FleetRoutes.h"
#include "RouteDocument.h"
#include "Theme.h"
#include "ZoneColours.h"

#include <QLoggingCategory>
#include <QTimer>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcScene3d, "sortie.ui.view3d")

namespace sortie::ui {

namespace {

// The grid never exceeds this many nodes a side (a 12 km area at 30 m), coarser beyond.
constexpr int kMaxNodes = 401;
constexpr double kFinestSpacing = 30.0;
constexpr double kMargin = 1000.0;   // metres of ground around the routes
constexpr double kRefocus = 1000.0;  // the camera's target moved this far: the terrain's detail follows

struct PlacedRoute
{
    mission::Route route;
    QColor colour;
    bool open = false;
};

} // namespace

FlightScene::FlightScene(QObject *parent)
    : QObject(parent), m_terrain(new MeshGeometry), m_routes(new MeshGeometry), m_curtains(new MeshGeometry), m_zones(new MeshGeometry)
{
    for (MeshGeometry *g : {m_terrain, m_routes, m_curtains, m_zones})
        g->setParent(this);
    connect(&m_terrainBuilder, &scene3d::SceneBuilder::built, this, &FlightScene::terrainBuilt);
    connect(&m_overlayBuilder, &scene3d::SceneBuilder::built, this, &FlightScene::overlayBuilt);
    connect(&m_camera, &OrbitCamera::changed, this, &FlightScene::followCamera);
}

client::RouteDocument *FlightScene::document() const { return m_document; }
client::FleetRoutes *FlightScene::fleetRoutes() const { return m_fleetRoutes; }
airspace::Airspace *FlightScene::airspace() const { return m_airspace; }
terrain::ElevationService *FlightScene::elevation() const { return m_elevation; }
Theme *FlightScene::theme() const { return m_theme; }

FlightScene::~FlightScene()
{
    m_terrainBuilder.waitForIdle();
    m_overlayBuilder.waitForIdle();
}

void FlightScene::setDocument(client::RouteDocument *document)
{
    if (document == m_document)
        return;
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (document) {
        connect(document->analyzer(), &mission::RouteAnalyzer::recomputed, this, [this] { schedule(false); });
        connect(document, &client::RouteDocument::currentChanged, this, [this] { schedule(false); });
    }
    m_fitted = false;
    schedule(false);
    emit inputsChanged();
}

void FlightScene::setFleetRoutes(client::FleetRoutes *routes)
{
    if (routes == m_fleetRoutes)
        return;
    if (m_fleetRoutes)
        disconnect(m_fleetRoutes, nullptr, this, nullptr);
    m_fleetRoutes = routes;
    if (routes) {
        connect(routes, &QAbstractItemModel::modelReset, this, [this] { schedule(false); });
        connect(routes, &QAbstractItemModel::rowsInserted, this, [this] { schedule(false); });
        connect(routes, &QAbstractItemModel::rowsRemoved, this, [this] { schedule(false); });
        connect(routes, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex &, const QModelIndex &, const QList<int> &roles) {
            if (roles.isEmpty() || roles.contains(client::FleetRoutes::PathRole) || roles.contains(client::FleetRoutes::ColorRole))
                schedule(false);
        });
    }
    schedule(false);
    emit inputsChanged();
}

void FlightScene::setAirspace(airspace::Airspace *airspace)
{
    if (airspace == m_airspace)
        return;
    if (m_airspace)
        disconnect(m_airspace, nullptr, this, nullptr);
    m_airspace = airspace;
    if (airspace)
        connect(airspace, &airspace::Airspace::changed, this, [this] { schedule(false); });
    schedule(false);
    emit inputsChanged();
}

void FlightScene::setElevation(terrain::ElevationService *elevation)
{
    if (elevation == m_elevation)
        return;
    if (m_elevation)
        disconnect(m_elevation, nullptr, this, nullptr);
    m_elevation = elevation;
    if (elevation)
        connect(elevation, &terrain::ElevationService::changed, this, [this] {
            m_gridStale = true;
            schedule(true);
        });
    m_gridStale = true;
    schedule(true);
    emit inputsChanged();
}

void FlightScene::setTheme(Theme *theme)
{
    if (theme == m_theme)
        return;
    if (m_theme)
        disconnect(m_theme, nullptr, this, nullptr);
    m_theme = theme;
    if (theme)
        connect(theme, &Theme::coloursChanged, this, [this] { schedule(false); });
    schedule(false);
    emit inputsChanged();
}

void FlightScene::setExaggeration(double factor)
{
    factor = std::clamp(factor, 1.0, 10.0);
    if (!std::isfinite(factor) || factor == m_exaggeration)
        return;
    // keep the camera's target on the same ground
    const double height = m_frame.heightOf(m_camera.target().y());
    m_exaggeration = factor;
    m_frame = scene3d::SceneFrame(m_frame.origin(), m_frame.baseHeight(), factor);
    QVector3D t = m_camera.target();
    t.setY(float(m_frame.sceneY(height)));
    m_camera.setTarget(t);
    schedule(true);
    emit exaggerationChanged();
}

void FlightScene::schedule(bool terrainToo)
{
    m_pendingTerrain = m_pendingTerrain || terrainToo;
    if (m_pending)
        return;
    m_pending = true;
    QTimer::singleShot(0, this, &FlightScene::rebuild);
}

void FlightScene::followCamera()
{
    const QVector3D t = m_camera.target();
    if (m_grid && std::hypot(t.x() - m_terrainFocus.x(), t.z() - m_terrainFocus.z()) > kRefocus)
        schedule(true);
}

void FlightScene::rebuild()
{
    m_pending = false;
    bool terrainToo = std::exchange(m_pendingTerrain, false);
    const MapPalette palette = m_theme ? m_theme->mapPalette() : MapPalette{};

    std::vector<PlacedRoute> routes;
    if (m_document && !m_document->route().segments.empty())
        routes.push_back({m_document->route(), palette.route, true});
    if (m_fleetRoutes) {
        const std::vector<client::FleetRoute> fleet = m_fleetRoutes->routes();
        for (int row = 0; row < int(fleet.size()); ++row) {
            const QModelIndex index = m_fleetRoutes->index(row);
            if (m_fleetRoutes->data(index, client::FleetRoutes::OpenRole).toBool())
                continue;
            routes.push_back({fleet[size_t(row)].route, m_fleetRoutes->data(index, client::FleetRoutes::ColorRole).value<QColor>(), false});
        }
    }
    m_openRouteFirst = !routes.empty() && routes.front().open;
    std::vector<terrain::ProfileRoute> profiles;
    std::vector<mission::GeoPoint> points;
    for (const PlacedRoute &r : routes) {
        profiles.push_back(terrain::profileRouteOf(r.route));
        for (const terrain::ProfileWaypoint &w : profiles.back().waypoints)
            points.push_back(w.position);
    }
    if (points.empty()) {
        const bool had = m_hasScene;
        m_hasScene = false;
        m_overlay.reset();
        for (MeshGeometry *g : {m_routes, m_curtains, m_zones})
            g->setMesh({});
        if (had)
            emit built();
        return;
    }

    // The ground: sampled once for the routes' area; again when they leave it or the terrain changed.
    const mission::GeoPoint centre = mission::LocalTangentPlane::centroidOf(points);
    const mission::LocalTangentPlane plane(centre);
    double half = 0.0;
    for (const mission::GeoPoint &p : points) {
        const mission::PlanePoint q = plane.project(p);
        half = std::max({half, std::abs(q.x), std::abs(q.y)});
    }
    half += kMargin;
    bool inside = m_grid && !m_gridStale;
    if (inside) {
        for (const mission::GeoPoint &p : points) {
            const mission::PlanePoint q = m_frame.toPlane(p);
            if (q.x < m_grid->east0 || q.y < m_grid->north0 || q.x > m_grid->east0 + m_grid->width() || q.y > m_grid->north0 + m_grid->depth()) {
                inside = false;
                break;
            }
        }
        // far too big a grid for a route much smaller (another route opened): sample again
        if (inside && m_grid->width() > 4.0 * 2.0 * half && m_grid->spacing > kFinestSpacing)
            inside = false;
    }
    if (!inside && m_elevation) {
        const double spacing = std::max(kFinestSpacing, 2.0 * half / (kMaxNodes - 1));
        const int nodes = std::max(2, int(std::ceil(2.0 * half / spacing)) + 1);
        scene3d::SceneFrame sampling(centre, 0.0, m_exaggeration);
        auto grid = std::make_shared<scene3d::HeightGrid>(scene3d::sampleGrid(*m_elevation, sampling, spacing, nodes, nodes));
        const double base = grid->lowest().value_or(0.0);
        m_frame = scene3d::SceneFrame(centre, base, m_exaggeration);
        m_grid = std::move(grid);
        m_gridStale = false;
        m_fitted = m_fitted && false;
        terrainToo = true;
        qCDebug(lcScene3d) << "terrain sampled:" << nodes << "x" << nodes << "nodes at" << spacing << "m," << m_grid->noDataCount() << "without data";
    } else if (!m_grid) {
        m_grid = std::make_shared<scene3d::HeightGrid>();
        m_frame = scene3d::SceneFrame(centre, 0.0, m_exaggeration);
        terrainToo = true;
    }

    scene3d::SceneInput input;
    input.frame = m_frame;
    input.grid = m_grid;
    input.withTerrain = false;
    double top = m_grid->highest().value_or(m_frame.baseHeight());
    for (size_t i = 0; i < routes.size(); ++i) {
        std::optional<terrain::TerrainProfile> ground;
        if (m_elevation)
            ground = terrain::computeProfile(profiles[i], *m_elevation);
        scene3d::RouteInput r;
        r.path = airspace::flownPath(profiles[i], ground ? &*ground : nullptr, airspace::flightEndsOf(routes[i].route), &m_frame.plane());
        r.style.colour = routes[i].colour;
        // thick enough to be seen from the whole scene's distance
        r.style.width = std::clamp(half / 250.0, 3.0, 40.0);
        r.style.markerSize = r.style.width * 2.5;
        for (const airspace::FlownLeg &leg : r.path.legs)
            for (const airspace::FlownPoint &p : leg.points)
                if (std::isfinite(p.in(terrain::HeightReference::Amsl)))
                    top = std::max(top, p.in(terrain::HeightReference::Amsl));
        input.routes.push_back(std::move(r));
    }
    m_selectedRow = m_document ? m_document->currentRow() : -1;
    if (m_airspace) {
        const std::shared_ptr<const airspace::ZoneSet> set = m_airspace->zoneSet();
        if (set)
            for (const airspace::Zone &zone : set->zones()) {
                scene3d::ZoneInput z;
                z.zone = zone;
                z.style.colour = zoneColour(palette, zone);
                z.style.alpha = zone.active ? 0.32f : 0.12f;
                z.style.sceneTop = top + 300.0;
                input.zones.push_back(std::move(z));
            }
    }
    if (terrainToo && m_grid) {
        scene3d::SceneInput t;
        t.frame = m_frame;
        t.grid = m_grid;
        m_terrainFocus = m_camera.target();
        t.terrain.focusEast = m_terrainFocus.x();
        t.terrain.focusNorth = -m_terrainFocus.z();
        const double scale = std::max(m_grid->spacing / kFinestSpacing, 1.0);
        for (double &d : t.terrain.lodDistances)
            d *= scale;
        m_terrainBuilder.build(std::move(t));
    }
    m_overlayBuilder.build(std::move(input));
}

void FlightScene::terrainBuilt()
{
    const std::shared_ptr<const scene3d::SceneMeshes> m = m_terrainBuilder.latest();
    if (!m)
        return;
    m_terrain->setMesh(m->terrain.mesh);
    m_terrainMissing = m->terrain.noDataVertices > 0;
    ++m_builds;
    emit built();
}

void FlightScene::overlayBuilt()
{
    m_overlay = m_overlayBuilder.latest();
    if (!m_overlay)
        return;
    m_routes->setMesh(m_overlay->routes);
    m_curtains->setMesh(m_overlay->curtains);
    m_zones->setMesh(m_overlay->zones);
    m_hasScene = true;
    if (!m_fitted) {
        m_fitted = true;
        fitRoute();
    }
    ++m_builds;
    emit built();
}

void FlightScene::fitRoute()
{
    if (!m_overlay || m_overlay->paths.empty())
        return;
    const size_t count = m_openRouteFirst ? 1 : m_overlay->paths.size();
    QVector3D lo, hi;
    bool any = false;
    for (size_t i = 0; i < count; ++i)
        for (const QVector3D &p : m_overlay->paths[i]) {
            lo = any ? QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z())) : p;
            hi = any ? QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z())) : p;
            any = true;
        }
    if (!any)
        return;
    if (m_grid && !m_grid->empty())
        lo.setY(std::min(lo.y(), float(m_frame.sceneY(m_grid->lowest().value_or(m_frame.baseHeight())))));
    m_camera.fit(lo, hi);
}

QPointF FlightScene::toScreen(const QVector3D &scene, double width, double height) const
{
    const QQuaternion q = m_camera.rotation();
    const QVector3D v = scene - m_camera.position();
    const float ahead = QVector3D::dotProduct(v, q.rotatedVector(QVector3D(0, 0, -1)));
    if (ahead <= 0.0f)
        return QPointF(qQNaN(), qQNaN());
    const double halfH = std::tan(m_camera.fieldOfView() * M_PI / 360.0);
    const double halfW = halfH * (height > 0 ? width / height : 1.0);
    const double x = QVector3D::dotProduct(v, q.rotatedVector(QVector3D(1, 0, 0))) / ahead / halfW;
    const double y = QVector3D::dotProduct(v, q.rotatedVector(QVector3D(0, 1, 0))) / ahead / halfH;
    return QPointF((x + 1.0) / 2.0 * width, (1.0 - y) / 2.0 * height);
}

int FlightScene::waypointCount() const
{
    return m_overlay && m_openRouteFirst && !m_overlay->waypoints.empty() ? int(m_overlay->waypoints.front().size()) : 0;
}

QVector3D FlightScene::waypointPosition(int index) const
{
    return index >= 0 && index < waypointCount() ? m_overlay->waypoints.front()[size_t(index)].position : QVector3D();
}

int FlightScene::waypointRow(int index) const
{
    return index >= 0 && index < waypointCount() ? m_overlay->waypoints.front()[size_t(index)].row : -1;
}

int FlightScene::waypointAt(double x, double y, double width, double height) const
{
    int best = -1;
    double bestDistance = 14.0;
    for (int i = 0; i < waypointCount(); ++i) {
        const QPointF p = toScreen(waypointPosition(i), width, height);
        const double d = std::hypot(p.x() - x, p.y() - y);
        if (waypointRow(i) >= 0 && d <= bestDistance) {
            bestDistance = d;
            best = waypointRow(i);
        }
    }
    return best;
}

bool FlightScene::pickAt(double x, double y, double width, double height)
{
    const int row = waypointAt(x, y, width, height);
    if (row < 0 || !m_document)
        return false;
    m_document->selectRows({row});
    return true;
}

void FlightScene::waitForBuilds()
{
    // a rebuild asked for and not started yet starts now
    if (m_pending)
        rebuild();
    m_terrainBuilder.waitForIdle();
    m_overlayBuilder.waitForIdle();
}

} // namespace sortie::ui
