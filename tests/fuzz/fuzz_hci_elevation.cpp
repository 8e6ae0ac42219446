// The server's elevation profile (ServerProfile.h): any GetElevationProfileResponse a server could
// send, placed on Sortie's samples of a path near Riga, gives one value per sample, each missing
// (NaN) or within the finite elevations the server sent: never infinite, never invented.
#include "Messages.pb.h"
#include "ServerProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::terrain;
    com::ugcs::ucs::proto::GetElevationProfileResponse response;
    if (!response.ParseFromArray(data, int(size)))
        return 0;
    static const SampledPath path = samplePath({{56.9500, 24.1000}, {56.9550, 24.1100}, {56.9600, 24.1000}}, 30.0);
    const std::vector<double> values = profileAlong(path, response);
    if (values.size() != path.points.size()) {
        std::fprintf(stderr, "fuzz_hci_elevation: %zu values for %zu samples\n", values.size(), path.points.size());
        std::abort();
    }
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int i = 0; i < response.elevations_size() && i < response.locations_size(); ++i)
        if (std::isfinite(response.elevations(i))) {
            low = std::min(low, response.elevations(i));
            high = std::max(high, response.elevations(i));
        }
    for (double v : values)
        if (!std::isnan(v) && !(v >= low - 1e-9 * std::abs(low) && v <= high + 1e-9 * std::abs(high))) {
            std::fprintf(stderr, "fuzz_hci_elevation: %g outside the server's %g..%g\n", v, low, high);
            std::abort();
        }
    return 0;
}
