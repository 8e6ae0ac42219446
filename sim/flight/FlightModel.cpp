#include "FlightModel.h"

#include <algorithm>
#include <cmath>

namespace sortie::sim {
namespace {

constexpr double kEarthRadius = 6371008.8; // mean radius, metres
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

double wrap360(double deg)
{
    deg = std::fmod(deg, 360.0);
    return deg < 0 ? deg + 360.0 : deg;
}

double wrap180(double deg)
{
    deg = wrap360(deg);
    return deg > 180.0 ? deg - 360.0 : deg;
}

} // namespace

double sphericalDistance(double lat1, double lon1, double lat2, double lon2)
{
    const double p1 = lat1 * kDeg, p2 = lat2 * kDeg;
    const double dp = (lat2 - lat1) * kDeg, dl = (lon2 - lon1) * kDeg;
    const double a = std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
    return 2 * kEarthRadius * std::atan2(std::sqrt(a), std::sqrt(std::max(0.0, 1 - a)));
}

double sphericalBearing(double lat1, double lon1, double lat2, double lon2)
{
    const double p1 = lat1 * kDeg, p2 = lat2 * kDeg, dl = (lon2 - lon1) * kDeg;
    const double y = std::sin(dl) * std::cos(p2);
    const double x = std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl);
    return wrap360(std::atan2(y, x) / kDeg);
}

void sphericalDestination(double lat, double lon, double bearing, double distance, double *outLat, double *outLon)
{
    const double d = distance / kEarthRadius, b = bearing * kDeg, p1 = lat * kDeg, l1 = lon * kDeg;
    const double p2 = std::asin(std::sin(p1) * std::cos(d) + std::cos(p1) * std::sin(d) * std::cos(b));
    const double l2 = l1 + std::atan2(std::sin(b) * std::sin(d) * std::cos(p1), std::cos(d) - std::sin(p1) * std::sin(p2));
    *outLat = p2 / kDeg;
    *outLon = wrap180(l2 / kDeg);
}

FlightModel::Limits FlightModel::Limits::forProfile(const endurance::EnergyProfile &profile)
{
    Limits limits;
    limits.energy = profile;
    if (profile.cruiseSpeed > 0)
        limits.cruiseSpeed = profile.cruiseSpeed;
    limits.maxSpeed = std::max(limits.maxSpeed, limits.cruiseSpeed);
    if (profile.climbRate > 0)
        limits.climbRate = profile.climbRate;
    if (profile.descentRate > 0)
        limits.descentRate = profile.descentRate;
    return limits;
}

FlightModel::FlightModel(double homeLatitude, double homeLongitude, double groundElevation)
    : FlightModel(homeLatitude, homeLongitude, groundElevation, Limits{})
{
}

FlightModel::FlightModel(double homeLatitude, double homeLongitude, double groundElevation, Limits limits)
    : m_limits(limits)
    , m_battery(limits.energy.batteryWh)
{
    m_state.latitude = m_state.homeLatitude = homeLatitude;
    m_state.longitude = m_state.homeLongitude = homeLongitude;
    m_state.groundElevation = groundElevation;
    m_state.batteryVoltage = m_battery.voltage();
    m_state.satellites = 14;
    m_state.gpsFix = 3;
}

FlightModel::Refusal FlightModel::arm()
{
    if (m_state.armed)
        return "already armed";
    if (m_state.gpsFix < 3)
        return "no 3D GPS fix";
    if (m_state.batteryRemaining < 0.1)
        return "battery too low to arm";
    m_state.armed = true;
    m_state.homeLatitude = m_state.latitude;
    m_state.homeLongitude = m_state.longitude;
    return {};
}

FlightModel::Refusal FlightModel::disarm()
{
    if (!m_state.armed)
        return "not armed";
    if (m_state.airborne())
        return "cannot disarm in flight; land first";
    m_state.armed = false;
    m_state.mode = Mode::Manual;
    m_state.currentWaypoint = -1;
    return {};
}

FlightModel::Refusal FlightModel::takeoff(double altitudeAgl)
{
    if (!m_state.armed)
        return "arm before take-off";
    if (m_state.airborne())
        return "already airborne";
    m_target = {m_state.latitude, m_state.longitude, altitudeAgl > 0 ? altitudeAgl : m_limits.takeoffAltitude, 0};
    m_state.mode = Mode::Takeoff;
    return {};
}

FlightModel::Refusal FlightModel::setMission(std::vector<Waypoint> waypoints)
{
    if (m_state.mode == Mode::Auto)
        return "cannot replace the mission while flying it; pause first";
    m_mission = std::move(waypoints);
    ++m_missionVersion;
    m_state.currentWaypoint = -1;
    m_state.missionComplete = false;
    return {};
}

