#include "ConflictSearch.h"

#include <QLoggingCategory>

#include <algorithm>

Q_LOGGING_CATEGORY(lcDeconfliction, "sortie.deconfliction")

namespace sortie::deconfliction {

namespace {

// Windows of the same two flights this close (seconds) are one conflict: piece ends meet exactly,
// up to rounding.
constexpr double kTouch = 1e-6;

// A piece pair's conflict window and its closest approach.
struct Window
{
    int first = 0, second = 0;
    TimeInterval interval;
    double time = 0.0, horizontal = 0.0, vertical = 0.0;
    const MotionPiece *a = nullptr, *b = nullptr;  // a's flight is `first`
};

bool boxesMeet(const MotionPiece &a, const MotionPiece &b, const Separation &s)
{
    return a.minEast - b.maxEast < s.horizontal && b.minEast - a.maxEast < s.horizontal && a.minNorth - b.maxNorth < s.horizontal
        && b.minNorth - a.maxNorth < s.horizontal && a.minUp - b.maxUp < s.vertical && b.minUp - a.maxUp < s.vertical;
}

mission::GeoPoint centreOf(const std::vector<ScheduledFlight> &flights)
{
    std::vector<mission::GeoPoint> points;
    for (const ScheduledFlight &f : flights)
        for (const mission::TimedLeg &l : f.timeline.legs())
            points.push_back(l.from);
    return points.empty() ? mission::GeoPoint{} : mission::LocalTangentPlane::centroidOf(points);
}

// Closer across wins; the same distance (to a millimetre) goes to the smaller height difference.
bool closer(const Window &w, double horizontal, double vertical)
{
    if (std::abs(w.horizontal - horizontal) > 1e-3)
        return w.horizontal < horizontal;
    return w.vertical < vertical - 1e-3;
}

ConflictSide sideAt(const MotionPiece &p, double t, const mission::LocalTangentPlane &plane)
{
    const LocalState s = p.stateAt(t);
    return {p.leg, plane.unproject({s.east, s.north}), s.up};
}

} // namespace

ConflictReport findConflicts(const std::vector<ScheduledFlight> &flights, const ConflictQuery &query)
{
    ConflictReport report;
    const int n = int(flights.size());
    const bool one = query.against.has_value();
    if (one && !(*query.against >= 0 && *query.against < n))
        return report;  // no such flight: no pairs
    report.pairs = one ? n - 1 : n * (n - 1) / 2;
    const mission::LocalTangentPlane plane(centreOf(flights));

    std::vector<MotionPiece> pieces;
    for (int i = 0; i < n; ++i) {
        const std::vector<MotionPiece> cut = motionPieces(flights[size_t(i)], i, plane);
        pieces.insert(pieces.end(), cut.begin(), cut.end());
    }
    report.pieces = (long long)pieces.size();
    std::sort(pieces.begin(), pieces.end(), [](const MotionPiece &a, const MotionPiece &b) { return a.begin < b.begin; });

    // The sweep: pieces in order of their start; `active` holds those still in the air. A flight's
    // pieces follow one another, so at most one per flight is active: the work is pieces × flights.
    const Separation &sep = query.separation;
    std::vector<Window> windows;
    std::vector<const MotionPiece *> active;
    for (const MotionPiece &p : pieces) {
        std::erase_if(active, [&](const MotionPiece *q) { return q->end <= p.begin; });
        for (const MotionPiece *q : active) {
            if (q->flight == p.flight || (one && q->flight != *query.against && p.flight != *query.against))
                continue;
            ++report.overlapping;
            if (!boxesMeet(p, *q, sep))
                continue;
            ++report.solved;
            const MotionPiece &a = q->flight < p.flight ? *q : p, &b = q->flight < p.flight ? p : *q;
            const double t0 = std::max(a.begin, b.begin), t1 = std::min(a.end, b.end);
            if (!(t1 > t0))
                continue;
            const LocalState sa = a.stateAt(t0), sb = b.stateAt(t0);
            const Approach found = closestApproach(sa, sb, t1 - t0, sep);
            if (!found.conflict || !(found.conflict->end > found.conflict->begin))
                continue;
            windows.push_back({a.flight, b.flight, {t0 + found.conflict->begin, t0 + found.conflict->end}, t0 + found.time,
                               found.horizontal, found.vertical, &a, &b});
        }
        active.push_back(&p);
    }

    // Merge the windows of each pair of flights that touch into conflicts.
    std::sort(windows.begin(), windows.end(), [](const Window &x, const Window &y) {
        return std::tie(x.first, x.second, x.interval.begin) < std::tie(y.first, y.second, y.interval.begin);
    });
    for (size_t i = 0; i < windows.size();) {
        Window best = windows[i];
        TimeInterval span = best.interval;
        size_t j = i + 1;
        for (; j < windows.size() && windows[j].first == best.first && windows[j].second == best.second
               && windows[j].interval.begin <= span.end + kTouch;
             ++j) {
            span.end = std::max(span.end, windows[j].interval.end);
            if (closer(windows[j], best.horizontal, best.vertical))
                best = windows[j];
        }
        Conflict c;
        c.first = best.first;
        c.second = best.second;
        c.interval = span;
        c.time = best.time;
        c.horizontal = best.horizontal;
        c.vertical = best.vertical;
        c.firstAt = sideAt(*best.a, best.time, plane);
        c.secondAt = sideAt(*best.b, best.time, plane);
        report.conflicts.push_back(c);
        i = j;
    }
    qCDebug(lcDeconfliction) << flights.size() << "flights," << report.pieces << "pieces," << report.overlapping << "overlapping in time,"
                             << report.solved << "solved," << report.conflicts.size() << "conflicts";
    return report;
}

} // namespace sortie::deconfliction
