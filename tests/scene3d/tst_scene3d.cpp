// core/scene3d: terrain tiles from a known DEM (heights, exaggeration, no cracks between levels of
// detail, no-data marked), zone volumes (a cylinder at its radius, a cone frustum's two radii, an
// AGL floor on the ground), the flown path as a tube with curtains and markers, and the builder
// running off the GUI thread.
#include "ElevationService.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "SceneBuilder.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>
#include <set>

using namespace sortie;
using namespace sortie::scene3d;

namespace {

HeightGrid gridOf(int columns, int rows, double spacing, const std::function<double(int, int)> &h)
{
    HeightGrid g;
    g.columns = columns;
    g.rows = rows;
    g.spacing = spacing;
    g.east0 = -0.5 * (columns - 1) * spacing;
    g.north0 = -0.5 * (rows - 1) * spacing;
    g.heights.resize(std::size_t(columns * rows));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c)
            g.heights[std::size_t(r * columns + c)] = float(h(c, r));
    return g;
}

const GeoPoint kOrigin{46.5, 7.5};

} // namespace

class TestScene3d : public QObject
{
    Q_OBJECT

private slots:
    void frameIsEastUpSouth()
    {
        const SceneFrame frame(kOrigin, 500.0, 3.0);
        const QVector3D p = frame.toScene(100.0, 200.0, 510.0);
        QCOMPARE(p, QVector3D(100.0f, 30.0f, -200.0f));
        // a point 1 km north of the origin is at -z, 1 km
        const mission::GeodesicDirect north = mission::geodesicDirect(kOrigin, 0.0, 1000.0);
        const QVector3D n = frame.toScene(north.point, 500.0);
        QVERIFY(std::abs(n.x()) < 0.01f);
        QVERIFY(std::abs(n.z() + 1000.0f) < 0.1f);
        QCOMPARE(frame.heightOf(30.0), 510.0);
    }

    void terrainHasTheDemsHeightsExaggerated()
    {
        const auto h = [](int c, int r) { return 400.0 + 0.5 * c + 2.0 * r; };
        const HeightGrid grid = gridOf(41, 33, 30.0, h);
        const SceneFrame frame(kOrigin, 400.0, 2.0);
        TerrainOptions options;
        options.tileCells = 16;
        options.lodDistances = {1e9};  // every tile at full detail
        const TerrainMesh t = buildTerrain(grid, frame, options);
        QCOMPARE(int(t.tiles.size()), 3 * 2);
        QCOMPARE(t.noDataVertices, 0);
        int checked = 0;
        for (const TerrainTile &tile : t.tiles) {
            QCOMPARE(tile.stride, 1);
            for (std::uint32_t v = tile.firstVertex; v < tile.firstSkirtVertex; ++v) {
                const QVector3D p = t.mesh.positions[v];
                const int c = int(std::lround((p.x() - grid.east0) / grid.spacing));
                const int r = int(std::lround((-p.z() - grid.north0) / grid.spacing));
                QCOMPARE(p.x(), float(grid.eastOf(c)));
                QVERIFY2(std::abs(p.y() - float((h(c, r) - 400.0) * 2.0)) < 1e-3f, qPrintable(QString::number(p.y())));
                ++checked;
            }
        }
        QCOMPARE(checked, 17 * 17 * 4 + 17 * 9 * 2);  // nodes of each tile, shared edges counted twice
        // the surface faces up: every normal has a positive y
        for (std::uint32_t v = 0; v < t.tiles.front().firstSkirtVertex; ++v)
            QVERIFY(t.mesh.normals[v].y() > 0.9f);
    }

