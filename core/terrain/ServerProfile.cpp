#include "ServerProfile.h"

#include "Geodesy.h"
#include "Messages.pb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sortie::terrain {

// The server picks its own sample positions: place them along our path by their running distance
// and interpolate linearly to our samples. A sample between a missing value and anything is missing.
std::vector<double> profileAlong(const SampledPath &path, std::vector<GeoPoint> locations, std::vector<double> elevations)
{
    const size_t n = std::min(locations.size(), elevations.size());  // a location without its value is none
    locations.resize(n);
    elevations.resize(n);
    // A value that is not a finite number is no elevation (NaN), whatever the server meant by it;
    // a server's location that is not a place gives no distances to place its values by.
    for (double &e : elevations)
        if (!std::isfinite(e))
            e = std::numeric_limits<double>::quiet_NaN();
    for (const GeoPoint &l : locations)
        if (!std::isfinite(l.latitude) || !std::isfinite(l.longitude) || std::abs(l.latitude) > 90 || std::abs(l.longitude) > 180)
            return std::vector<double>(path.points.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<double> values(path.points.size(), std::numeric_limits<double>::quiet_NaN());
    // A server that samples the way we do (the simulator does) gives our points: take them as they are.
    bool same = locations.size() == path.points.size();
    for (size_t i = 0; same && i < locations.size(); ++i)
        same = mission::geodesicDistance(locations[i], path.points[i].position) < 0.5;
    if (same) {
        for (size_t i = 0; i < values.size(); ++i)
            values[i] = elevations[i];
    } else if (!locations.empty()) {
        std::vector<double> at(locations.size(), 0.0);
        for (size_t i = 1; i < locations.size(); ++i)
            at[i] = at[i - 1] + mission::geodesicDistance(locations[i - 1], locations[i]);
        // Scale the server's running distance onto ours: both walk the same legs.
        const double scale = at.back() > 0 && path.length() > 0 ? path.length() / at.back() : 1.0;
        for (double &d : at)
            d *= scale;
        size_t j = 0;
        for (size_t i = 0; i < path.points.size(); ++i) {
            const double d = path.points[i].distance;
            while (j + 1 < at.size() && at[j + 1] < d - 1e-6)
                ++j;
            if (std::abs(at[j] - d) < 1e-3) {
                values[i] = elevations[j];
                continue;
            }
            if (j + 1 < at.size() && at[j] <= d && d <= at[j + 1] + 1e-6) {
                if (std::abs(at[j + 1] - d) < 1e-3) {
                    values[i] = elevations[j + 1];
                    continue;
                }
                const double f = (d - at[j]) / (at[j + 1] - at[j]);
                values[i] = std::lerp(elevations[j], elevations[j + 1], f);  // NaN spreads; no overflow between finite values
            }
        }
    }
    return values;
}

std::vector<double> profileAlong(const SampledPath &path, const com::ugcs::ucs::proto::GetElevationProfileResponse &response)
{
    constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
    std::vector<GeoPoint> locations;
    std::vector<double> elevations;
    for (int i = 0; i < response.locations_size() && i < response.elevations_size(); ++i) {
        locations.push_back({response.locations(i).latitude() * kDegreesPerRadian, response.locations(i).longitude() * kDegreesPerRadian});
        elevations.push_back(response.elevations(i));
    }
    return profileAlong(path, std::move(locations), std::move(elevations));
}

} // namespace sortie::terrain
