// The server's ADS-B entries (HciTrafficSource::reportFromAdsb): any bytes that parse as an
// AdsbAircraft become a report or nothing. A report has a 24-bit address, a position only when both
// coordinates are finite degrees on the globe, a track in [0, 360), a ground speed that is finite
// and not negative, and a callsign of at most eight characters; whatever is not finite is missing.
#include "HciTrafficSource.h"
#include "Messages.pb.h"

#include <cmath>
#include <cstdlib>

using namespace sortie::traffic;

namespace {
void require(bool condition)
{
    if (!condition)
        std::abort();
}

bool finiteOrMissing(const std::optional<double> &value)
{
    return !value || std::isfinite(*value);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    com::ugcs::ucs::proto::AdsbAircraft aircraft;
    if (!aircraft.ParsePartialFromArray(data, int(size)))
        return 0;
    const auto report = HciTrafficSource::reportFromAdsb(aircraft);
    require(report.has_value() == aircraft.has_icaoaddress());
    if (!report)
        return 0;
    require(report->address <= 0xffffffu);
    require(report->latitude.has_value() == report->longitude.has_value());
    if (report->latitude)
        require(std::abs(*report->latitude) <= 90 && std::abs(*report->longitude) <= 180);
    if (report->trackDeg)
        require(*report->trackDeg >= 0 && *report->trackDeg < 360);
    if (report->groundSpeedMps)
        require(*report->groundSpeedMps >= 0);
    require(finiteOrMissing(report->altitudeM) && finiteOrMissing(report->groundSpeedMps)
            && finiteOrMissing(report->verticalRateMps) && finiteOrMissing(report->trackDeg));
    if (report->callsign)
        require(!report->callsign->isEmpty() && report->callsign->size() <= 8);
    return 0;
}
