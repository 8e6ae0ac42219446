#include "TerrainFollow.h"

#include "SegmentParameters.h"

#include <algorithm>
#include <cmath>

namespace sortie::terrain {

void markFollowPoints(const std::vector<double> &distance, const std::vector<double> &ground, double tolerance,
                      size_t first, size_t last, std::vector<bool> &keep)
{
    if (last <= first + 1)
        return;
    const double d0 = distance[first], d1 = distance[last];
    const double h0 = ground[first], h1 = ground[last];
    double worst = std::max(0.1, tolerance);
    size_t at = 0;
    for (size_t i = first + 1; i < last; ++i) {
        const double f = d1 > d0 ? (distance[i] - d0) / (d1 - d0) : 0.0;
        const double off = std::abs(h0 + f * (h1 - h0) - ground[i]);
        if (off > worst) {
            worst = off;
            at = i;
        }
    }
    if (at == 0)
        return;
    keep[at] = true;
    markFollowPoints(distance, ground, tolerance, first, at, keep);
    markFollowPoints(distance, ground, tolerance, at, last, keep);
}

std::optional<double> terrainFollowTolerance(const mission::Segment &segment)
{
    if (mission::asWaypoint(segment) || mission::altitudeTypeOf(segment) != mission::AltitudeType::Agl)
        return std::nullopt;
    if (!mission::isAreaScan(segment) && !mission::parameterNames(segment).contains(QStringLiteral("tolerance")))
        return std::nullopt;
    bool ok = false;
    const double value = mission::parameterValue(segment, QStringLiteral("tolerance")).toDouble(&ok);
    return ok && value >= 0 ? value : kDefaultFollowTolerance;
}

FollowResult followTerrain(const std::vector<GeoPoint> &pass, const FollowOptions &options, ElevationService &service)
{
    FollowResult out;
    if (pass.empty())
        return out;
    const SampledPath path = samplePath(pass, options.probeStep);
    std::vector<GroundSample> g;
    service.samplePath(path, g);
    for (size_t i = 0; i < g.size(); ++i) {
        if (g[i].status == SampleStatus::Pending) {
            out.status = SampleStatus::Pending;
            out.message = QStringLiteral("Waiting for terrain data from %1").arg(service.triedText());
            return out;
        }
        if (!g[i].hasValue()) {
            out.status = SampleStatus::NoData;
            out.message = QStringLiteral("No terrain data %1 m along the pass (tried: %2): terrain following needs the ground everywhere")
                              .arg(QString::number(path.points[i].distance, 'f', 0), service.triedText());
            return out;
        }
    }
    std::vector<bool> keep(path.points.size(), false);
    for (const int v : path.vertexSample)
        keep[size_t(v)] = true;
    std::vector<double> distance(path.points.size()), ground(g.size());
    for (size_t i = 0; i < g.size(); ++i) {
        distance[i] = path.points[i].distance;
        ground[i] = g[i].ground;
    }
    for (size_t k = 0; k + 1 < path.vertexSample.size(); ++k)
        markFollowPoints(distance, ground, options.tolerance, size_t(path.vertexSample[k]), size_t(path.vertexSample[k + 1]), keep);
    for (size_t i = 0; i < keep.size(); ++i)
        if (keep[i])
            out.points.push_back({path.points[i].position, g[i].ground + options.altitudeAgl, g[i].ground});
    return out;
}

} // namespace sortie::terrain
