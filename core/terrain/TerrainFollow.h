#pragma once

#include "ElevationService.h"

#include <QString>

#include <vector>

namespace sortie::terrain {

struct FollowPoint
{
    GeoPoint position;
    double altitudeAmsl = 0.0;  // ground + the wanted height
    double ground = 0.0;
};

struct FollowOptions
{
    double altitudeAgl = 50.0;  // the height to keep above the ground
    double tolerance = 5.0;     // metres the flown height may stray from it between points
    double probeStep = 10.0;    // metres between ground probes along the pass
};

struct FollowResult
{
    std::vector<FollowPoint> points;  // empty unless ok
    SampleStatus status = SampleStatus::Value;  // NoData: some of the pass has no ground; Pending: ask again later
    QString message;                  // why not, for the operator
    bool ok() const { return status == SampleStatus::Value; }
};

// Terrain following for a scan pass: the pass's vertices are kept, and points are added where the
// ground changes faster than the tolerance, so that flying straight (and climbing linearly) between
// consecutive points stays within `tolerance` of altitudeAgl above every probed ground sample. Like
// Douglas–Peucker on the height profile: split each leg at the worst probe until all fit.
FollowResult followTerrain(const std::vector<GeoPoint> &pass, const FollowOptions &options, ElevationService &service);

} // namespace sortie::terrain