    void tilesOfDifferentDetailLeaveNoCrack()
    {
        // rough ground, fine tiles near the focus (the south-west corner), coarse ones further
        const auto h = [](int c, int r) { return 800.0 + 40.0 * std::sin(c * 0.7) * std::cos(r * 0.45) + 3.0 * ((c * 7 + r * 13) % 5); };
        const HeightGrid grid = gridOf(65, 65, 30.0, h);
        const SceneFrame frame(kOrigin, 800.0, 1.5);
        TerrainOptions options;
        options.tileCells = 16;
        options.focusEast = grid.east0;
        options.focusNorth = grid.north0;
        options.lodDistances = {100.0, 500.0, 1000.0};
        const TerrainMesh t = buildTerrain(grid, frame, options);
        std::set<int> strides;
        for (const TerrainTile &tile : t.tiles)
            strides.insert(tile.stride);
        QVERIFY2(strides.size() >= 3, "the focus gives tiles of three levels of detail at least");

        // Along every edge two tiles share: where their surfaces differ, both skirts reach below both.
        int differing = 0, edges = 0;
        for (const TerrainTile &a : t.tiles)
            for (const TerrainTile &b : t.tiles) {
                const bool eastNeighbour = b.column == a.column + a.cellsEast && b.row == a.row;
                const bool northNeighbour = b.row == a.row + a.cellsNorth && b.column == a.column;
                if (!eastNeighbour && !northNeighbour)
                    continue;
                ++edges;
                // the edge's fixed coordinate and a function giving each tile's surface and skirt along it
                const float fixed = eastNeighbour ? float(grid.eastOf(b.column)) : float(-grid.northOf(b.row));
                const auto along = [&](const TerrainTile &tile, bool skirt) {
                    std::map<float, float> line;  // position along the edge -> lowest y there
                    const std::uint32_t from = skirt ? tile.firstSkirtVertex : tile.firstVertex;
                    const std::uint32_t to = skirt ? tile.endVertex : tile.firstSkirtVertex;
                    for (std::uint32_t v = from; v < to; ++v) {
                        const QVector3D p = t.mesh.positions[v];
                        if ((eastNeighbour ? p.x() : p.z()) != fixed)
                            continue;
                        const float key = eastNeighbour ? p.z() : p.x();
                        auto it = line.find(key);
                        if (it == line.end() || p.y() < it->second)
                            line[key] = p.y();
                    }
                    return line;
                };
                const auto interpolate = [](const std::map<float, float> &line, float at) {
                    auto hi = line.lower_bound(at);
                    if (hi == line.end())
                        return std::prev(hi)->second;
                    if (hi->first == at || hi == line.begin())
                        return hi->second;
                    auto lo = std::prev(hi);
                    const float f = (at - lo->first) / (hi->first - lo->first);
                    return lo->second + (hi->second - lo->second) * f;
                };
                const auto sa = along(a, false), sb = along(b, false), ka = along(a, true), kb = along(b, true);
                QVERIFY(sa.size() >= 2 && sb.size() >= 2 && !ka.empty() && !kb.empty());
                // the fine tile's nodes: each position along the edge either tile has a node
                std::set<float> keys;
                for (const auto &[k, y] : sa)
                    keys.insert(k);
                for (const auto &[k, y] : sb)
                    keys.insert(k);
                for (float k : keys) {
                    const float ya = interpolate(sa, k), yb = interpolate(sb, k);
                    if (std::abs(ya - yb) > 0.01f)
                        ++differing;
                    const float bottom = std::min(ya, yb);
                    QVERIFY2(interpolate(ka, k) < bottom && interpolate(kb, k) < bottom,
                             qPrintable(QStringLiteral("a crack at %1 on the edge at %2").arg(k).arg(fixed)));
                }
                // where both have a node, it is the same point of the DEM
                for (const auto &[k, y] : sa)
                    if (sb.count(k))
                        QVERIFY(std::abs(sb.at(k) - y) < 1e-3f);
            }
        QVERIFY(edges >= 2 * 4 * 3);
        QVERIFY2(differing > 0, "levels of detail do differ along some edges (the skirts are needed)");
    }

    void heightsComeFromTheElevationServiceAndNoDataIsMarked()
    {
        // An SRTM3 tile N46E007 whose ground rises 1 m per post northwards, with a void in its middle.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const auto height = [](int r, int c) {
            if (r >= 597 && r <= 603 && c >= 597 && c <= 603)
                return -32768;  // SRTM's void
            return 2000 - r;
        };
        QVERIFY(terrain::test::writeHgt(dir.filePath(QStringLiteral("N46E007.hgt")), 1201, height));
        terrain::HgtTileSource tiles(dir.path());
        terrain::ElevationService service;
        service.setSources({&tiles});
        // the tile's centre: N46.5 E7.5 is post (600, 600)
        const SceneFrame frame(GeoPoint{46.5, 7.5}, 1400.0, 1.0);
        const HeightGrid grid = sampleGrid(service, frame, 30.0, 101, 101);
        QCOMPARE(grid.columns, 101);
        QCOMPARE(grid.pending, 0);
        // south-west corner: 1500 m south of the centre, 1500 m west
        const GeoPoint sw = frame.plane().unproject({grid.eastOf(0), grid.northOf(0)});
        const double expected = 2000.0 - (47.0 - sw.latitude) * 1200.0;
        QVERIFY2(std::abs(grid.at(0, 0) - expected) < 0.5, qPrintable(QString::number(grid.at(0, 0))));
        const GeoPoint nw = frame.plane().unproject({grid.eastOf(0), grid.northOf(100)});
        QVERIFY(std::abs(grid.at(0, 100) - (2000.0 - (47.0 - nw.latitude) * 1200.0)) < 0.5);  // 3 km north: 32 posts higher
        QVERIFY(grid.at(0, 100) > grid.at(0, 0) + 30.0);
        QVERIFY(!grid.hasValue(50, 50));  // the void is no data, not sea level
        QVERIFY(grid.noDataCount() > 0 && grid.noDataCount() < 101 * 101 / 10);

