#pragma once

#include <QElapsedTimer>
#include <QString>

#include <vector>

namespace sortie::sim {

// One simulated aircraft at one moment: what an ADS-B receiver would hear from it.
struct SimAircraft
{
    quint32 address = 0;     // 24-bit
    QString callsign;
    double latitude = 0;     // degrees
    double longitude = 0;
    double altitudeM = 0;    // above mean sea level (and as pressure altitude: the simulated day is standard)
    double trackDeg = 0;     // clockwise from true north
    double groundSpeedMps = 0;
    double verticalRateMps = 0; // up positive
};

// Manned traffic through the demo area (the port of Riga, where the emulator vehicles are): three
// aircraft on deterministic orbits around its centre, a helicopter low and close, a light aircraft
// climbing and descending, an airliner level and further out. Where each one is depends only on
// the seconds since the traffic started (aircraftAt), so tests can predict it.
class SimTraffic
{
public:
    static constexpr double kCentreLatitude = 56.9765;
    static constexpr double kCentreLongitude = 24.0760;

    // An empty sky (no aircraft) for a demo where nothing may move (sortie --demo-scene).
    explicit SimTraffic(bool flying = true);

    std::vector<SimAircraft> aircraftAt(double seconds) const;
    std::vector<SimAircraft> aircraftNow() const { return aircraftAt(secondsSinceStart()); }
    double secondsSinceStart() const { return double(m_clock.elapsed()) / 1000.0; }

    // The aircraft within `radiusM` of a point (degrees), now.
    std::vector<SimAircraft> aircraftWithin(double latitude, double longitude, double radiusM) const;

private:
    QElapsedTimer m_clock;
    bool m_flying = true;
};

} // namespace sortie::sim