FlightModel::Refusal FlightModel::startMission()
{
    if (m_mission.empty())
        return "no mission uploaded";
    if (!m_state.armed)
        return "arm before starting the mission";
    m_state.currentWaypoint = 0;
    m_state.missionComplete = false;
    m_holdLeft = -1;
    m_climbingOut = false;
    m_state.mode = Mode::Auto;
    return {};
}

FlightModel::Refusal FlightModel::pause()
{
    if (!m_state.airborne())
        return "not flying";
    m_state.mode = Mode::Hold;
    return {};
}

FlightModel::Refusal FlightModel::resume()
{
    if (m_mission.empty() || m_state.currentWaypoint < 0)
        return "no mission to resume";
    if (!m_state.armed)
        return "not armed";
    m_state.mode = Mode::Auto;
    return {};
}

FlightModel::Refusal FlightModel::land()
{
    if (!m_state.airborne())
        return "already on the ground";
    m_state.mode = Mode::Land;
    return {};
}

FlightModel::Refusal FlightModel::returnHome()
{
    if (!m_state.airborne())
        return "not flying";
    m_state.mode = Mode::ReturnHome;
    return {};
}

FlightModel::Refusal FlightModel::goTo(double latitude, double longitude, double altitudeAgl, double speed)
{
    if (!m_state.armed)
        return "not armed";
    if (std::abs(latitude) > 90 || std::abs(longitude) > 180)
        return "target outside the globe";
    m_target = {latitude, longitude, std::max(altitudeAgl, 2.0), speed};
    m_state.mode = Mode::Guided;
    return {};
}

FlightModel::Refusal FlightModel::manual()
{
    m_state.mode = Mode::Manual;
    return {};
}

FlightModel::Refusal FlightModel::setMode(Mode mode)
{
    switch (mode) {
    case Mode::Manual: return manual();
    case Mode::Hold: return pause();
    case Mode::Takeoff: return takeoff();
    case Mode::Auto: return m_state.currentWaypoint >= 0 ? resume() : startMission();
    case Mode::Guided: return goTo(m_state.latitude, m_state.longitude, m_state.altitudeAgl);
    case Mode::Land: return land();
    case Mode::ReturnHome: return returnHome();
    }
    return "unknown mode";
}

const char *FlightModel::modeName(Mode mode)
{
    switch (mode) {
    case Mode::Manual: return "manual";
    case Mode::Hold: return "hold";
    case Mode::Takeoff: return "takeoff";
    case Mode::Auto: return "auto";
    case Mode::Guided: return "guided";
    case Mode::Land: return "land";
    case Mode::ReturnHome: return "return_home";
    }
    return "unknown";
}

bool FlightModel::modeFromName(const std::string &name, Mode *mode)
{
    for (Mode m : {Mode::Manual, Mode::Hold, Mode::Takeoff, Mode::Auto, Mode::Guided, Mode::Land, Mode::ReturnHome}) {
        if (name == modeName(m)) {
            *mode = m;
            return true;
        }
    }
    return false;
}

void FlightModel::turnTowards(double bearing, double dt)
{
    const double delta = wrap180(bearing - m_state.heading);
    const double step = m_limits.yawRate * dt;
    m_state.heading = wrap360(m_state.heading + std::clamp(delta, -step, step));
}

void FlightModel::climbTo(double altAgl, double dt, double timeToGo)
{
    // Spread over the time left to the waypoint, as autopilots slide the height along a leg: the
    // vehicle flies the straight line the plan drew (within its climb and descent rates).
    const double diff = altAgl - m_state.altitudeAgl;
    const double wanted = diff / std::max(dt, timeToGo);
    const double rate = diff > 0 ? std::min(m_limits.climbRate, wanted) : std::max(-m_limits.descentRate, wanted);
    m_state.verticalSpeed = rate;
    m_state.altitudeAgl = std::max(m_state.floor, m_state.altitudeAgl + rate * dt);
}

bool FlightModel::flyTowards(double lat, double lon, double altAgl, double speed, double dt, double radius)
{
    const double distance = sphericalDistance(m_state.latitude, m_state.longitude, lat, lon);
    const double cruise = std::min(speed > 0 ? speed : m_limits.cruiseSpeed, m_limits.maxSpeed);
    climbTo(altAgl, dt, distance / cruise);
    if (distance > 0.01) {
        const double bearing = sphericalBearing(m_state.latitude, m_state.longitude, lat, lon);
        turnTowards(bearing, dt);
        const double step = std::min(distance, cruise * dt);
        sphericalDestination(m_state.latitude, m_state.longitude, bearing, step, &m_state.latitude, &m_state.longitude);
        m_state.groundSpeed = step / dt;
        m_state.pitch = -std::min(15.0, m_state.groundSpeed * 1.5);
    } else {
        m_state.groundSpeed = 0;
        m_state.pitch = 0;
    }
    return distance <= (radius > 0 ? radius : m_limits.acceptanceRadius) && std::abs(altAgl - m_state.altitudeAgl) < 0.5;
}

