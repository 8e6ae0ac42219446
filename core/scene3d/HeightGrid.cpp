#include "HeightGrid.h"

#include "ElevationService.h"

#include <algorithm>

namespace sortie::scene3d {

std::optional<double> HeightGrid::heightAt(double east, double north) const
{
    if (empty())
        return std::nullopt;
    const double u = (east - east0) / spacing;
    const double v = (north - north0) / spacing;
    if (!(u >= 0.0 && v >= 0.0 && u <= columns - 1 && v <= rows - 1))
        return std::nullopt;
    const int c = std::min(int(u), columns - 2);
    const int r = std::min(int(v), rows - 2);
    const double fu = u - c, fv = v - r;
    const double h00 = at(c, r), h10 = at(c + 1, r), h01 = at(c, r + 1), h11 = at(c + 1, r + 1);
    const double h = (h00 * (1 - fu) + h10 * fu) * (1 - fv) + (h01 * (1 - fu) + h11 * fu) * fv;
    if (!std::isfinite(h))
        return std::nullopt;
    return h;
}

std::optional<double> HeightGrid::lowest() const
{
    std::optional<double> out;
    for (float h : heights)
        if (std::isfinite(h) && (!out || h < *out))
            out = h;
    return out;
}

std::optional<double> HeightGrid::highest() const
{
    std::optional<double> out;
    for (float h : heights)
        if (std::isfinite(h) && (!out || h > *out))
            out = h;
    return out;
}

int HeightGrid::noDataCount() const
{
    return int(std::count_if(heights.begin(), heights.end(), [](float h) { return !std::isfinite(h); }));
}

HeightGrid sampleGrid(terrain::ElevationService &service, const SceneFrame &frame, double spacing, int columns, int rows)
{
    HeightGrid grid;
    grid.spacing = spacing > 0.0 ? spacing : 30.0;
    grid.columns = std::max(columns, 2);
    grid.rows = std::max(rows, 2);
    grid.east0 = -0.5 * (grid.columns - 1) * grid.spacing;
    grid.north0 = -0.5 * (grid.rows - 1) * grid.spacing;
    grid.heights.assign(std::size_t(grid.columns) * std::size_t(grid.rows), std::numeric_limits<float>::quiet_NaN());
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c) {
            const mission::GeoPoint p = frame.plane().unproject({grid.eastOf(c), grid.northOf(r)});
            if (!p.isValid())
                continue;
            const terrain::GroundSample s = service.sample(p);
            if (s.hasValue())
                grid.heights[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)] = float(s.ground);
            else if (s.status == terrain::SampleStatus::Pending)
                ++grid.pending;
        }
    return grid;
}

} // namespace sortie::scene3d
