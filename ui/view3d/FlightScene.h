#pragma once

#include "MeshGeometry.h"
#include "OrbitCamera.h"
#include "SceneBuilder.h"

#include <QObject>
#include <QPointer>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <memory>

namespace sortie::client {
class RouteDocument;
class FleetRoutes;
}
namespace sortie::airspace {
class Airspace;
}
namespace sortie::terrain {
class ElevationService;
}

namespace sortie::ui {

class Theme;

// What the 3D view draws (docs/view3d.md): the ground under the open route from the elevation
// service (a grid sampled once for the route's area, again only when the route leaves it or the
// terrain changes), the open route's flown path and every fleet route in its vehicle's colour, and
// the zones as volumes in their map colours. Meshes are built off the GUI thread (scene3d::
// SceneBuilder): the terrain by itself (its detail follows the camera's target), the routes and
// zones by themselves (a selection or an edit does not rebuild the ground).
class FlightScene : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_MOC_INCLUDE("RouteDocument.h")
    Q_MOC_INCLUDE("FleetRoutes.h")
    Q_MOC_INCLUDE("Airspace.h")
    Q_MOC_INCLUDE("ElevationService.h")
    Q_MOC_INCLUDE("Theme.h")
    Q_PROPERTY(sortie::client::RouteDocument *document READ document WRITE setDocument NOTIFY inputsChanged)
    Q_PROPERTY(sortie::client::FleetRoutes *fleetRoutes READ fleetRoutes WRITE setFleetRoutes NOTIFY inputsChanged)
    Q_PROPERTY(sortie::airspace::Airspace *airspace READ airspace WRITE setAirspace NOTIFY inputsChanged)
    Q_PROPERTY(sortie::terrain::ElevationService *elevation READ elevation WRITE setElevation NOTIFY inputsChanged)
    Q_PROPERTY(sortie::ui::Theme *theme READ theme WRITE setTheme NOTIFY inputsChanged)
    Q_PROPERTY(double exaggeration READ exaggeration WRITE setExaggeration NOTIFY exaggerationChanged)
    Q_PROPERTY(sortie::ui::OrbitCamera *camera READ camera CONSTANT)
    Q_PROPERTY(sortie::ui::MeshGeometry *terrain READ terrainGeometry CONSTANT)
    Q_PROPERTY(sortie::ui::MeshGeometry *routes READ routesGeometry CONSTANT)
    Q_PROPERTY(sortie::ui::MeshGeometry *curtains READ curtainsGeometry CONSTANT)
    Q_PROPERTY(sortie::ui::MeshGeometry *zones READ zonesGeometry CONSTANT)
    Q_PROPERTY(bool hasScene READ hasScene NOTIFY built)
    Q_PROPERTY(bool terrainMissing READ terrainMissing NOTIFY built)  // part of the ground has no data (drawn as such)
    Q_PROPERTY(int builds READ builds NOTIFY built)
    Q_PROPERTY(int selectedRow READ selectedRow NOTIFY built)

public:
    explicit FlightScene(QObject *parent = nullptr);
    ~FlightScene() override;

    client::RouteDocument *document() const;
    void setDocument(client::RouteDocument *document);
    client::FleetRoutes *fleetRoutes() const;
    void setFleetRoutes(client::FleetRoutes *routes);
    airspace::Airspace *airspace() const;
    void setAirspace(airspace::Airspace *airspace);
    terrain::ElevationService *elevation() const;
    void setElevation(terrain::ElevationService *elevation);
    Theme *theme() const;
    void setTheme(Theme *theme);
    double exaggeration() const { return m_exaggeration; }
    void setExaggeration(double factor);

    OrbitCamera *camera() { return &m_camera; }
    MeshGeometry *terrainGeometry() { return m_terrain; }
    MeshGeometry *routesGeometry() { return m_routes; }
    MeshGeometry *curtainsGeometry() { return m_curtains; }
    MeshGeometry *zonesGeometry() { return m_zones; }
    bool hasScene() const { return m_hasScene; }
    bool terrainMissing() const { return m_terrainMissing; }
    int builds() const { return m_builds; }
    int selectedRow() const { return m_selectedRow; }

    // Frames the open route (every route when none is open).
    Q_INVOKABLE void fitRoute();
    // The open route's waypoint under a pixel of a w×h view (within 14 px), its route row, or -1;
    // pickAt selects it in the document (the table and the map follow).
    Q_INVOKABLE int waypointAt(double x, double y, double width, double height) const;
    Q_INVOKABLE bool pickAt(double x, double y, double width, double height);
    // Where a scene point is drawn in a w×h view (NaN behind the camera), and the open route's
    // waypoints and path as drawn: for the tests and the tooltips.
    Q_INVOKABLE QPointF toScreen(const QVector3D &scene, double width, double height) const;
    Q_INVOKABLE int waypointCount() const;
    Q_INVOKABLE QVector3D waypointPosition(int index) const;
    Q_INVOKABLE int waypointRow(int index) const;
    const scene3d::SceneMeshes *meshes() const { return m_overlay.get(); }
    const scene3d::HeightGrid *grid() const { return m_grid.get(); }
    const scene3d::SceneFrame &frame() const { return m_frame; }
    // Blocks until the builds asked for are in (tests, the benchmark).
    Q_INVOKABLE void waitForBuilds();

signals:
    void inputsChanged();
    void exaggerationChanged();
    void built();

private:
    void schedule(bool terrainToo);
    void rebuild();
    void terrainBuilt();
    void overlayBuilt();
    void followCamera();

    QPointer<client::RouteDocument> m_document;
    QPointer<client::FleetRoutes> m_fleetRoutes;
    QPointer<airspace::Airspace> m_airspace;
    QPointer<terrain::ElevationService> m_elevation;
    QPointer<Theme> m_theme;
    double m_exaggeration = 1.0;
    OrbitCamera m_camera;
    MeshGeometry *m_terrain, *m_routes, *m_curtains, *m_zones;
    scene3d::SceneBuilder m_terrainBuilder, m_overlayBuilder;
    std::shared_ptr<const scene3d::HeightGrid> m_grid;
    scene3d::SceneFrame m_frame;
    std::shared_ptr<const scene3d::SceneMeshes> m_overlay;
    QVector3D m_terrainFocus;
    bool m_gridStale = true;
    bool m_pending = false, m_pendingTerrain = false;
    bool m_hasScene = false, m_terrainMissing = false;
    bool m_fitted = false;
    bool m_openRouteFirst = false;
    int m_builds = 0;
    int m_selectedRow = -1;
};

} // namespace sortie::ui
