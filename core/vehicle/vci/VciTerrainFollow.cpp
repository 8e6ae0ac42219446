#include "VciTerrainFollow.h"

#include "ElevationService.h"
#include "TerrainFollow.h"

#include <algorithm>
namespace sortie::vehicle {

namespace {

// Probes every 10 m, as sortie-sim's processing does (SimRouteTerrain::kStep).
constexpr double kFollowProbeStep = 10.0;

} // namespace

VciFollowedPoints followGround(const std::vector<VciRoutePoint> &points, double tolerance,
                               terrain::ElevationService &elevation, double homeAmsl)
{
    std::vector<terrain::FollowVertex> pass;
    pass.reserve(points.size());
    for (const VciRoutePoint &p : points)
        pass.push_back({p.position, p.height});
    terrain::FollowOptions options;
    options.tolerance = tolerance;
    options.probeStep = kFollowProbeStep;
    const terrain::FollowResult followed = terrain::followTerrain(pass, options, elevation);
    VciFollowedPoints out;
    out.pending = followed.status == terrain::SampleStatus::Pending;
    if (!followed.ok())
        return out;
    out.ok = true;
    size_t next = 0;  // the vertex the next leg arrives at
    for (const terrain::FollowPoint &f : followed.points) {
        const VciRoutePoint &leg = points[f.vertex >= 0 ? size_t(f.vertex) : std::min(next, points.size() - 1)];
        MissionItem item{f.position.latitude, f.position.longitude, f.altitudeAmsl - homeAmsl, leg.speed, 0, {}};
        if (f.vertex >= 0) {
            item.acceptanceRadius = leg.acceptanceRadius;
            item.actions = leg.actions;
            next = size_t(f.vertex) + 1;
        }
        out.items.push_back(std::move(item));
    }
    return out;
}

} // namespace sortie::vehicle
