#pragma once

#include "FlightModel.h"

#include <cstdint>
#include <vector>

namespace sortie::sim {

// One picture the simulated camera took: where the vehicle was and how it stood at that moment.
struct SimPhoto
{
    int sequence = 0;        // 1, 2, 3 ... since the vehicle started
    int64_t time = 0;        // ms since the epoch on the vehicle's clock
    double latitude = 0, longitude = 0; // degrees
    double altitudeAmsl = 0; // m
    double altitudeAgl = 0;  // m above the ground under it (above home ground without a ground)
    double heading = 0, roll = 0, pitch = 0; // degrees
    double gimbalTilt = 90;  // degrees, UgCS's convention: 90 looks straight down, 0 ahead
};

// The simulated vehicle's camera shutter: it takes single shots and runs the series a mission's
// camera actions start (one photo every so many metres flown or seconds), as an autopilot's camera
// trigger does. A series starts with a photo at once (after its delay) and runs until its shot count
// is taken, another camera action replaces it, or the vehicle leaves the mission: a hold pauses it
// (no distance is flown, no time counts), any other mode ends it, so a vehicle sent home or landed
// half-way takes no pictures on its way down. Distance is horizontal; the overshoot of one tick is
// carried to the next photo, so the spacing is the interval on average. No I/O, no Qt.
class SimShutter
{
public:
    // The shutter's time: `seconds` runs with the simulation (a series' interval and delay count
    // in it), `stampMs` is the vehicle's clock a photo is stamped with.
    struct Clock
    {
        double seconds = 0;
        int64_t stampMs = 0;
    };

    // Takes one photo now.
    void single(const FlightModel::State &state, Clock now);
    // An interval of 0 (or less) stops a running series, as the VCI profile and UgCS say; `shots`
    // 0 takes photos until the series is stopped.
    void startByDistance(double intervalMetres, int shots, double delaySeconds, Clock now);
    void startByTime(double intervalSeconds, int shots, double delaySeconds, Clock now);
    void stop();
    void setGimbalTilt(double degrees) { m_gimbalTilt = degrees; }

    // After the model moved: the series' photo when one is due.
    void tick(const FlightModel::State &state, Clock now);

    bool seriesRunning() const { return m_series != Series::None; }
    const std::vector<SimPhoto> &photos() const { return m_photos; }

private:
    enum class Series { None, Distance, Time };

    void take(const FlightModel::State &state, Clock now);
    void start(Series kind, double interval, int shots, double delaySeconds, Clock now);

    Series m_series = Series::None;
    double m_interval = 0;      // metres or seconds
    int m_shotsLeft = 0;        // 0: no limit
    double m_startAt = 0;       // s: the first photo of the series, after its delay
    bool m_started = false;     // the first photo was taken
    double m_sinceLast = 0;     // metres or seconds since the last photo of the series
    double m_lastSeconds = 0;
    double m_lastLatitude = 0, m_lastLongitude = 0;
    bool m_placed = false;      // m_last* hold where the series was at its last tick
    double m_gimbalTilt = 90;
    std::vector<SimPhoto> m_photos;
};

} // namespace sortie::sim
