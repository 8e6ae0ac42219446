#pragma once

#include <cmath>
#include <limits>

namespace sortie::terrain {

// What a source knows about the ground at one place. Pending: an asynchronous source has asked and
// will signal when the answer is in. NoData is an answer ("this source has nothing here"), never 0 m.
enum class SampleStatus : unsigned char { Value, NoData, Pending };

struct ElevationSample
{
    double ground = std::numeric_limits<double>::quiet_NaN();  // metres above the EGM96 geoid
    SampleStatus status = SampleStatus::NoData;

    bool hasValue() const { return status == SampleStatus::Value; }
    static ElevationSample value(double metres) { return {metres, SampleStatus::Value}; }
    static ElevationSample noData() { return {}; }
    static ElevationSample pending() { return {std::numeric_limits<double>::quiet_NaN(), SampleStatus::Pending}; }
};

// A sample with the source that gave it: the index of the source in ElevationService's order, or
// -1 when no source had the value.
struct GroundSample : ElevationSample
{
    int source = -1;
};

} // namespace sortie::terrain
