#pragma once

#include "HeightGrid.h"
#include "SceneMesh.h"

#include <QColor>

#include <vector>

namespace sortie::scene3d {

struct TerrainOptions
{
    int tileCells = 32;  // grid cells along a tile's side at full detail
    // Level of detail by the distance from `focus` (plane metres) to a tile's nearest point: within
    // lodDistances[0] every node, within [1] every second, [2] every fourth, beyond every eighth.
    std::vector<double> lodDistances{1500.0, 3000.0, 6000.0};
    double focusEast = 0.0;
    double focusNorth = 0.0;
    double skirtMargin = 2.0;  // metres below the lowest ground along a tile's edge
    QColor noData{150, 90, 160};  // where no source has the ground: drawn at the lowest known height, in this colour
};

// One tile as built: its first node, how many cells it spans, the stride its level of detail took,
// and where its vertices are in the mesh (surface first, then its skirts).
struct TerrainTile
{
    int column = 0;
    int row = 0;
    int cellsEast = 0;
    int cellsNorth = 0;
    int stride = 1;
    std::uint32_t firstVertex = 0;
    std::uint32_t firstSkirtVertex = 0;
    std::uint32_t endVertex = 0;
};

struct TerrainMesh
{
    Mesh mesh;
    std::vector<TerrainTile> tiles;
    int noDataVertices = 0;  // surface vertices drawn in the no-data colour
};

int strideFor(double distance, const TerrainOptions &options);
// The grid as tiles of triangles coloured by height (a no-data node in options.noData), each at the
// level of detail its distance from the focus asks for, with skirts hanging below every edge so two
// tiles of different detail leave no crack between them.
TerrainMesh buildTerrain(const HeightGrid &grid, const SceneFrame &frame, const TerrainOptions &options = {});
// The colour of the ground by height between the grid's lowest and highest (green, ochre, brown, dark
// rock: never the sky's pale blue-grey).
QColor heightColour(double height, double lowest, double highest);

} // namespace sortie::scene3d
