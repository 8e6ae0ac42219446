#pragma once

#include "CoverageMap.h"
#include "Geotagger.h"

#include <functional>
#include <optional>
#include <vector>

namespace sortie::coverage {

struct ShotOptions
{
    // The ground's height above sea level, taken as flat: a photo's height above the ground is then
    // its altitude AMSL less this.
    std::optional<double> groundAmsl;
    // Or the ground under each photo from a DEM (metres AMSL; nullopt where it has none): the
    // photo's altitude AMSL less the ground beneath the camera. Handed in, so this room opens no
    // raster (sortie-log gives raster::openDem's source).
    std::function<std::optional<double>(double latitude, double longitude)> groundAmslAt;
    // Neither: the height above the take-off point (flat ground at the take-off's height).
};

// Photos placed on their track (geotag::matchPhotos) as shots: the position the track gives, the
// height above the ground (ShotOptions: a DEM, a flat ground, or the take-off's), the heading the track holds at that time (a flight log's
// Heading) or else the course flown then. A value the track cannot give stays NaN, and
// computeCoverage names the photo.
std::vector<Shot> shotsFromPhotos(const std::vector<geotag::TaggedPhoto> &photos, const geotag::Track &track, const ShotOptions &options,
                                  const geotag::MatchOptions &match);

} // namespace sortie::coverage
