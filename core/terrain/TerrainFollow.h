#pragma once

#include "ElevationService.h"
#include "Segment.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::terrain {

// A corner of the pass and the height to keep above the ground there (between corners the wanted
// height goes linearly with distance).
struct FollowVertex
{
    GeoPoint position;
    double heightAgl = 50.0;
};

struct FollowPoint
{
    GeoPoint position;
    double altitudeAmsl = 0.0;  // ground + the wanted height
    double ground = 0.0;
    int vertex = -1;            // the pass's vertex this point is, -1 for a point following adds
};

struct FollowOptions
{
    double tolerance = 5.0;     // metres the flown height may stray from the wanted one between points
    double probeStep = 10.0;    // metres between ground probes along the pass
};

struct FollowResult
{
    std::vector<FollowPoint> points;  // empty unless ok
    SampleStatus status = SampleStatus::Value;  // NoData: some of the pass has no ground; Pending: ask again later
    QString message;                  // why not, for the operator
    bool ok() const { return status == SampleStatus::Value; }
};

// Terrain following for a pass: the pass's vertices are kept, and points are added where the ground
// changes faster than the tolerance, so that flying straight (and climbing linearly) between
// consecutive points stays within `tolerance` of the wanted height above every probed ground
// sample. Like Douglas–Peucker on the height profile: split each leg at the worst probe until all
// fit. What VCI uploads fly (vehicle::vciMissionFor); sortie-sim's processing uses markFollowPoints.
FollowResult followTerrain(const std::vector<FollowVertex> &pass, const FollowOptions &options, ElevationService &service);

// The probes a terrain-following leg flies through: of probes first..last (their distances along the
// path and the ground at each), marks in `keep` the ones where a straight climb between the kept
// probes would stray more than `tolerance` from the ground's shape. first and last are not marked
// here: the caller keeps them. The step both followTerrain and the simulator's processing use.
void markFollowPoints(const std::vector<double> &distance, const std::vector<double> &ground, double tolerance,
                      size_t first, size_t last, std::vector<bool> &keep);

// UgCS's area tools flown AGL follow the terrain: extra points where the ground departs more than
// the segment's `tolerance` (docs/missions.md). The tolerance for a segment that does so (a scan,
// photogrammetry or another algorithm with a `tolerance` parameter, its altitude type AGL), else
// nullopt. An unset tolerance is the algorithm's default (kDefaultFollowTolerance).
inline constexpr double kDefaultFollowTolerance = 3.0;
std::optional<double> terrainFollowTolerance(const mission::Segment &segment);

} // namespace sortie::terrain
