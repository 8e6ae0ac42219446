#include "RouteTiming.h"

#include "FlownLegs.h"
#include "Geodesy.h"

#include <algorithm>
#include <cmath>

namespace sortie::mission {

namespace {

constexpr double kPi = 3.14159265358979323846;

double verticalSeconds(double dh, const TimingParameters &p)
{
    if (dh > 0)
        return p.climbRate > 0 ? dh / p.climbRate : 0.0;
    if (dh < 0)
        return p.descentRate > 0 ? -dh / p.descentRate : 0.0;
    return 0.0;
}

// Time to cover d metres at speed v, starting and/or ending at rest with acceleration a: each stop
// needs v²/2a metres and v/2a seconds more than cruising would; a leg too short to reach v is
// flown speeding up (and slowing down) all the way.
double horizontalSeconds(double d, double v, const std::optional<double> &a, bool stopAtStart, bool stopAtEnd)
{
    if (d <= 0 || v <= 0)
        return 0.0;
    const int stops = int(stopAtStart) + int(stopAtEnd);
    if (!a || *a <= 0 || stops == 0)
        return d / v;
    if (d >= stops * v * v / (2 * *a))
        return d / v + stops * v / (2 * *a);
    return stops == 2 ? 2 * std::sqrt(d / *a) : std::sqrt(2 * d / *a);
}

// The track's direction as a unit vector (east, north) for the wind triangle. A short leg (within
// kShortLegDegrees) is a straight line on the local ellipsoid to far better than a wind's direction
// is known, and this is many times cheaper than Vincenty's iteration; longer legs take the
// geodesic's initial azimuth.
struct Track
{
    double east = 0.0, north = 1.0;
};

Track trackOf(const GeoPoint &from, const GeoPoint &to)
{
    const double dLat = to.latitude - from.latitude, dLon = normalizeLongitude(to.longitude - from.longitude);
    if (std::abs(dLat) > kShortLegDegrees || std::abs(dLon) > kShortLegDegrees) {
        const std::optional<GeodesicInverse> g = geodesicInverse(from, to);
        const double az = (g ? g->azimuth1Deg : 0.0) * kPi / 180.0;
        return {std::sin(az), std::cos(az)};
    }
    constexpr Ellipsoid e = Ellipsoid::wgs84();
    const double e2 = e.f * (2 - e.f);
    const double phi = (from.latitude + to.latitude) / 2 * kPi / 180.0;
    const double sinPhi = std::sin(phi);
    const double w = 1 - e2 * sinPhi * sinPhi;
    const double north = dLat * (1 - e2) / w;                 // meridian radius / prime vertical radius
    const double east = dLon * std::cos(phi);
    const double length = std::hypot(east, north);
    return length > 0 ? Track{east / length, north / length} : Track{};
}

// Ground speed along a track at an air speed in a wind given as the vector it blows towards (m/s
// east, north); nullopt when the vehicle cannot make headway.
std::optional<double> groundSpeedAlong(double airSpeed, const Track &t, double windEast, double windNorth)
{
    const double along = windEast * t.east + windNorth * t.north;
    const double across = windNorth * t.east - windEast * t.north;
    if (std::abs(across) >= airSpeed)
        return std::nullopt;
    // The heading crabs into the cross wind; what is left of the air speed goes along the track.
    const double gs = std::sqrt(airSpeed * airSpeed - across * across) + along;
    if (!(gs > 1e-6))
        return std::nullopt;
    return gs;
}

QString legName(int leg, bool home)
{
    return home ? QStringLiteral("the flight home (leg %1)").arg(leg) : QStringLiteral("leg %1").arg(leg);
}

// Builds the legs one after another, keeping the running clock.
class LegBuilder
{
public:
    explicit LegBuilder(const TimingParameters &p)
        : m_p(p)
        // The wind blows towards fromDeg + 180°.
        , m_windEast(-p.wind.speed * std::sin(p.wind.fromDeg * kPi / 180.0))
        , m_windNorth(-p.wind.speed * std::cos(p.wind.fromDeg * kPi / 180.0))
    {
    }

