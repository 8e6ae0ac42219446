#include "SimTraffic.h"

#include <cmath>
#include <numbers>

namespace sortie::sim {
namespace {

constexpr double kEarthRadiusM = 6371000.0;
constexpr double kPi = std::numbers::pi;

// An aircraft flying a circle around the centre at a constant speed, its height a slow sine.
struct Orbit
{
    quint32 address;
    const char *callsign;
    double radiusM;
    double speedMps;
    bool clockwise;
    double startBearingDeg;  // where on the circle it is at 0 s, seen from the centre
    double altitudeM;        // the middle of its height band
    double altitudeSwingM;   // half the band
    double swingPeriodS;

    SimAircraft at(double t) const
    {
        const double turn = (clockwise ? 1.0 : -1.0) * speedMps / radiusM; // rad/s of bearing from the centre
        const double bearing = startBearingDeg * kPi / 180.0 + turn * t;
        const double east = radiusM * std::sin(bearing), north = radiusM * std::cos(bearing);
        // Flying along the circle: the bearing plus or minus a right angle.
        const double track = bearing + (clockwise ? kPi / 2 : -kPi / 2);
        const double phase = 2 * kPi * t / swingPeriodS;
        SimAircraft a;
        a.address = address;
        a.callsign = QString::fromLatin1(callsign);
        a.latitude = SimTraffic::kCentreLatitude + north / kEarthRadiusM * 180.0 / kPi;
        a.longitude = SimTraffic::kCentreLongitude
            + east / (kEarthRadiusM * std::cos(SimTraffic::kCentreLatitude * kPi / 180.0)) * 180.0 / kPi;
        a.altitudeM = altitudeM + altitudeSwingM * std::sin(phase);
        a.verticalRateMps = altitudeSwingM * 2 * kPi / swingPeriodS * std::cos(phase);
        a.trackDeg = std::fmod(std::fmod(track * 180.0 / kPi, 360.0) + 360.0, 360.0);
        a.groundSpeedMps = speedMps;
        return a;
    }
};

// Addresses from the block ICAO gives Latvia (502C00-502FFF).
constexpr Orbit kOrbits[] = {
    {0x502C11, "YLHEL1", 900, 40, true, 0, 250, 60, 180},
    {0x502C22, "BTI7TR", 2200, 60, false, 120, 700, 200, 240},
    {0x502C33, "AFR64K", 4000, 120, true, 240, 1800, 0, 600},
};

double distanceM(double lat1, double lon1, double lat2, double lon2)
{
    const double p1 = lat1 * kPi / 180, p2 = lat2 * kPi / 180;
    const double dp = p2 - p1, dl = (lon2 - lon1) * kPi / 180;
    const double h = std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
    return 2 * kEarthRadiusM * std::asin(std::min(1.0, std::sqrt(h)));
}

} // namespace

SimTraffic::SimTraffic(bool flying)
    : m_flying(flying)
{
    m_clock.start();
}

std::vector<SimAircraft> SimTraffic::aircraftAt(double seconds) const
{
    std::vector<SimAircraft> out;
    if (!m_flying)
        return out;
    for (const Orbit &orbit : kOrbits)
        out.push_back(orbit.at(seconds));
    return out;
}

std::vector<SimAircraft> SimTraffic::aircraftWithin(double latitude, double longitude, double radiusM) const
{
    std::vector<SimAircraft> out;
    for (const SimAircraft &a : aircraftNow()) {
        if (distanceM(latitude, longitude, a.latitude, a.longitude) <= radiusM)
            out.push_back(a);
    }
    return out;
}

} // namespace sortie::sim
