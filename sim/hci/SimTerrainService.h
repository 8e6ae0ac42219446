#pragma once

namespace sortie::sim {

class HciRequestDispatcher;
class SimWorld;

// Elevation for logged-in clients, from the world's terrain (the same ground the vehicles fly
// over and route processing checks):
// - GetElevationProfile (48) and GetElevationProfileV2 (176): the path through `locations` sampled
//   every samplingStep metres along great-circle legs (each vertex, then every step, then the last
//   vertex), answered as locations with their ground and elevations; V2 adds accumulatedDistances
//   and surfaceHeight (the ground: the simulated world has no buildings or trees);
// - GetRasterValues (34): the ground at each latitude/longitude;
// - GetRasterGrid (30): a width×height grid over the box, row 0 at the north edge.
// Latitudes and longitudes are radians, as everywhere in HCI. Where the terrain has no data the
// value is NaN and noData is set; obstacleHeight is 0 (no obstacles).
class SimTerrainService
{
public:
    static constexpr int kMaxSamples = 1000000;
    static void install(HciRequestDispatcher &dispatcher, SimWorld &world);
};

} // namespace sortie::sim