    // Fills the move of a leg whose ends, speeds and stops are set; an error when it cannot be flown.
    std::optional<MissionError> move(TimedLeg &leg, double speed, bool stopAtStart, bool stopAtEnd) const
    {
        leg.airSpeed = speed > 0 ? speed : m_p.cruiseSpeed;
        leg.groundSpeed = leg.airSpeed;
        if (leg.distance > 0) {
            if (!(leg.airSpeed > 0))
                return MissionError{QStringLiteral("%1 has no speed, and no cruise speed is given").arg(legName(leg.leg, leg.returnHome)), {}, 0, 0, {}};
            if (m_p.wind.speed > 0) {
                const std::optional<double> gs = groundSpeedAlong(leg.airSpeed, trackOf(leg.from, leg.to), m_windEast, m_windNorth);
                if (!gs)
                    return MissionError{QStringLiteral("%1 cannot be flown at %2 m/s against a %3 m/s wind from %4°")
                                            .arg(legName(leg.leg, leg.returnHome))
                                            .arg(leg.airSpeed, 0, 'f', 1)
                                            .arg(m_p.wind.speed, 0, 'f', 1)
                                            .arg(m_p.wind.fromDeg, 0, 'f', 0),
                                        {}, 0, 0, {}};
                leg.groundSpeed = *gs;
            }
        }
        const double cruise = leg.distance > 0 ? leg.distance / leg.groundSpeed : 0.0;
        const double horizontal = horizontalSeconds(leg.distance, leg.groundSpeed, m_p.acceleration, stopAtStart, stopAtEnd);
        const double vertical = verticalSeconds(leg.heightChange, m_p);
        leg.moveSeconds = std::max(horizontal, vertical);
        leg.verticalSeconds = vertical;
        // Speed changes show only while the horizontal motion is the longer.
        leg.manoeuvreSeconds = horizontal >= vertical ? std::min(horizontal - cruise, leg.moveSeconds - vertical) : 0.0;
        leg.verticalAirSpeed = vertical > horizontal && leg.moveSeconds > 0 ? leg.airSpeed * cruise / leg.moveSeconds : leg.airSpeed;
        return std::nullopt;
    }

    void takeoff(TimedLeg &leg, double height) const
    {
        leg.takeoffClimb = height;
        leg.takeoffSeconds = verticalSeconds(height, m_p);
    }
    void landing(TimedLeg &leg, double height) const
    {
        leg.landsAtEnd = true;
        leg.landingDescent = height;
        leg.landingSeconds = verticalSeconds(-height, m_p);
    }

