#include "PhotoShots.h"

namespace sortie::coverage {

std::vector<Shot> shotsFromPhotos(const std::vector<geotag::TaggedPhoto> &photos, const geotag::Track &track, const ShotOptions &options,
                                  const geotag::MatchOptions &match)
{
    std::vector<Shot> shots;
    shots.reserve(photos.size());
    for (const geotag::TaggedPhoto &p : photos) {
        Shot s;
        s.name = p.photo.fileName;
        s.latitude = p.position.latitude;
        s.longitude = p.position.longitude;
        if (options.groundAmslAt) {
            const auto ground = options.groundAmslAt(s.latitude, s.longitude);
            if (ground && p.position.altitudeAmsl)
                s.heightAboveGround = *p.position.altitudeAmsl - *ground;
        } else if (options.groundAmsl) {
            if (p.position.altitudeAmsl)
                s.heightAboveGround = *p.position.altitudeAmsl - *options.groundAmsl;
        } else if (p.position.heightAboveTakeoff) {
            s.heightAboveGround = *p.position.heightAboveTakeoff;
        }
        if (p.position.heading)
            s.headingDegrees = *p.position.heading;
        else if (const auto course = geotag::courseAt(track, p.time, match.maxGapMs))
            s.headingDegrees = *course;
        shots.push_back(s);
    }
    return shots;
}

} // namespace sortie::coverage
