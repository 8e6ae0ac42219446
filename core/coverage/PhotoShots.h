#pragma once

#include "CoverageMap.h"
#include "Geotagger.h"

#include <optional>
#include <vector>

namespace sortie::coverage {

struct ShotOptions
{
    // The ground's height above sea level, taken as flat: a photo's height above the ground is then
    // its altitude AMSL less this. Absent: its height above the take-off point (flat ground at the
    // take-off's height).
    std::optional<double> groundAmsl;
};

// Photos placed on their track (geotag::matchPhotos) as shots: the position the track gives, the
// height above the ground (ShotOptions), the heading the track holds at that time (a flight log's
// Heading) or else the course flown then. A value the track cannot give stays NaN, and
// computeCoverage names the photo.
std::vector<Shot> shotsFromPhotos(const std::vector<geotag::TaggedPhoto> &photos, const geotag::Track &track, const ShotOptions &options,
                                  const geotag::MatchOptions &match);

} // namespace sortie::coverage