        const TerrainMesh t = buildTerrain(grid, frame);
        QVERIFY(t.noDataVertices > 0);
        const QVector4D noData = rgba(TerrainOptions{}.noData, 1.0f);
        const double lowest = *grid.lowest();
        QVERIFY(lowest > 1300.0);
        int marked = 0;
        for (std::uint32_t v = 0; v < t.mesh.vertexCount(); ++v)
            if (t.mesh.colours[v] == noData) {
                ++marked;
                QVERIFY(t.mesh.positions[v].y() >= float(frame.sceneY(lowest)) - 3.0f);  // never at 0 m
            }
        QVERIFY(marked >= t.noDataVertices);
    }

    void aCylindersVerticesLieAtItsRadius()
    {
        const HeightGrid grid = gridOf(11, 11, 100.0, [](int, int) { return 300.0; });
        const SceneFrame frame(kOrigin, 300.0, 2.0);
        airspace::Zone zone;
        zone.shape = airspace::ZoneCircle{kOrigin, 400.0};
        zone.floor = airspace::HeightLimit{350.0, terrain::HeightReference::Amsl};
        zone.ceiling = airspace::HeightLimit{500.0, terrain::HeightReference::Amsl};
        ZoneStyle style;
        style.circleSegments = 48;
        const ZoneMesh m = buildZone(zone, frame, grid, style);
        QVERIFY(m.hasFloor && m.hasLid);
        QCOMPARE(int(m.outline.size()), 48);
        QVERIFY(!m.mesh.empty());
        for (const QVector3D &p : m.mesh.positions) {
            QVERIFY2(std::abs(std::hypot(p.x(), p.z()) - 400.0f) < 0.01f, qPrintable(QString::number(std::hypot(p.x(), p.z()))));
            QVERIFY(std::abs(p.y() - 100.0f) < 1e-3f || std::abs(p.y() - 400.0f) < 1e-3f);  // (350-300)·2, (500-300)·2
        }
        QCOMPARE(m.mesh.colours.front().w(), style.alpha);
    }

    void aConeFrustumNarrowsFromFloorToCeiling()
    {
        const HeightGrid grid = gridOf(11, 11, 100.0, [](int, int) { return 0.0; });
        const SceneFrame frame(kOrigin, 0.0, 1.0);
        airspace::Zone zone;
        zone.shape = airspace::ZoneConeFrustum{kOrigin, 200.0, 800.0};
        zone.floor = airspace::HeightLimit{0.0, terrain::HeightReference::Amsl};
        zone.ceiling = airspace::HeightLimit{150.0, terrain::HeightReference::Amsl};
        const ZoneMesh m = buildZone(zone, frame, grid);
        for (const QVector3D &p : m.mesh.positions) {
            const float r = std::hypot(p.x(), p.z());
            if (p.y() < 1.0f)
                QVERIFY(std::abs(r - 200.0f) < 0.01f);
            else
                QVERIFY(std::abs(r - 800.0f) < 0.01f && std::abs(p.y() - 150.0f) < 1e-3f);
        }
    }

    void anAglFloorFollowsTheGroundAndNoCeilingHasNoLid()
    {
        // ground sloping 10 m per 100 m eastwards
        const HeightGrid grid = gridOf(21, 21, 100.0, [](int c, int) { return 500.0 + 10.0 * c; });
        const SceneFrame frame(kOrigin, 500.0, 1.0);
        airspace::Zone zone;
        std::vector<GeoPoint> ring;
        for (const auto &[e, n] : std::vector<std::pair<double, double>>{{-600, -300}, {600, -300}, {600, 300}, {-600, 300}})
            ring.push_back(frame.plane().unproject({e, n}));
        zone.shape = airspace::ZonePolygons{{airspace::ZonePolygon{{ring}}}};
        zone.floor = airspace::HeightLimit{50.0, terrain::HeightReference::AboveTerrain};
        ZoneStyle style;
        style.sceneTop = 2000.0;
        const ZoneMesh m = buildZone(zone, frame, grid, style);
        QVERIFY(m.hasFloor && !m.hasLid);
        int floorVertices = 0;
        for (const QVector3D &p : m.mesh.positions) {
            if (p.y() > 1400.0f) {
                QVERIFY(std::abs(p.y() - 1500.0f) < 1e-3f);  // 2000 m AMSL
                continue;
            }
            const double ground = *grid.heightAt(p.x(), -p.z());
            QVERIFY2(std::abs(p.y() - float(ground + 50.0 - 500.0)) < 0.01f, qPrintable(QString::number(p.y())));
            ++floorVertices;
        }
        QVERIFY(floorVertices > 8);  // the edges were cut to follow the ground
    }

    void triangulatesAConcavePolygon()
    {
        // an L: area 3 unit squares
        const std::vector<mission::PlanePoint> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        const std::vector<std::uint32_t> tris = triangulate(l);
        QCOMPARE(int(tris.size()), 3 * 4);
        double area = 0;
        for (std::size_t k = 0; k < tris.size(); k += 3) {
            const auto &a = l[tris[k]], &b = l[tris[k + 1]], &c = l[tris[k + 2]];
            const double s = ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
            QVERIFY(s > 0);
            area += s;
        }
        QCOMPARE(area, 3.0);
    }

    void theFlownPathIsATubeWithCurtainsAndMarkers()
    {
        const HeightGrid grid = gridOf(41, 41, 50.0, [](int c, int r) { return 200.0 + 2.0 * c + r; });
        const SceneFrame frame(kOrigin, 200.0, 1.0);
        terrain::ProfileRoute route;
        const auto at = [&](double e, double n) { return frame.plane().unproject({e, n}); };
        route.waypoints = {{at(-500, -500), 300.0, terrain::HeightReference::Amsl, 0, QStringLiteral("1")},
                           {at(500, -500), 350.0, terrain::HeightReference::Amsl, 1, QStringLiteral("2")},
                           {at(500, 500), 320.0, terrain::HeightReference::Amsl, 2, QStringLiteral("3")}};
        const airspace::FlownPath path = airspace::flownPath(route, nullptr, {}, &frame.plane());
        RouteStyle style;
        style.width = 8.0;
        const RouteMesh m = buildRoute(path, frame, grid, style);
        QCOMPARE(m.unknownHeights, 0);
        QCOMPARE(int(m.waypoints.size()), 3);
        QCOMPARE(m.waypoints[1].row, 1);
        QVERIFY((m.waypoints[1].position - QVector3D(500, 150, 500)).length() < 0.5f);
        QVERIFY((m.waypoints[2].position - QVector3D(500, 120, -500)).length() < 0.5f);
        // every tube vertex within half the width (the corners: w/√2) of the path's straight legs
        for (const QVector3D &p : m.path.positions) {
            float best = 1e9f;
            for (std::size_t i = 0; i + 1 < m.points.size(); ++i) {
                const QVector3D a = m.points[i], d = m.points[i + 1] - a;
                const float t = std::clamp(QVector3D::dotProduct(p - a, d) / d.lengthSquared(), 0.0f, 1.0f);
                best = std::min(best, (a + d * t - p).length());
            }
            QVERIFY2(best <= float(style.markerSize) + 0.01f, qPrintable(QString::number(best)));
        }
        // the curtain's foot is on the ground, its top on the path
        int feet = 0;
        for (const QVector3D &p : m.curtain.positions) {
            const double ground = *grid.heightAt(p.x(), -p.z());
            if (std::abs(p.y() - float(ground - 200.0)) < 0.05f)
                ++feet;
        }
        QCOMPARE(feet * 2, int(m.curtain.positions.size()));
        QCOMPARE(m.curtain.colours.front().w(), style.curtainAlpha);
    }

    void theBuilderRunsOffTheGuiThread()
    {
        SceneInput input;
        input.frame = SceneFrame(kOrigin, 0.0, 1.0);
        input.grid = std::make_shared<const HeightGrid>(gridOf(65, 65, 30.0, [](int c, int r) { return 10.0 * std::sin(c * 0.1) + r; }));
        airspace::Zone zone;
        zone.shape = airspace::ZoneCircle{kOrigin, 300.0};
        input.zones.push_back({zone, {}});
        const SceneMeshes direct = buildScene(input);
        SceneBuilder builder;
        QSignalSpy built(&builder, &SceneBuilder::built);
        builder.build(input);
        builder.build(input);  // a second request while the first builds: one result, the newest
        QVERIFY(built.wait(10000));
        QVERIFY(builder.latest());
        QVERIFY(builder.latest()->builtOn != QThread::currentThread());
        QCOMPARE(builder.latest()->terrain.mesh.triangleCount(), direct.terrain.mesh.triangleCount());
        QCOMPARE(builder.latest()->zones.triangleCount(), direct.zones.triangleCount());
        QVERIFY(!builder.busy() || built.wait(10000));
        builder.waitForIdle();
    }
};

QTEST_GUILESS_MAIN(TestScene3d)
#include "tst_scene3d.moc"
