#pragma once

#include "SceneFrame.h"

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace sortie::terrain {
class ElevationService;
}

namespace sortie::scene3d {

// Ground heights on a regular grid of the scene's tangent plane: column c is `east0 + c·spacing`
// metres east of the origin, row r `north0 + r·spacing` north (row 0 the southern edge). A node
// without data (no source has it, or an asynchronous one is still asking) is NaN, never 0 m.
struct HeightGrid
{
    double east0 = 0.0;
    double north0 = 0.0;
    double spacing = 30.0;
    int columns = 0;
    int rows = 0;
    std::vector<float> heights;  // rows × columns, row-major from the south
    int pending = 0;             // nodes an asynchronous source is still asking for

    bool empty() const { return columns < 2 || rows < 2; }
    float at(int column, int row) const { return heights[std::size_t(row) * std::size_t(columns) + std::size_t(column)]; }
    bool hasValue(int column, int row) const { return std::isfinite(at(column, row)); }
    double eastOf(int column) const { return east0 + column * spacing; }
    double northOf(int row) const { return north0 + row * spacing; }
    double width() const { return (columns - 1) * spacing; }
    double depth() const { return (rows - 1) * spacing; }
    // Bilinear between the four nodes around a plane point; nullopt outside or where one has no data.
    std::optional<double> heightAt(double east, double north) const;
    // The lowest and highest heights with data; nullopt when none has.
    std::optional<double> lowest() const;
    std::optional<double> highest() const;
    int noDataCount() const;
};

// The grid of `columns` × `rows` nodes `spacing` metres apart centred on the frame's origin,
// each node asked of the elevation service once (a DEM tile is opened the first time a node falls
// in it and kept by its source). Runs where the service lives (its sources are not thread-safe).
HeightGrid sampleGrid(terrain::ElevationService &service, const SceneFrame &frame, double spacing, int columns, int rows);

} // namespace sortie::scene3d
