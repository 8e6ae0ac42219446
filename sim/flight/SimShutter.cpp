#include "SimShutter.h"

#include <cmath>

namespace sortie::sim {

void SimShutter::single(const FlightModel::State &state, Clock now)
{
    take(state, now);
}

void SimShutter::startByDistance(double intervalMetres, int shots, double delaySeconds, Clock now)
{
    start(Series::Distance, intervalMetres, shots, delaySeconds, now);
}

void SimShutter::startByTime(double intervalSeconds, int shots, double delaySeconds, Clock now)
{
    start(Series::Time, intervalSeconds, shots, delaySeconds, now);
}

void SimShutter::start(Series kind, double interval, int shots, double delaySeconds, Clock now)
{
    if (!(interval > 0)) {
        stop();
        return;
    }
    m_series = kind;
    m_interval = interval;
    m_shotsLeft = std::max(0, shots);
    m_startAt = now.seconds + std::max(0.0, delaySeconds);
    m_started = false;
    m_sinceLast = 0;
    m_lastSeconds = now.seconds;
    m_placed = false;
}

void SimShutter::stop()
{
    m_series = Series::None;
}

void SimShutter::tick(const FlightModel::State &state, Clock now)
{
    if (m_series == Series::None)
        return;
    if (state.mode != FlightModel::Mode::Auto && state.mode != FlightModel::Mode::Hold) {
        stop();
        return;
    }
    const bool paused = state.mode == FlightModel::Mode::Hold;
    const double elapsed = now.seconds - m_lastSeconds;
    const double moved = m_placed ? sphericalDistance(m_lastLatitude, m_lastLongitude, state.latitude, state.longitude) : 0.0;
    m_placed = true;
    m_lastSeconds = now.seconds;
    m_lastLatitude = state.latitude;
    m_lastLongitude = state.longitude;
    if (paused) {
        m_startAt += elapsed; // a delay does not run out during a hold either
        return;
    }
    if (!m_started) {
        if (now.seconds + 1e-9 < m_startAt)
            return;
        m_started = true;
        m_sinceLast = 0;
    } else {
        m_sinceLast += m_series == Series::Distance ? moved : elapsed;
        if (m_sinceLast < m_interval)
            return;
        // One photo a tick at most: what is left over counts towards the next, but never more than
        // one interval of it (a tick longer than an interval must not bunch photos up afterwards).
        m_sinceLast = std::min(m_sinceLast - m_interval, m_interval * 0.999);
    }
    take(state, now);
    if (m_shotsLeft > 0 && --m_shotsLeft == 0)
        stop();
}

void SimShutter::take(const FlightModel::State &state, Clock now)
{
    SimPhoto p;
    p.sequence = int(m_photos.size()) + 1;
    p.time = now.stampMs;
    p.latitude = state.latitude;
    p.longitude = state.longitude;
    p.altitudeAmsl = state.altitudeAmsl();
    p.altitudeAgl = state.altitudeAgl - state.floor;
    p.heading = state.heading;
    p.roll = state.roll;
    p.pitch = state.pitch;
    p.gimbalTilt = m_gimbalTilt;
    m_photos.push_back(p);
}

} // namespace sortie::sim