void FlightModel::tick(double dt)
{
    if (dt <= 0)
        return;
    State &s = m_state;
    s.floor = floorHere();
    s.verticalSpeed = 0;
    s.groundSpeed = 0;
    switch (s.mode) {
    case Mode::Manual:
    case Mode::Hold:
        if (s.mode == Mode::Manual && s.airborne()) // no stick input: hold altitude, drift to a stop
            climbTo(s.altitudeAgl, dt);
        break;
    case Mode::Takeoff:
        climbTo(m_target.altitudeAgl, dt);
        if (std::abs(s.altitudeAgl - m_target.altitudeAgl) < 0.3)
            s.mode = Mode::Hold;
        break;
    case Mode::Auto: {
        if (s.currentWaypoint < 0 || s.currentWaypoint >= int(m_mission.size())) {
            s.mode = Mode::Hold;
            break;
        }
        const Waypoint &wp = m_mission[size_t(s.currentWaypoint)];
        // A multicopter leaves the ground straight up: from the ground it climbs to the waypoint's
        // height where it stands, and only then moves across (mission::flownLegs' take-off).
        if (!s.airborne() && wp.altitudeAgl > s.altitudeAgl + 0.5)
            m_climbingOut = true;
        if (m_climbingOut) {
            climbTo(wp.altitudeAgl, dt);
            if (std::abs(wp.altitudeAgl - s.altitudeAgl) >= 0.5)
                break;
            m_climbingOut = false;
        }
        if (flyTowards(wp.latitude, wp.longitude, wp.altitudeAgl, wp.speed, dt, wp.acceptanceRadius)) {
            if (m_holdLeft < 0 && m_waypointReached)
                m_waypointReached(s.currentWaypoint);
            if (m_holdLeft < 0 && wp.holdSeconds > 0)
                m_holdLeft = wp.holdSeconds; // arrived: start waiting
            if (m_holdLeft > 0) {
                m_holdLeft = std::max(0.0, m_holdLeft - dt);
                if (m_holdLeft > 0)
                    break;
            }
            m_holdLeft = -1;
            if (wp.landHere) {
                s.mode = Mode::Land;
                s.missionComplete = true;
                break;
            }
            if (++s.currentWaypoint >= int(m_mission.size())) {
                s.currentWaypoint = int(m_mission.size()) - 1;
                s.mode = Mode::Hold; // mission complete: hold at the last waypoint
                s.missionComplete = true;
            }
        }
        break;
    }
    case Mode::Guided:
        if (flyTowards(m_target.latitude, m_target.longitude, m_target.altitudeAgl, m_target.speed, dt))
            s.mode = Mode::Hold;
        break;
    case Mode::Land: // straight down to the ground under it
        climbTo(s.floor, dt);
        if (!s.airborne()) {
            s.altitudeAgl = s.floor;
            s.armed = false; // auto-disarm on touchdown
            s.mode = Mode::Manual;
        }
        break;
    case Mode::ReturnHome: {
        const double distance = sphericalDistance(s.latitude, s.longitude, s.homeLatitude, s.homeLongitude);
        const double cruiseAlt = std::max(s.altitudeAgl, m_limits.returnAltitude);
        if (distance > m_limits.acceptanceRadius && s.altitudeAgl < m_limits.returnAltitude - 0.5)
            climbTo(m_limits.returnAltitude, dt); // climb first, then go
        else if (flyTowards(s.homeLatitude, s.homeLongitude, cruiseAlt, 0, dt))
            s.mode = Mode::Land;
        break;
    }
    }
    s.floor = floorHere();
    if (s.armed)
        m_armedSeconds += dt;
    drainBattery(dt);
    s.roll = 0;
}

double FlightModel::floorHere() const
{
    if (!m_ground)
        return 0.0;
    const std::optional<double> g = m_ground(m_state.latitude, m_state.longitude);
    return g ? *g - m_state.groundElevation : 0.0;
}

void FlightModel::drainBattery(double dt)
{
    // The power of what this tick did (its speeds), drawn over the tick.
    State &s = m_state;
    m_battery.draw(simPowerW(m_limits.energy, s.armed, s.airborne(), s.groundSpeed, s.verticalSpeed), dt);
    s.batteryRemaining = m_battery.remaining();
    s.batteryVoltage = m_battery.voltage();
    s.batteryCurrent = m_battery.current();
}

} // namespace sortie::sim
