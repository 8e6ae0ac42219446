#include "RouteComparison.h"

#include "FlightPath.h"
#include "FlownLegs.h"
#include "LocalTangentPlane.h"

#include <QDateTime>
#include <QJsonArray>
#include <QStringList>

#include <cmath>
#include <limits>
#include <numbers>

namespace sortie::flightlog {

using vehicle::TelemetryField;

namespace {

struct Sample
{
    int64_t time;
    mission::PlanePoint p;
    double amsl, agl; // NaN when unknown
    double lat, lon;  // degrees
};

struct Planned
{
    mission::PlanePoint p;
    double altitude;
    bool amsl;
    double radius;
};

double dist(const mission::PlanePoint &a, const mission::PlanePoint &b)
{
    return std::hypot(a.x - b.x, a.y - b.y);
}

// Distance from p to the segment a-b and where along it (0..1) the closest point is.
double toSegment(const mission::PlanePoint &p, const mission::PlanePoint &a, const mission::PlanePoint &b, double *along)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    if (along)
        *along = t;
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

std::vector<Sample> trackOf(const FlightLog &log, int vehicle, const mission::LocalTangentPlane &plane)
{
    const FlightLog::Vehicle &v = log.vehicles()[size_t(vehicle)];
    std::vector<Sample> out;
    double lat = std::nan(""), lon = std::nan(""), amsl = std::nan(""), agl = std::nan("");
    const vehicle::TelemetryBatch updates = log.updatesBetween(vehicle, v.start - 1, v.end);
    for (size_t i = 0; i < updates.size(); ++i) {
        const vehicle::TelemetryUpdate &u = updates[i];
        switch (u.field) {
        case TelemetryField::Latitude: lat = u.value; break;
        case TelemetryField::Longitude: lon = u.value; break;
        case TelemetryField::AltitudeAmsl: amsl = u.value; break;
        case TelemetryField::AltitudeAgl: agl = u.value; break;
        default: break;
        }
        const bool lastOfTime = i + 1 == updates.size() || updates[i + 1].time != u.time;
        if (lastOfTime && std::isfinite(lat) && std::isfinite(lon))
            out.push_back({u.time, plane.project({lat, lon}), amsl, agl, lat, lon});
    }
    return out;
}

QString when(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

double jsonNumber(double v)
{
    return std::isfinite(v) ? std::round(v * 100) / 100 : 0;
}

QJsonValue jsonOrNull(double v)
{
    return std::isfinite(v) ? QJsonValue(std::round(v * 100) / 100) : QJsonValue();
}

} // namespace

ComparisonResult compareRoute(const FlightLog &log, int vehicle, const mission::Route &route)
{
    if (vehicle < 0 || size_t(vehicle) >= log.vehicles().size()) {
        QStringList names;
        for (const FlightLog::Vehicle &v : log.vehicles())
            names.append(v.name());
        return {std::nullopt, QObject::tr("That vehicle is not in this log (it holds %1).").arg(names.isEmpty() ? QObject::tr("no vehicle") : names.join(QStringLiteral(", ")))};
    }
    const FlightLog::Vehicle &v = log.vehicles()[size_t(vehicle)];
    const std::vector<mission::PathPoint> path = mission::flightPath(route);
    if (path.size() < 2)
        return {std::nullopt, QObject::tr("Route \"%1\" has fewer than two waypoints: there is nothing to compare.").arg(route.settings.name)};

    // Each leg's heights as flown (FlownLegs.h): a take-off has climbed straight up before the leg,
    // a landing is descended to straight down after it.
    const std::vector<mission::LegShape> shapes = mission::flownLegs(path);
    const mission::LocalTangentPlane plane(path.front().position);
    std::vector<Planned> planned;
    for (const mission::PathPoint &p : path) {
        double radius = 0;
        if (p.segment >= 0 && size_t(p.segment) < route.segments.size()) {
            if (const auto *w = std::get_if<mission::Waypoint>(&route.segments[size_t(p.segment)]))
                radius = w->acceptanceRadius;
        }
        planned.push_back({plane.project(p.position), p.altitude, p.altitudeType == mission::AltitudeType::Amsl,
                           radius > 0 ? radius : kDefaultAcceptance});
    }
    const std::vector<Sample> track = trackOf(log, vehicle, plane);
    if (track.size() < 2)
        return {std::nullopt, QObject::tr("%1 has no track in this log to compare with.").arg(v.name())};

    // The route must be where this vehicle flew.
    double nearest = std::numeric_limits<double>::infinity();
    for (const Planned &w : planned) {
        for (const Sample &s : track)
            nearest = std::min(nearest, dist(w.p, s.p));
    }
    if (nearest > kMatchDistance)
        return {std::nullopt, QObject::tr("Route \"%1\" does not match %2: its waypoints are %3 km from anywhere %2 flew in this log.")
                                  .arg(route.settings.name, v.name(), QString::number(nearest / 1000, 'f', 1))};

    RouteComparison c;
    c.routeName = route.settings.name;
    c.vehicleName = v.name();
    const size_t n = planned.size();
    std::vector<std::optional<size_t>> reachedAt(n); // track index at which each waypoint was reached
    size_t cursor = 0;
    for (size_t w = 0; w < n; ++w) {
        WaypointPassage passage{int(w), path[w].position.latitude, path[w].position.longitude, planned[w].radius, std::nullopt,
                                std::numeric_limits<double>::infinity()};
        for (size_t k = cursor; k + 1 < track.size(); ++k) {
            double along = 0;
            const double d = toSegment(planned[w].p, track[k].p, track[k + 1].p, &along);
            passage.closest = std::min(passage.closest, d);
            if (d <= planned[w].radius) {
                passage.reachedAt = track[k].time + int64_t(std::llround(along * double(track[k + 1].time - track[k].time)));
                reachedAt[w] = k;
                cursor = k;
                break;
            }
        }
        if (passage.reachedAt)
            ++c.reached;
        else
            ++c.missed;
        c.waypoints.push_back(passage);
    }

    // Legs, and which track points belong to which.
    for (size_t w = 1; w < n; ++w)
        c.legs.push_back({int(w - 1), int(w), 0, 0, 0, 0, 0});
    std::vector<double> altitudeSum(c.legs.size(), 0), crossSum(c.legs.size(), 0);
    std::vector<int> altitudeSamples(c.legs.size(), 0);
    size_t nextUnassigned = 0; // windows meet at a reached waypoint's point: it counts once
    // A sample belongs to the leg the vehicle is flying: legs are taken in order, starting with the leg
    // that leaves the last reached waypoint. A later leg takes over only where the track comes within
    // kRejoinDistance of it (a vehicle sent elsewhere mid-leg stays on the leg it left, however close a
    // later leg happens to pass).
    constexpr double kRejoinDistance = 10.0;
    // fromStart: the window begins where the route's first waypoint was reached.
    auto assign = [&](size_t fromTrack, size_t toTrack, size_t firstLeg, size_t lastLeg, bool fromStart = false) { // legs by 'to' waypoint
        fromTrack = std::max(fromTrack, nextUnassigned);
        nextUnassigned = toTrack + 1;
        size_t current = firstLeg;
        bool closingIn = true; // towards the waypoint just reached, until the track first moves away from it
        double lastToTurn = std::numeric_limits<double>::infinity();
        for (size_t k = fromTrack; k <= toTrack && k < track.size(); ++k) {
            double bestAlong = 0;
            double bestD = toSegment(track[k].p, planned[current - 1].p, planned[current].p, &bestAlong);
            size_t best = current;
            // Closing in on the waypoint just reached (inside twice its acceptance radius, not yet past it,
            // not yet moving away) is still flying the leg into it.
            const size_t turnAt = firstLeg - 1;
            const double toTurn = dist(track[k].p, planned[turnAt].p);
            closingIn = closingIn && toTurn <= lastToTurn + 0.01;
            lastToTurn = toTurn;
            // Closing in on the route's first waypoint, not yet 1 m along leg 1: the flight from
            // wherever the vehicle started, which is no leg of the route (its acceptance radius is
            // reached before the vehicle is there).
            if (turnAt == 0 && closingIn && current == firstLeg && fromStart && bestAlong * dist(planned[0].p, planned[1].p) < 1.0)
                continue;
            if (closingIn && current == firstLeg && turnAt >= 1 && toTurn <= 2 * planned[turnAt].radius) {
                double along = 0;
                const double d = toSegment(track[k].p, planned[turnAt - 1].p, planned[turnAt].p, &along);
                if (along < 1.0 && d < bestD) { // not yet past the waypoint along the leg into it
                    bestD = d;
                    best = turnAt;
                    bestAlong = along;
                }
            }
            for (size_t leg = current + 1; leg <= lastLeg; ++leg) {
                double along = 0;
                const double d = toSegment(track[k].p, planned[leg - 1].p, planned[leg].p, &along);
                if (d <= kRejoinDistance && d < bestD) {
                    bestD = d;
                    best = leg;
                    bestAlong = along;
                }
            }
            current = std::max(current, best);
            LegDeviation &l = c.legs[best - 1];
            ++l.samples;
            l.maxCrossTrack = std::max(l.maxCrossTrack, bestD);
            crossSum[best - 1] += bestD;
            const Planned &a = planned[shapes[best - 1].departHeight], &b = planned[shapes[best - 1].arriveHeight];
            const double plannedAltitude = a.altitude + bestAlong * (b.altitude - a.altitude);
            const double flown = b.amsl ? track[k].amsl : track[k].agl;
            double dev = std::nan("");
            if (std::isfinite(flown)) {
                dev = std::fabs(flown - plannedAltitude);
                l.maxAltitude = std::max(l.maxAltitude, dev);
                altitudeSum[best - 1] += dev;
                ++altitudeSamples[best - 1];
            }
            c.track.push_back({track[k].lat, track[k].lon, track[k].time, int(best - 1), bestD, dev});
        }
    };
    std::optional<size_t> previous; // waypoint index of the last reached one
    for (size_t w = 0; w < n; ++w) {
        if (!reachedAt[w])
            continue;
        if (previous) // from the last reached waypoint to this one: the legs between them
            assign(*reachedAt[*previous], *reachedAt[w], *previous + 1, w, *previous == 0);
        else if (w > 0) // the first waypoints were missed: from the start of the track
            assign(0, *reachedAt[w], 1, w);
        previous = w;
    }
    if (!previous)
        assign(0, track.size() - 1, 1, n - 1);
    else if (*previous + 1 < n) // sent elsewhere before the end: the rest of the track from the leg it left on
        assign(*reachedAt[*previous], track.size() - 1, *previous + 1, n - 1, *previous == 0);

    double crossTotal = 0, altitudeTotal = 0;
    int crossCount = 0, altitudeCount = 0;
    for (size_t i = 0; i < c.legs.size(); ++i) {
        LegDeviation &l = c.legs[i];
        l.meanCrossTrack = l.samples ? crossSum[i] / l.samples : std::nan("");
        l.meanAltitude = altitudeSamples[i] ? altitudeSum[i] / altitudeSamples[i] : std::nan("");
        if (!altitudeSamples[i])
            l.maxAltitude = std::nan("");
        if (!l.samples)
            l.maxCrossTrack = std::nan("");
        crossTotal += crossSum[i];
        crossCount += l.samples;
        altitudeTotal += altitudeSum[i];
        altitudeCount += altitudeSamples[i];
        if (l.samples)
            c.maxCrossTrack = std::max(c.maxCrossTrack, l.maxCrossTrack);
        if (altitudeSamples[i])
            c.maxAltitude = std::max(c.maxAltitude, l.maxAltitude);
    }
    c.meanCrossTrack = crossCount ? crossTotal / crossCount : std::nan("");
    c.meanAltitude = altitudeCount ? altitudeTotal / altitudeCount : std::nan("");
    c.start = track.front().time;
    c.end = track.back().time;
    return {std::move(c), {}};
}

QJsonObject RouteComparison::toJson() const
{
    QJsonArray wps, legArray;
    for (const WaypointPassage &w : waypoints) {
        wps.append(QJsonObject{{"index", w.index}, {"latitude", w.latitude}, {"longitude", w.longitude},
                               {"radius", jsonNumber(w.radius)}, {"closest", jsonOrNull(w.closest)},
                               {"reached", w.reachedAt ? QJsonValue(when(*w.reachedAt)) : QJsonValue(QStringLiteral("missed"))}});
    }
    for (const LegDeviation &l : legs) {
        legArray.append(QJsonObject{{"from", l.from}, {"to", l.to}, {"samples", l.samples},
                                    {"maxCrossTrack", jsonOrNull(l.maxCrossTrack)}, {"meanCrossTrack", jsonOrNull(l.meanCrossTrack)},
                                    {"maxAltitude", jsonOrNull(l.maxAltitude)}, {"meanAltitude", jsonOrNull(l.meanAltitude)}});
    }
    return QJsonObject{{"route", routeName}, {"vehicle", vehicleName}, {"start", when(start)}, {"end", when(end)},
                       {"waypoints", wps}, {"legs", legArray},
                       {"total", QJsonObject{{"reached", reached}, {"missed", missed},
                                             {"maxCrossTrack", jsonOrNull(maxCrossTrack)}, {"meanCrossTrack", jsonOrNull(meanCrossTrack)},
                                             {"maxAltitude", jsonOrNull(maxAltitude)}, {"meanAltitude", jsonOrNull(meanAltitude)}}}};
}

QString RouteComparison::toText() const
{
    auto m = [](double v) { return std::isfinite(v) ? QString::number(v, 'f', 1) + QStringLiteral(" m") : QStringLiteral("-"); };
    QString out = QObject::tr("%1 flown by %2, %3 to %4\n").arg(routeName, vehicleName, when(start), when(end));
    out += QObject::tr("\nwaypoint  reached                    closest\n");
    for (const WaypointPassage &w : waypoints)
        out += QStringLiteral("%1  %2  %3\n").arg(w.index + 1, 8).arg(w.reachedAt ? when(*w.reachedAt) : QStringLiteral("missed"), -25).arg(m(w.closest));
    out += QObject::tr("\nleg      samples  cross-track max  mean      altitude max  mean\n");
    for (const LegDeviation &l : legs)
        out += QStringLiteral("%1  %2  %3  %4  %5  %6\n").arg(QStringLiteral("%1-%2").arg(l.from + 1).arg(l.to + 1), -7).arg(l.samples, 7)
                   .arg(m(l.maxCrossTrack), 15).arg(m(l.meanCrossTrack), 8).arg(m(l.maxAltitude), 12).arg(m(l.meanAltitude), 8);
    out += QObject::tr("\ntotal: %1 reached, %2 missed; cross-track max %3, mean %4; altitude max %5, mean %6\n")
               .arg(reached).arg(missed).arg(m(maxCrossTrack), m(meanCrossTrack), m(maxAltitude), m(meanAltitude));
    return out;
}

} // namespace sortie::flightlog
