#include "TerrainFollow.h"

#include <cmath>

namespace sortie::terrain {

namespace {
// Keeps probes first..last, marking in `keep` the ones that must become points.
void split(const SampledPath &path, const std::vector<GroundSample> &g, double tolerance, size_t first, size_t last,
           std::vector<bool> &keep)
{
    if (last <= first + 1)
        return;
    const double d0 = path.points[first].distance, d1 = path.points[last].distance;
    const double h0 = g[first].ground, h1 = g[last].ground;
    double worst = tolerance;
    size_t at = 0;
    for (size_t i = first + 1; i < last; ++i) {
        const double f = d1 > d0 ? (path.points[i].distance - d0) / (d1 - d0) : 0.0;
        const double off = std::abs(h0 + f * (h1 - h0) - g[i].ground);
        if (off > worst) {
            worst = off;
            at = i;
        }
    }
    if (at == 0)
        return;
    keep[at] = true;
    split(path, g, tolerance, first, at, keep);
    split(path, g, tolerance, at, last, keep);
}
} // namespace

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
    const double tolerance = std::max(0.1, options.tolerance);
    for (size_t k = 0; k + 1 < path.vertexSample.size(); ++k)
        split(path, g, tolerance, size_t(path.vertexSample[k]), size_t(path.vertexSample[k + 1]), keep);
    for (size_t i = 0; i < keep.size(); ++i)
        if (keep[i])
            out.points.push_back({path.points[i].position, g[i].ground + options.altitudeAgl, g[i].ground});
    return out;
}

} // namespace sortie::terrain
