#include "PhaseSegmenter.h"

#include <cmath>

namespace sortie::endurance::fit {

const char *phaseName(Phase phase)
{
    switch (phase) {
    case Phase::Ground: return "ground";
    case Phase::Hover: return "hover";
    case Phase::Level: return "level";
    case Phase::Climb: return "climb";
    case Phase::Descent: return "descent";
    case Phase::Transition: return "transition";
    }
    return "?";
}

Phase classify(const PowerSample &s, const PhaseThresholds &t)
{
    // The height decides where there is one: arming is a state change, which some links stamp by
    // the ground station's clock rather than the vehicle's (docs/endurance-fit.md).
    if (std::isfinite(s.altitudeAgl) ? s.altitudeAgl < t.airborneAbove : s.armed == 0.0)
        return Phase::Ground;
    if (!std::isfinite(s.groundSpeed) || !std::isfinite(s.verticalSpeed))
        return Phase::Transition; // cannot tell
    const double gs = s.groundSpeed, vz = s.verticalSpeed;
    if (std::abs(vz) < t.levelVerticalBelow) {
        if (gs < t.stillBelow)
            return Phase::Hover;
        if (gs > t.levelFasterThan)
            return Phase::Level;
        return Phase::Transition;
    }
    if (gs < t.verticalGroundBelow && vz > t.verticalFasterThan)
        return Phase::Climb;
    if (gs < t.verticalGroundBelow && vz < -t.verticalFasterThan)
        return Phase::Descent;
    return Phase::Transition;
}

std::vector<PhaseRun> segmentPhases(const std::vector<PowerSample> &samples, const PhaseThresholds &t)
{
    std::vector<PhaseRun> runs;
    const auto ms = [](double seconds) { return int64_t(std::llround(seconds * 1000.0)); };
    // Keeps the part of [begin, end) more than trimSeconds from either end, when it is long enough.
    const auto keep = [&](Phase phase, size_t begin, size_t end) {
        if (phase == Phase::Ground || phase == Phase::Transition)
            return;
        const int64_t from = samples[begin].time + ms(t.trimSeconds), to = samples[end - 1].time - ms(t.trimSeconds);
        size_t first = begin;
        while (first < end && samples[first].time < from)
            ++first;
        size_t last = end;
        while (last > first && samples[last - 1].time > to)
            --last;
        if (last <= first + 1 || samples[last - 1].time - samples[first].time < ms(t.minRunSeconds))
            return;
        runs.push_back({phase, first, last - 1});
    };
    size_t begin = 0;
    Phase current = Phase::Transition;
    for (size_t i = 0; i < samples.size(); ++i) {
        const Phase p = classify(samples[i], t);
        const bool gap = i > 0 && samples[i].time - samples[i - 1].time > ms(t.maxGapSeconds);
        if (i == 0) {
            current = p;
            continue;
        }
        if (p != current || gap) {
            keep(current, begin, i);
            begin = i;
            current = p;
        }
    }
    if (!samples.empty())
        keep(current, begin, samples.size());
    return runs;
}

} // namespace sortie::endurance::fit
