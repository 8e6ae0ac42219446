#include "EnduranceEstimate.h"

#include "Geodesy.h"

#include <algorithm>
#include <cmath>

namespace sortie::endurance {

using namespace sortie::mission;

namespace {

constexpr double kSecondsPerHour = 3600.0;

// Energy within one leg, split where the timeline splits it: before the move (take-off, holds at
// the start), the move itself, and after it (holds at the end, the landing).
struct LegParts
{
    double beforeWh = 0.0, moveWh = 0.0, holdAfterWh = 0.0, landingWh = 0.0;
    double total() const { return beforeWh + moveWh + holdAfterWh + landingWh; }
};

LegParts legParts(const TimedLeg &l, const EnergyProfile &p)
{
    LegParts e;
    e.beforeWh = (l.takeoffSeconds * p.climbPowerW + l.departHoldSeconds * p.hoverPowerW) / kSecondsPerHour;
    // Level flight and the speed changes at stops, at the leg's air speed.
    double joules = std::max(0.0, l.moveSeconds - l.verticalSeconds) * p.levelPowerW(l.airSpeed);
    if (l.verticalSeconds > 0) {
        // A height change flown with horizontal motion: level power plus what the climb costs
        // beyond hovering (its potential energy), or minus what the descent saves, never below
        // the descent power itself. Straight up or down this is exactly climbPowerW / descentPowerW.
        const double moving = p.levelPowerW(l.verticalAirSpeed);
        const double power = l.heightChange > 0 ? moving + p.climbPowerW - p.hoverPowerW
                                                : std::max(p.descentPowerW, moving + p.descentPowerW - p.hoverPowerW);
        joules += l.verticalSeconds * power;
    }
    e.moveWh = joules / kSecondsPerHour;
    e.holdAfterWh = l.arriveHoldSeconds * p.hoverPowerW / kSecondsPerHour;
    e.landingWh = l.landingSeconds * p.descentPowerW / kSecondsPerHour;
    return e;
}

// A place a fraction of the way along a leg's horizontal motion.
RoutePlace placeOn(const TimedLeg &l, double startDistance, double fraction)
{
    RoutePlace at;
    at.leg = l.leg;
    at.distance = startDistance + l.distance * fraction;
    at.altitude = l.fromAltitude + l.heightChange * fraction;
    at.altitudeType = l.altitudeType;
    if (fraction <= 0) {
        at.position = l.from;
        at.segment = l.fromSegment;
    } else if (fraction >= 1) {
        at.position = l.to;
        at.segment = l.toSegment;
    } else {
        const std::optional<GeodesicInverse> g = geodesicInverse(l.from, l.to);
        at.position = g ? geodesicDirect(l.from, g->azimuth1Deg, l.distance * fraction).point : l.to;
    }
    return at;
}

// Finds the point of no return: the first place on the first battery where going straight home
// would land below the reserve; what is returned is the last place before it that still would not.
class NoReturnSearch
{
public:
    NoReturnSearch(const EnergyProfile &p, const HomePosition &home, const Wind &wind) : m_p(p), m_home(home), m_wind(wind) {}

    // Energy left above the reserve after going home from `at` with `usedWh` spent; -inf when home
    // cannot be reached at all.
    double margin(const RoutePlace &at, double usedWh) const
    {
        const std::optional<double> home = energyHomeWh(m_p, at.position, heightAboveHome(at.altitude, at.altitudeType, m_home),
                                                         m_home.position, m_wind);
        return home ? m_p.usableWh() - usedWh - *home : -HUGE_VAL;
    }

