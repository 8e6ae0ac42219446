#pragma once

#include "GeoPoint.h"
#include "PathSampling.h"

#include <vector>

namespace com::ugcs::ucs::proto {
class GetElevationProfileResponse;
}

namespace sortie::terrain {

// A server's elevation profile (GetElevationProfileResponse: its own sample locations along the
// path asked for, and their elevations) placed on Sortie's samples of the same path, one value per
// sample, NaN where none can be given. Pure, so it is tested and fuzzed (fuzz_hci_elevation) on
// whatever a server sends: locations without values, values that are not finite numbers, places
// that are not on the Earth.
std::vector<double> profileAlong(const SampledPath &path, std::vector<GeoPoint> locations, std::vector<double> elevations);
// The same from the server's answer as it came (locations in radians, as everywhere in HCI).
std::vector<double> profileAlong(const SampledPath &path, const com::ugcs::ucs::proto::GetElevationProfileResponse &response);

} // namespace sortie::terrain
