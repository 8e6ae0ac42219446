#include "TerrainMesh.h"

#include <algorithm>
#include <cmath>

namespace sortie::scene3d {

int strideFor(double distance, const TerrainOptions &options)
{
    int stride = 1;
    for (double d : options.lodDistances) {
        if (distance <= d)
            return stride;
        stride *= 2;
    }
    return stride;
}

QColor heightColour(double height, double lowest, double highest)
{
    const double span = highest - lowest;
    const double t = span > 0.0 ? std::clamp((height - lowest) / span, 0.0, 1.0) : 0.3;
    struct Stop { double at; int r, g, b; };
    static constexpr Stop stops[] = {{0.0, 86, 140, 70}, {0.35, 150, 170, 90}, {0.65, 170, 140, 90}, {0.9, 140, 115, 95}, {1.0, 125, 110, 100}};
    for (std::size_t i = 1; i < std::size(stops); ++i)
        if (t <= stops[i].at) {
            const Stop &a = stops[i - 1], &b = stops[i];
            const double f = (t - a.at) / (b.at - a.at);
            return QColor(int(a.r + (b.r - a.r) * f), int(a.g + (b.g - a.g) * f), int(a.b + (b.b - a.b) * f));
        }
    return QColor(125, 110, 100);
}

namespace {

// The nodes a tile of `cells` cells from `first` takes at `stride` (its last node always).
std::vector<int> nodesOf(int first, int cells, int stride)
{
    std::vector<int> out;
    for (int i = 0; i < cells; i += stride)
        out.push_back(first + i);
    out.push_back(first + cells);
    return out;
}

} // namespace

TerrainMesh buildTerrain(const HeightGrid &grid, const SceneFrame &frame, const TerrainOptions &options)
{
    TerrainMesh out;
    if (grid.empty())
        return out;
    const double lowest = grid.lowest().value_or(frame.baseHeight());
    const double highest = grid.highest().value_or(lowest);
    const double fill = lowest;  // a no-data node stands at the lowest known ground, in its own colour
    const QVector4D noData = rgba(options.noData, 1.0f);
    const auto heightAt = [&](int c, int r) {
        const float h = grid.at(c, r);
        return std::isfinite(h) ? double(h) : fill;
    };
    const int tileCells = std::max(options.tileCells, 1);
    const double ex = frame.exaggeration();

    for (int r0 = 0; r0 < grid.rows - 1; r0 += tileCells)
        for (int c0 = 0; c0 < grid.columns - 1; c0 += tileCells) {
            TerrainTile tile;
            tile.column = c0;
            tile.row = r0;
            tile.cellsEast = std::min(tileCells, grid.columns - 1 - c0);
            tile.cellsNorth = std::min(tileCells, grid.rows - 1 - r0);
            // distance from the focus to the tile's nearest point
            const double e0 = grid.eastOf(c0), e1 = grid.eastOf(c0 + tile.cellsEast);
            const double n0 = grid.northOf(r0), n1 = grid.northOf(r0 + tile.cellsNorth);
            const double de = std::max({e0 - options.focusEast, 0.0, options.focusEast - e1});
            const double dn = std::max({n0 - options.focusNorth, 0.0, options.focusNorth - n1});
            tile.stride = strideFor(std::hypot(de, dn), options);
            const std::vector<int> cs = nodesOf(c0, tile.cellsEast, tile.stride);
            const std::vector<int> rs = nodesOf(r0, tile.cellsNorth, tile.stride);
            const int w = int(cs.size());
            const int h = int(rs.size());

            Mesh &m = out.mesh;
            tile.firstVertex = m.vertexCount();
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    const int c = cs[size_t(i)], r = rs[size_t(j)];
                    // the normal from central differences over the grid's own nodes
                    const int cl = std::max(c - 1, 0), cr = std::min(c + 1, grid.columns - 1);
                    const int rd = std::max(r - 1, 0), ru = std::min(r + 1, grid.rows - 1);
                    const double dx = (heightAt(cr, r) - heightAt(cl, r)) * ex / ((cr - cl) * grid.spacing);
                    const double dn2 = (heightAt(c, ru) - heightAt(c, rd)) * ex / ((ru - rd) * grid.spacing);
                    // scene z is south: d/dz = -d/dnorth
                    const QVector3D normal = QVector3D(float(-dx), 1.0f, float(dn2)).normalized();
                    const bool known = grid.hasValue(c, r);
                    if (!known)
                        ++out.noDataVertices;
                    m.addVertex(frame.toScene(grid.eastOf(c), grid.northOf(r), heightAt(c, r)), normal,
                                known ? rgba(heightColour(heightAt(c, r), lowest, highest), 1.0f) : noData);
                }
            // counter-clockwise from above: scene z points south, so north (row + 1) is -z
            for (int j = 0; j + 1 < h; ++j)
                for (int i = 0; i + 1 < w; ++i) {
                    const std::uint32_t a = tile.firstVertex + std::uint32_t(j * w + i);
                    const std::uint32_t b = a + 1, c = a + std::uint32_t(w), d = c + 1;
                    m.addTriangle(a, b, d);
                    m.addTriangle(a, d, c);
                }
            // Skirts: each edge's vertices again, lowered below the lowest ground along that edge
            // (over every grid node of it, not only this tile's), joined to the edge by a wall.
            tile.firstSkirtVertex = m.vertexCount();
            const auto skirt = [&](const std::vector<std::uint32_t> &edge, bool alongColumns, int fixed, int from, int to) {
                double low = fill;
                bool any = false;
                for (int k = from; k <= to; ++k) {
                    const double hk = alongColumns ? heightAt(k, fixed) : heightAt(fixed, k);
                    low = any ? std::min(low, hk) : hk;
                    any = true;
                }
                const float bottomY = float(frame.sceneY(low - options.skirtMargin));
                std::vector<std::uint32_t> lower;
                lower.reserve(edge.size());
                for (std::uint32_t v : edge) {
                    QVector3D p = m.positions[v];
                    p.setY(bottomY);
                    lower.push_back(m.addVertex(p, m.normals[v], m.colours[v]));
                }
                for (std::size_t k = 0; k + 1 < edge.size(); ++k) {
                    // one winding: the view draws the ground without back-face culling
                    m.addTriangle(edge[k], edge[k + 1], lower[k + 1]);
                    m.addTriangle(edge[k], lower[k + 1], lower[k]);
                }
            };
            std::vector<std::uint32_t> south, north, west, east;
            for (int i = 0; i < w; ++i) {
                south.push_back(tile.firstVertex + std::uint32_t(i));
                north.push_back(tile.firstVertex + std::uint32_t((h - 1) * w + i));
            }
            for (int j = 0; j < h; ++j) {
                west.push_back(tile.firstVertex + std::uint32_t(j * w));
                east.push_back(tile.firstVertex + std::uint32_t(j * w + w - 1));
            }
            skirt(south, true, r0, c0, c0 + tile.cellsEast);
            skirt(north, true, r0 + tile.cellsNorth, c0, c0 + tile.cellsEast);
            skirt(west, false, c0, r0, r0 + tile.cellsNorth);
            skirt(east, false, c0 + tile.cellsEast, r0, r0 + tile.cellsNorth);
            tile.endVertex = m.vertexCount();
            out.tiles.push_back(tile);
        }
    return out;
}

} // namespace sortie::scene3d
