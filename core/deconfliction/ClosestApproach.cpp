#include "ClosestApproach.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sortie::deconfliction {

namespace {

// Below this a speed squared (m²/s²) or a rate (m/s) counts as none: the quantity is constant.
constexpr double kStill = 1e-12;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The open interval of t where a·t² + b·t + c < 0 (a > 0), or an empty one.
TimeInterval belowZero(double a, double b, double c)
{
    const double disc = b * b - 4 * a * c;
    if (!(disc > 0))
        return {kInf, -kInf};
    // The numerically stable pair of roots.
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = q / a, r2 = c / q;
    return {std::min(r1, r2), std::max(r1, r2)};
}

} // namespace

Approach relativeApproach(const LocalState &r, double horizonSeconds, const Separation &s)
{
    const double horizon = std::max(0.0, horizonSeconds);
    // Horizontal distance squared: a·t² + b·t + c.
    const double a = r.vEast * r.vEast + r.vNorth * r.vNorth;
    const double b = 2 * (r.east * r.vEast + r.north * r.vNorth);
    const double c = r.east * r.east + r.north * r.north;
    const auto horizontalAt = [&](double t) { return std::hypot(r.east + r.vEast * t, r.north + r.vNorth * t); };
    const auto verticalAt = [&](double t) { return std::abs(r.up + r.vUp * t); };

    // Where each separation is lost.
    TimeInterval across{-kInf, kInf};
    if (a > kStill)
        across = belowZero(a, b, c - s.horizontal * s.horizontal);
    else if (!(c < s.horizontal * s.horizontal))
        across = {kInf, -kInf};
    TimeInterval height{-kInf, kInf};
    if (std::abs(r.vUp) > kStill) {
        const double t1 = (-s.vertical - r.up) / r.vUp, t2 = (s.vertical - r.up) / r.vUp;
        height = {std::min(t1, t2), std::max(t1, t2)};
    } else if (!(std::abs(r.up) < s.vertical)) {
        height = {kInf, -kInf};
    }
    const double begin = std::max({0.0, across.begin, height.begin});
    const double end = std::min({horizon, across.end, height.end});

    Approach out;
    double lo = 0.0, hi = horizon;
    // A conflict has length, or (a horizon of 0: now only) holds strictly at its one moment.
    if (begin < end || (begin == end && horizontalAt(begin) < s.horizontal && verticalAt(begin) < s.vertical)) {
        out.conflict = TimeInterval{begin, end};
        lo = begin;
        hi = end;
    }
    if (a > kStill)
        out.time = std::clamp(-b / (2 * a), lo, hi);
    else  // the horizontal distance holds: the smallest height difference instead
        out.time = std::abs(r.vUp) > kStill ? std::clamp(-r.up / r.vUp, lo, hi) : lo;
    out.horizontal = horizontalAt(out.time);
    out.vertical = verticalAt(out.time);
    return out;
}

Approach closestApproach(const LocalState &a, const LocalState &b, double horizonSeconds, const Separation &separation)
{
    const LocalState relative{b.east - a.east, b.north - a.north, b.up - a.up, b.vEast - a.vEast, b.vNorth - a.vNorth, b.vUp - a.vUp};
    return relativeApproach(relative, horizonSeconds, separation);
}

} // namespace sortie::deconfliction
