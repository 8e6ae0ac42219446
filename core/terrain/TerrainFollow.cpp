#include "TerrainFollow.h"

#include "SegmentParameters.h"

#include <algorithm>
#include <cmath>
#include <QCoreApplication>

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

FollowResult followTerrain(const std::vector<FollowVertex> &pass, const FollowOptions &options, ElevationService &service)
{
    FollowResult out;
    if (pass.empty())
        return out;
    std::vector<GeoPoint> corners;
    corners.reserve(pass.size());
    for (const FollowVertex &v : pass)
        corners.push_back(v.position);
    const SampledPath path = samplePath(std::move(corners), options.probeStep);
    std::vector<GroundSample> g;
    service.samplePath(path, g);
    for (size_t i = 0; i < g.size(); ++i) {
        if (g[i].status == SampleStatus::Pending) {
            out.status = SampleStatus::Pending;
            out.message = QCoreApplication::translate("TerrainFollow", "Waiting for terrain data from %1").arg(service.triedText());
            return out;
        }
        if (!g[i].hasValue()) {
            out.status = SampleStatus::NoData;
            out.message = QCoreApplication::translate("TerrainFollow", "No terrain data %1 m along the pass (tried: %2): terrain following needs the ground everywhere")
                              .arg(QString::number(path.points[i].distance, 'f', 0), service.triedText());
            return out;
        }
    }
    std::vector<bool> keep(path.points.size(), false);
    std::vector<int> vertexAt(path.points.size(), -1);
    for (size_t v = 0; v < path.vertexSample.size(); ++v) {
        keep[size_t(path.vertexSample[v])] = true;
        vertexAt[size_t(path.vertexSample[v])] = int(v);
    }
    std::vector<double> distance(path.points.size()), ground(g.size());
    for (size_t i = 0; i < g.size(); ++i) {
        distance[i] = path.points[i].distance;
        ground[i] = g[i].ground;
    }
    for (size_t k = 0; k + 1 < path.vertexSample.size(); ++k)
        markFollowPoints(distance, ground, options.tolerance, size_t(path.vertexSample[k]), size_t(path.vertexSample[k + 1]), keep);
    for (size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i])
            continue;
        // The wanted height on this point's leg, linear in distance between the leg's corners.
        const size_t leg = std::min(size_t(path.points[i].leg), pass.size() - 1);
        const size_t next = std::min(leg + 1, pass.size() - 1);
        const double d0 = path.vertexDistance[leg], d1 = path.vertexDistance[next];
        const double f = vertexAt[i] >= 0 || d1 <= d0 ? 0.0 : (distance[i] - d0) / (d1 - d0);
        const double wanted = vertexAt[i] >= 0 ? pass[size_t(vertexAt[i])].heightAgl
                                               : pass[leg].heightAgl + f * (pass[next].heightAgl - pass[leg].heightAgl);
        out.points.push_back({path.points[i].position, g[i].ground + wanted, g[i].ground, vertexAt[i]});
    }
    return out;
}

} // namespace sortie::terrain
