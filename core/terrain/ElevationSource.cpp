#include "ElevationSource.h"

#include <algorithm>

namespace sortie::terrain {

void ElevationSource::samplePath(const SampledPath &path, std::vector<ElevationSample> &out)
{
    out.resize(path.points.size());
    for (size_t i = 0; i < path.points.size(); ++i)
        out[i] = sample(path.points[i].position);
}

std::vector<NoDataStretch> ElevationSource::noDataStretches(const SampledPath &path, const std::vector<ElevationSample> &samples)
{
    std::vector<NoDataStretch> out;
    const size_t n = std::min(path.points.size(), samples.size());
    bool open = false;
    for (size_t i = 0; i < n; ++i) {
        const PathSamplePoint &p = path.points[i];
        const bool missing = samples[i].status == SampleStatus::NoData;
        if (missing && open && out.back().leg == p.leg) {
            out.back().toDistance = p.distance;
            continue;
        }
        if (missing) {
            // A vertex sample starts the next leg; the stretch before it on the previous leg ends here too.
            if (open && out.back().leg != p.leg)
                out.back().toDistance = p.distance;
            out.push_back({p.leg, p.distance, p.distance});
            open = true;
        } else {
            open = false;
        }
    }
    return out;
}

} // namespace sortie::terrain
