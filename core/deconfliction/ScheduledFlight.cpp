#include "ScheduledFlight.h"

#include <algorithm>

namespace sortie::deconfliction {

using mission::TimedLeg;

namespace {

struct Point3
{
    double east = 0.0, north = 0.0, up = 0.0;
};

Point3 lerp(const Point3 &a, const Point3 &b, double f)
{
    return {a.east + (b.east - a.east) * f, a.north + (b.north - a.north) * f, a.up + (b.up - a.up) * f};
}

// Appends the pieces of one flight, keeping the clock running.
class PieceCutter
{
public:
    PieceCutter(int flight, std::vector<MotionPiece> &out) : m_flight(flight), m_out(out) {}

    // A straight line from `from` to `to` over `seconds` of the timeline, starting at its second t0.
    void add(int leg, double t0, double seconds, const Point3 &from, const Point3 &to)
    {
        if (!(seconds > 0))
            return;
        MotionPiece p;
        p.flight = m_flight;
        p.leg = leg;
        p.begin = t0;
        p.end = t0 + seconds;
        p.at = {from.east, from.north, from.up, (to.east - from.east) / seconds, (to.north - from.north) / seconds,
                (to.up - from.up) / seconds};
        m_out.push_back(p);
    }

private:
    int m_flight;
    std::vector<MotionPiece> &m_out;
};

void cutLeg(const TimedLeg &l, const mission::LocalTangentPlane &plane, PieceCutter &cut)
{
    const mission::PlanePoint a = plane.project(l.from), b = l.distance > 0 ? plane.project(l.to) : a;
    const Point3 ground{a.x, a.y, l.fromAltitude - l.takeoffClimb};
    const Point3 from{a.x, a.y, l.fromAltitude};
    const Point3 to{b.x, b.y, l.fromAltitude + l.heightChange};
    const Point3 arrived{b.x, b.y, l.toAltitude};
    double t = l.start;
    cut.add(l.leg, t, l.takeoffSeconds, ground, from);
    t += l.takeoffSeconds;
    cut.add(l.leg, t, l.departHoldSeconds, from, from);
    t += l.departHoldSeconds;
    if (l.verticalSeconds > 0 && l.verticalSeconds < l.moveSeconds) {
        // The height is reached part way, the horizontal progress even over the whole move.
        const double f = l.verticalSeconds / l.moveSeconds;
        Point3 reached = lerp(from, to, f);
        reached.up = to.up;
        cut.add(l.leg, t, l.verticalSeconds, from, reached);
        cut.add(l.leg, t + l.verticalSeconds, l.moveSeconds - l.verticalSeconds, reached, to);
    } else {
        cut.add(l.leg, t, l.moveSeconds, from, to);
    }
    t += l.moveSeconds;
    cut.add(l.leg, t, l.arriveHoldSeconds, arrived, arrived);
    t += l.arriveHoldSeconds;
    cut.add(l.leg, t, l.landingSeconds, arrived, {b.x, b.y, l.toAltitude - l.landingDescent});
}

void boxIn(MotionPiece &p)
{
    const LocalState e = p.stateAt(p.end);
    p.minEast = std::min(p.at.east, e.east);
    p.maxEast = std::max(p.at.east, e.east);
    p.minNorth = std::min(p.at.north, e.north);
    p.maxNorth = std::max(p.at.north, e.north);
    p.minUp = std::min(p.at.up, e.up);
    p.maxUp = std::max(p.at.up, e.up);
}

} // namespace

LocalState MotionPiece::stateAt(double t) const
{
    const double dt = t - begin;
    return {at.east + at.vEast * dt, at.north + at.vNorth * dt, at.up + at.vUp * dt, at.vEast, at.vNorth, at.vUp};
}

std::optional<double> flownAlongLeg(const mission::RouteTimeline &timeline, int legIndex, const mission::GeoPoint &position)
{
    if (legIndex < 0 || legIndex >= int(timeline.legs().size()))
        return std::nullopt;
    const TimedLeg &l = timeline.legs()[size_t(legIndex)];
    double along = 0.0;
    if (l.distance > 0) {
        const mission::LocalTangentPlane plane(l.from);
        const mission::PlanePoint to = plane.project(l.to), at = plane.project(position);
        const double length2 = to.x * to.x + to.y * to.y;
        along = length2 > 0 ? std::clamp((at.x * to.x + at.y * to.y) / length2, 0.0, 1.0) : 0.0;
    }
    return l.start + l.takeoffSeconds + l.departHoldSeconds + along * l.moveSeconds;
}

std::vector<MotionPiece> motionPieces(const ScheduledFlight &flight, int flightIndex, const mission::LocalTangentPlane &plane)
{
    std::vector<MotionPiece> pieces;
    const std::vector<TimedLeg> &legs = flight.timeline.legs();
    pieces.reserve(legs.size() + 2);
    PieceCutter cut(flightIndex, pieces);
    // Legs wholly flown already are skipped before they are cut.
    const int first = std::max(0, flight.timeline.legAt(flight.flown));
    for (size_t i = size_t(first); i < legs.size(); ++i)
        cutLeg(legs[i], plane, cut);

    // Drop what is flown, trim the piece the vehicle is on, and start it from where the vehicle is.
    const auto flownEnd = std::find_if(pieces.begin(), pieces.end(), [&](const MotionPiece &p) { return p.end > flight.flown; });
    pieces.erase(pieces.begin(), flownEnd);
    if (!pieces.empty() && (pieces.front().begin < flight.flown || flight.now)) {
        MotionPiece &p = pieces.front();
        const double t0 = std::max(p.begin, flight.flown);
        const LocalState end = p.stateAt(p.end);
        LocalState from = p.stateAt(t0);
        if (flight.now) {
            const mission::PlanePoint here = plane.project(flight.now->position);
            from = {here.x, here.y, flight.now->altitude};
        }
        const double seconds = p.end - t0;
        p.begin = t0;
        p.at = {from.east, from.north, from.up, (end.east - from.east) / seconds, (end.north - from.north) / seconds,
                (end.up - from.up) / seconds};
    }
    for (MotionPiece &p : pieces) {
        const double shift = flight.start - flight.flown;
        p.begin += shift;
        p.end += shift;
        boxIn(p);
    }
    return pieces;
}

} // namespace sortie::deconfliction
