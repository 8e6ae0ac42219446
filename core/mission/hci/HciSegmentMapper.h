#pragma once

#include "MissionError.h"
#include "Segment.h"

#include <QStringList>

namespace com::ugcs::ucs::proto {
class SegmentDefinition;
class VehicleProfile;
}

namespace sortie::mission {

// What a segment's meaning depends on beyond itself.
struct HciSegmentContext
{
    double defaultSpeed = 5.0;  // the route's initial speed, for segments without a "speed"
    const com::ugcs::ucs::proto::VehicleProfile *profile = nullptr;  // its camera, for area scans
};

// One SegmentDefinition <-> one Segment. See HciRouteMapper.h for the merge rule.
Result<Segment> segmentFromHci(const com::ugcs::ucs::proto::SegmentDefinition &segment, const HciSegmentContext &context,
                               QStringList *notices);
com::ugcs::ucs::proto::SegmentDefinition segmentToHci(const Segment &segment, const HciSegmentContext &context);

} // namespace sortie::mission