    void close(TimedLeg &leg)
    {
        leg.start = m_clock;
        leg.duration = leg.takeoffSeconds + leg.departHoldSeconds + leg.moveSeconds + leg.arriveHoldSeconds + leg.landingSeconds;
        m_clock += leg.duration;
    }

private:
    const TimingParameters &m_p;
    double m_windEast, m_windNorth;  // m/s, the way the wind blows
    double m_clock = 0.0;
};

double holdAt(const Route &route, const PathPoint &p)
{
    if (p.segment >= 0 && p.segment < int(route.segments.size()))
        if (const Waypoint *w = asWaypoint(route.segments[size_t(p.segment)]))
            return actionSeconds(w->actions);
    return p.holdSeconds;
}

double groundHeight(const PathPoint &p)
{
    return p.altitudeType == AltitudeType::Agl ? std::max(0.0, p.altitude) : 0.0;
}

} // namespace

TimingParameters timingOf(const RouteSettings &settings)
{
    TimingParameters p;
    p.cruiseSpeed = settings.initialSpeed;
    p.climbRate = settings.profile.climbRate;
    p.descentRate = settings.profile.descentRate;
    return p;
}

PhaseSeconds TimedLeg::phases() const
{
    PhaseSeconds s;
    s.hover = departHoldSeconds + arriveHoldSeconds;
    s.climb = takeoffSeconds + (heightChange > 0 ? verticalSeconds : 0.0);
    s.descent = landingSeconds + (heightChange < 0 ? verticalSeconds : 0.0);
    s.manoeuvre = manoeuvreSeconds;
    s.level = std::max(0.0, moveSeconds - verticalSeconds - manoeuvreSeconds);
    return s;
}

double actionSeconds(const std::vector<WaypointAction> &actions)
{
    double seconds = 0.0;
    for (const WaypointAction &a : actions) {
        if (const auto *wait = std::get_if<WaitAction>(&a)) {
            seconds += std::max(0.0, wait->seconds);
        } else if (const auto *pano = std::get_if<PanoramaAction>(&a)) {
            const double angle = std::abs(pano->angleDeg);
            if (pano->rotationSpeedDegPerSecond > 0)
                seconds += angle / pano->rotationSpeedDegPerSecond;
            // A photo panorama pauses at every step, the start included.
            if (pano->mode == PanoramaMode::Photo && pano->stepAngleDeg > 0)
                seconds += (std::floor(angle / pano->stepAngleDeg + 1e-9) + 1) * std::max(0.0, pano->stepDelaySeconds);
        }
    }
    return seconds;
}

std::optional<double> groundSpeed(double airSpeed, double trackDeg, const Wind &wind)
{
    if (!(wind.speed > 0))
        return airSpeed;
    const double track = trackDeg * kPi / 180.0, from = wind.fromDeg * kPi / 180.0;
    return groundSpeedAlong(airSpeed, {std::sin(track), std::cos(track)}, -wind.speed * std::sin(from), -wind.speed * std::cos(from));
}

RouteTimeline::RouteTimeline(std::vector<TimedLeg> legs) : m_legs(std::move(legs)) {}

int RouteTimeline::legAt(double seconds) const
{
    if (m_legs.empty())
        return -1;
    const auto after = std::upper_bound(m_legs.begin(), m_legs.end(), seconds, [](double t, const TimedLeg &l) { return t < l.start; });
    return std::max(0, int(after - m_legs.begin()) - 1);
}

TimelinePosition RouteTimeline::positionAt(double seconds) const
{
    TimelinePosition at;
    at.leg = legAt(seconds);
    if (at.leg < 0)
        return at;
    const TimedLeg &l = m_legs[size_t(at.leg)];
    at.altitudeType = l.altitudeType;
    double t = std::clamp(seconds - l.start, 0.0, l.duration);
    at.position = l.from;
    if (t < l.takeoffSeconds) {  // climbing from the ground
        at.altitude = l.fromAltitude - l.takeoffClimb * (1.0 - t / l.takeoffSeconds);
        return at;
    }
    t -= l.takeoffSeconds + l.departHoldSeconds;
    at.altitude = l.fromAltitude;
    if (t <= 0)
        return at;
    if (t < l.moveSeconds) {
        // Horizontal progress spread over the move (uniform speed: speed changes are not shown),
        // the height changing at its rate until it is reached.
        const double f = t / l.moveSeconds;
        const double v = l.verticalSeconds > 0 ? std::min(1.0, t / l.verticalSeconds) : 1.0;
        at.altitude = l.fromAltitude + l.heightChange * v;
        if (l.distance > 0) {
            const std::optional<GeodesicInverse> g = geodesicInverse(l.from, l.to);
            at.position = g ? geodesicDirect(l.from, g->azimuth1Deg, l.distance * f).point : l.to;
        }
        return at;
    }
    t -= l.moveSeconds + l.arriveHoldSeconds;
    at.position = l.to;
    at.altitude = l.toAltitude;
    if (t > 0 && l.landingSeconds > 0)
        at.altitude -= l.landingDescent * std::min(1.0, t / l.landingSeconds);
    return at;
}

Result<RouteTimeline> timeRoute(const Route &route, const TimingParameters &parameters, ScanPlanCache *cache)
{
    return timePath(route, flightPath(route, cache), parameters);
}

Result<RouteTimeline> timePath(const Route &route, const std::vector<PathPoint> &path, const TimingParameters &parameters)
{
    std::vector<TimedLeg> legs;
    if (path.empty())
        return RouteTimeline{};
    const RouteSettings &rs = route.settings;
    const bool goesHome = rs.endAction == EndAction::ReturnHome && rs.home.has_value();
    const size_t last = path.size() - 1;
    std::vector<double> holds(path.size());
    for (size_t i = 0; i < path.size(); ++i)
        holds[i] = holdAt(route, path[i]);
    const auto stopsAt = [&](size_t i) {
        return i == 0 || (i == last && !goesHome) || holds[i] > 0 || path[i].role != WaypointRole::Pass
            || parameters.turns == TurnMode::StopAndTurn;
    };
    legs.reserve(path.size() + 1);
    LegBuilder build(parameters);
    // The one rule for take-off climbs and landing descents (FlownLegs.h). Leg n runs from point
    // n-1 to point n; a lone point is one leg that goes nowhere: its take-off, holds and landing.
    for (const LegShape &shape : flownLegs(path)) {
        const size_t i = shape.to, from = shape.from;
        const PathPoint &q = path[from], &p = path[i];
        const PathPoint &depart = path[shape.departHeight], &arrive = path[shape.arriveHeight];
        TimedLeg leg;
        leg.leg = shape.leg;
        leg.from = q.position;
        leg.to = p.position;
        leg.fromAltitude = depart.altitude;
        leg.toAltitude = arrive.altitude;
        leg.altitudeType = arrive.altitudeType;
        leg.fromSegment = q.segment;
        leg.toSegment = p.segment;
        if (shape.moves()) {
            leg.distance = geodesicDistance(q.position, p.position);
            leg.heightChange = arrive.altitudeType == depart.altitudeType ? arrive.altitude - depart.altitude : 0.0;
            if (arrive.altitudeType != depart.altitudeType)
                leg.fromAltitude = arrive.altitude;  // frames differ: the height change is not known
        }
        if (auto error = build.move(leg, p.speed, stopsAt(from), stopsAt(i)))
            return *error;
        // Take-off counts in the leg that leaves its point, landing in the one that reaches it.
        if (shape.climbAtStart)
            build.takeoff(leg, groundHeight(depart));
        if (from == 0)
            leg.departHoldSeconds = holds[0];
        if (shape.moves()) {
            leg.arriveHoldSeconds = holds[i];
            if (shape.climbAtEnd && !goesHome)
                build.takeoff(leg, groundHeight(p));  // a take-off nothing leaves from
        }
        if (shape.descentAtEnd)
            build.landing(leg, groundHeight(arrive));
        build.close(leg);
        legs.push_back(leg);
    }
    const size_t legCount = legs.size();
    if (goesHome) {
        // Straight home at the last leg's speed, then down from the last height.
        const PathPoint &q = path[last];
        TimedLeg leg;
        leg.leg = int(legCount) + 1;
        leg.returnHome = true;
        leg.from = q.position;
        leg.to = rs.home->position;
        leg.fromAltitude = leg.toAltitude = q.altitude;
        leg.altitudeType = q.altitudeType;
        leg.fromSegment = q.segment;
        leg.distance = geodesicDistance(q.position, rs.home->position);
        if (auto error = build.move(leg, q.speed, stopsAt(last), true))
            return *error;
        build.landing(leg, q.altitudeType == AltitudeType::Agl ? std::max(0.0, q.altitude)
                                                                : std::max(0.0, q.altitude - rs.home->altitudeAmsl));
        build.close(leg);
        legs.push_back(leg);
    }
    return RouteTimeline(std::move(legs));
}

} // namespace sortie::mission