    std::optional<RoutePlace> find(const RouteTimeline &timeline, const std::vector<LegParts> &parts, const std::vector<double> &startWh) const
    {
        double distance = 0.0;
        std::optional<RoutePlace> lastGood;
        for (size_t k = 0; k < timeline.legs().size(); ++k) {
            const TimedLeg &l = timeline.legs()[k];
            const LegParts &e = parts[k];
            const double pre = startWh[k] + e.beforeWh;
            const RoutePlace start = placeOn(l, distance, 0.0);
            if (margin(start, pre) < 0)
                return lastGood ? lastGood : start;  // out of reach from the start: the start itself
            const RoutePlace end = placeOn(l, distance, 1.0);
            if (margin(end, pre + e.moveWh + e.holdAfterWh) < 0) {
                if (margin(end, pre + e.moveWh) >= 0)
                    return end;  // reached, but not the holds there
                // Along the move the margin falls (more spent, usually further out): bisect.
                double good = 0.0, bad = 1.0;
                for (int i = 0; i < 40 && (bad - good) * l.distance > 0.01; ++i) {
                    const double f = (good + bad) / 2;
                    (margin(placeOn(l, distance, f), pre + e.moveWh * f) >= 0 ? good : bad) = f;
                }
                return placeOn(l, distance, good);
            }
            lastGood = end;
            distance += l.distance;
        }
        return std::nullopt;
    }

private:
    const EnergyProfile &m_p;
    const HomePosition &m_home;
    Wind m_wind;
};

} // namespace

TimingParameters timingFor(const EnergyProfile &profile, const FlightConditions &conditions)
{
    TimingParameters t;
    t.cruiseSpeed = profile.cruiseSpeed;
    t.climbRate = profile.climbRate;
    t.descentRate = profile.descentRate;
    t.acceleration = profile.acceleration;
    t.turns = conditions.turns;
    t.wind = conditions.wind;
    return t;
}

double legEnergyWh(const TimedLeg &leg, const EnergyProfile &profile)
{
    return legParts(leg, profile).total();
}

double heightAboveHome(double altitude, AltitudeType type, const HomePosition &home)
{
    return type == AltitudeType::Agl ? altitude : altitude - home.altitudeAmsl;
}

std::optional<double> energyHomeWh(const EnergyProfile &p, const GeoPoint &from, double height, const GeoPoint &home, const Wind &wind)
{
    double joules = 0.0;
    const double d = geodesicDistance(from, home);
    if (d > 0) {
        double speed = p.cruiseSpeed;
        if (wind.speed > 0) {
            const std::optional<GeodesicInverse> g = geodesicInverse(from, home);
            const std::optional<double> gs = groundSpeed(p.cruiseSpeed, g ? g->azimuth1Deg : 0.0, wind);
            if (!gs)
                return std::nullopt;
            speed = *gs;
        }
        joules += p.levelPowerW(p.cruiseSpeed) * d / speed;
    }
    if (height > 0)
        joules += p.descentPowerW * height / p.descentRate;
    else if (height < 0)
        joules += p.climbPowerW * -height / p.climbRate;
    return joules / kSecondsPerHour;
}

Result<EnduranceEstimate> estimateEndurance(const Route &route, const EnergyProfile &profile, const FlightConditions &conditions,
                                            ScanPlanCache *cache)
{
    if (const QString problem = profile.problem(); !problem.isEmpty())
        return MissionError{QStringLiteral("energy profile: %1").arg(problem), {}, 0, 0, {}};
    Result<RouteTimeline> timed = timeRoute(route, timingFor(profile, conditions), cache);
    if (!timed)
        return timed.error();
    EnduranceEstimate est;
    est.timeline = std::move(timed).value();
    est.usableWh = profile.usableWh();
    est.reserveWh = profile.batteryWh * profile.reserve;
    const std::vector<TimedLeg> &legs = est.timeline.legs();
    std::vector<LegParts> parts;
    std::vector<double> startWh, endWh, startDistance;
    parts.reserve(legs.size());
    startWh.reserve(legs.size());
    endWh.reserve(legs.size());
    startDistance.reserve(legs.size());
    est.legs.reserve(legs.size());
    double used = 0.0, distance = 0.0;
    for (const TimedLeg &l : legs) {
        parts.push_back(legParts(l, profile));
        startWh.push_back(used);
        startDistance.push_back(distance);
        const double wh = parts.back().total();
        est.legs.push_back({l.leg, l.returnHome, l.duration, wh, used});
        used += wh;
        distance += l.distance;
        endWh.push_back(used);
    }
    est.energyWh = used;
    est.flightTimeSeconds = est.timeline.totalSeconds();
    est.batteryAtEnd = 1.0 - used / profile.batteryWh;

    // Battery changes: on each battery, fly to the last leg end it reaches with the reserve intact
    // (a planned landing before it, if there is one: the latest), change there, go on.
    constexpr double kSlackWh = 1e-9;
    double base = 0.0;
    long last = -1;
    for (size_t k = 0; k < legs.size() && !est.legTooLong; ++k) {
        while (endWh[k] - base > est.usableWh + kSlackWh) {
            if (long(k) - 1 <= last) {
                est.legTooLong = legs[k].leg;
                break;
            }
            long j = long(k) - 1;
            bool planned = false;
            for (long m = j; m > last; --m)
                if (legs[size_t(m)].landsAtEnd) {
                    j = m;
                    planned = true;
                    break;
                }
            BatteryChange change;
            change.at = placeOn(legs[size_t(j)], startDistance[size_t(j)], 1.0);
            change.batteryLeft = 1.0 - (endWh[size_t(j)] - base) / profile.batteryWh;
            change.planned = planned;
            est.changes.push_back(change);
            base = endWh[size_t(j)];
            last = j;
        }
    }
    est.lastBatteryAtEnd = 1.0 - (used - base) / profile.batteryWh;
    est.batteriesNeeded = int(est.changes.size()) + 1;
    if (est.legTooLong)
        est.batteriesNeeded = std::max(est.batteriesNeeded, int(std::ceil(used / est.usableWh)));

    if (route.settings.home) {
        est.homeKnown = true;
        est.pointOfNoReturn = NoReturnSearch(profile, *route.settings.home, conditions.wind).find(est.timeline, parts, startWh);
    }
    return est;
}

} // namespace sortie::endurance
