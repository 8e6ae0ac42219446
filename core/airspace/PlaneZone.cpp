#include "PlaneZone.h"

#include <algorithm>
#include <cmath>

namespace sortie::airspace {

namespace {
constexpr double kTiny = 1e-9;  // of a piece: spans shorter than this are touches, not crossings

PlaneXY xy(const PlanePoint &p) { return {p.x, p.y}; }

// Where q(t) = A t² + B t + C <= 0 within [0, 1]: split at the roots, keep the parts whose middle
// is at or below zero. The closed form of a circle or a cone: Boost.Geometry has neither.
std::vector<Span> quadraticAtMostZero(double A, double B, double C)
{
    std::vector<double> cuts{0.0};
    const double scale = std::max({std::abs(A), std::abs(B), std::abs(C), 1e-12});
    if (std::abs(A) < 1e-12 * scale) {
        if (std::abs(B) > 1e-12 * scale)
            cuts.push_back(-C / B);
    } else {
        const double disc = B * B - 4 * A * C;
        if (disc >= 0) {
            const double s = std::sqrt(disc);
            // The stable pair of roots (no cancellation).
            const double q = -0.5 * (B + (B >= 0 ? s : -s));
            cuts.push_back(q / A);
            if (q != 0)
                cuts.push_back(C / q);
        }
    }
    cuts.push_back(1.0);
    for (double &c : cuts)
        c = std::clamp(std::isfinite(c) ? c : 0.0, 0.0, 1.0);
    std::sort(cuts.begin(), cuts.end());
    std::vector<Span> out;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double m = 0.5 * (cuts[i] + cuts[i + 1]);
        if (cuts[i + 1] - cuts[i] > 0 && A * m * m + B * m + C <= 0)
            out.push_back({cuts[i], cuts[i + 1]});
    }
    if (out.empty() && C <= 0 && A + B + C <= 0 && cuts.size() == 2)
        out.push_back({0.0, 1.0});
    return joinSpans(std::move(out));
}

// Where a height linear from h0 to h1 is >= limit (above) or <= limit (!above).
std::optional<Span> linearSide(double h0, double h1, double limit, bool above)
{
    const double d = h1 - h0;
    if (d == 0)
        return (above ? h0 >= limit : h0 <= limit) ? std::optional<Span>(Span{0, 1}) : std::nullopt;
    const double t = std::clamp((limit - h0) / d, 0.0, 1.0);
    Span s = (d > 0) == above ? Span{t, 1.0} : Span{0.0, t};
    if (s.to - s.from <= 0 && !(above ? std::max(h0, h1) >= limit : std::min(h0, h1) <= limit))
        return std::nullopt;
    return s;
}

double lineDistance(const PlaneXY &a, const PlaneXY &b, const PlaneLine &line)
{
    if (bg::equals(a, b))
        return bg::distance(a, line);
    return bg::distance(PlaneSegment(a, b), line);
}
} // namespace

std::vector<Span> joinSpans(std::vector<Span> spans)
{
    std::sort(spans.begin(), spans.end(), [](const Span &x, const Span &y) { return x.from < y.from; });
    std::vector<Span> out;
    for (const Span &s : spans) {
        if (!out.empty() && s.from <= out.back().to + kTiny) {
            out.back().to = std::max(out.back().to, s.to);
            out.back().heightUnknown |= s.heightUnknown;
        } else {
            out.push_back(s);
        }
    }
    return out;
}

std::vector<Span> intersectSpans(const std::vector<Span> &a, const std::vector<Span> &b)
{
    std::vector<Span> out;
    size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const double from = std::max(a[i].from, b[j].from), to = std::min(a[i].to, b[j].to);
        if (to >= from)
            out.push_back({from, to, a[i].heightUnknown || b[j].heightUnknown});
        (a[i].to < b[j].to ? i : j)++;
    }
    return out;
}

std::vector<Span> complementSpans(const std::vector<Span> &spans)
{
    std::vector<Span> out;
    double at = 0.0;
    for (const Span &s : spans) {
        if (s.from > at + kTiny)
            out.push_back({at, s.from});
        at = std::max(at, s.to);
    }
    if (at < 1.0 - kTiny)
        out.push_back({at, 1.0});
    return out;
}

QString shapeProblem(const Zone &zone)
{
    const auto *polygons = std::get_if<ZonePolygons>(&zone.shape);
    if (!polygons)
        return {};
    // In longitude and latitude as plane coordinates: what crosses itself there crosses itself on
    // any small zone's tangent plane too.
    PlaneMultiPolygon geo;
    for (const ZonePolygon &part : polygons->parts) {
        PlanePolygon poly;
        for (size_t r = 0; r < part.rings.size(); ++r) {
            auto &ring = r == 0 ? poly.outer() : (poly.inners().emplace_back(), poly.inners().back());
            for (const GeoPoint &g : part.rings[r])
                ring.push_back({g.longitude, g.latitude});
        }
        geo.push_back(std::move(poly));
    }
    bg::correct(geo);
    std::string why;
    if (bg::is_valid(geo, why))
        return {};
    return QStringLiteral("the polygon cannot be checked: %1").arg(QString::fromStdString(why));
}

PlaneZone::PlaneZone(const Zone &zone, int index, const LocalTangentPlane &plane) : m_zone(&zone), m_index(index)
{
    if (const auto *polygons = std::get_if<ZonePolygons>(&zone.shape)) {
        for (const ZonePolygon &part : polygons->parts) {
            PlanePolygon poly;
            for (size_t r = 0; r < part.rings.size(); ++r) {
                auto &ring = r == 0 ? poly.outer() : (poly.inners().emplace_back(), poly.inners().back());
                for (const GeoPoint &g : part.rings[r])
                    ring.push_back(xy(plane.project(g)));
            }
            m_polygons.push_back(std::move(poly));
        }
        bg::correct(m_polygons);
        m_envelope = bg::return_envelope<PlaneBox>(m_polygons);
        return;
    }
    m_round = true;
    if (const auto *circle = std::get_if<ZoneCircle>(&zone.shape)) {
        m_center = xy(plane.project(circle->center));
        m_bottomRadius = m_topRadius = circle->radius;
    } else if (const auto *cone = std::get_if<ZoneConeFrustum>(&zone.shape)) {
        m_center = xy(plane.project(cone->center));
        m_bottomRadius = cone->bottomRadius;
        m_topRadius = cone->topRadius;
        m_cone = zone.ceiling.has_value();
    }
    const double r = std::max(m_bottomRadius, m_topRadius);
    m_envelope = PlaneBox({m_center.x() - r, m_center.y() - r}, {m_center.x() + r, m_center.y() + r});
}

std::vector<Span> PlaneZone::overPolygons(const PlaneXY &a, const PlaneXY &b) const
{
    if (bg::equals(a, b))
        return bg::covered_by(a, m_polygons) ? std::vector<Span>{{0, 1}} : std::vector<Span>{};
    const PlaneBox box({std::min(a.x(), b.x()), std::min(a.y(), b.y())}, {std::max(a.x(), b.x()), std::max(a.y(), b.y())});
    if (bg::disjoint(box, m_envelope))
        return {};
    const PlaneLine line{a, b};
    bg::model::multi_linestring<PlaneLine> parts;
    try {
        bg::intersection(line, m_polygons, parts);
    } catch (const bg::exception &) {
        return {{0, 1}};  // a shape Boost.Geometry refuses (the readers leave them out): counted as inside, to be safe
    }
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), len2 = dx * dx + dy * dy;
    std::vector<Span> out;
    for (const PlaneLine &part : parts) {
        double lo = 1.0, hi = 0.0;
        for (const PlaneXY &p : part) {
            const double t = std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2, 0.0, 1.0);
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        if (hi - lo > kTiny)
            out.push_back({lo, hi});
    }
    return joinSpans(std::move(out));
}

std::vector<Span> PlaneZone::betweenLimits(const FlownPoint &a, const FlownPoint &b) const
{
    Span all{0.0, 1.0};
    std::vector<Span> out{all};
    for (const auto &[limit, above] : {std::pair{&m_zone->floor, true}, std::pair{&m_zone->ceiling, false}}) {
        if (!*limit)
            continue;
        const double h0 = a.in((*limit)->reference), h1 = b.in((*limit)->reference);
        if (std::isnan(h0) || std::isnan(h1)) {
            for (Span &s : out)
                s.heightUnknown = true;
            continue;
        }
        const std::optional<Span> side = linearSide(h0, h1, (*limit)->metres, above);
        if (!side)
            return {};
        out = intersectSpans(out, {*side});
    }
    return out;
}

std::vector<Span> PlaneZone::insideRound(const FlownPoint &a, const FlownPoint &b) const
{
    const double ex = a.at.x - m_center.x(), ey = a.at.y - m_center.y();
    const double dx = b.at.x - a.at.x, dy = b.at.y - a.at.y;
    double r0 = std::max(m_bottomRadius, m_topRadius), r1 = 0.0;
    bool unknown = false;
    if (m_cone && m_zone->floor && m_bottomRadius != m_topRadius) {
        const HeightReference ref = m_zone->floor->reference;
        const double floor = m_zone->floor->metres;
        const double ceiling = m_zone->ceiling->reference == ref ? m_zone->ceiling->metres : std::numeric_limits<double>::quiet_NaN();
        const double h0 = a.in(ref), h1 = b.in(ref);
        if (std::isnan(h0) || std::isnan(h1) || std::isnan(ceiling)) {
            unknown = true;  // the widest circle stands for the cone
        } else {
            const auto radius = [&](double h) { return m_bottomRadius + (m_topRadius - m_bottomRadius) * (h - floor) / (ceiling - floor); };
            r0 = radius(h0);
            r1 = radius(h1) - r0;
        }
    }
    std::vector<Span> out = quadraticAtMostZero(dx * dx + dy * dy - r1 * r1, 2 * (ex * dx + ey * dy - r0 * r1), ex * ex + ey * ey - r0 * r0);
    for (Span &s : out)
        s.heightUnknown = unknown;
    return out;
}

std::vector<Span> PlaneZone::inside(const FlownPoint &a, const FlownPoint &b) const
{
    std::vector<Span> shadow = m_round ? insideRound(a, b) : overPolygons(xy(a.at), xy(b.at));
    if (shadow.empty())
        return {};
    return intersectSpans(shadow, betweenLimits(a, b));
}

double PlaneZone::clearance(const FlownPoint &a, const FlownPoint &b) const
{
    const PlaneXY pa = xy(a.at), pb = xy(b.at);
    const bool point = bg::equals(pa, pb);
    // The piece's height range in each limit's reference; unknown heights are taken as near.
    double below = 0.0, above = 0.0, roomUnder = 1e18, roomOver = 1e18;
    if (m_zone->floor) {
        const double h0 = a.in(m_zone->floor->reference), h1 = b.in(m_zone->floor->reference);
        if (!std::isnan(h0) && !std::isnan(h1)) {
            below = std::max(0.0, m_zone->floor->metres - std::max(h0, h1));
            roomUnder = std::min(h0, h1) - m_zone->floor->metres;
        }
    }
    if (m_zone->ceiling) {
        const double h0 = a.in(m_zone->ceiling->reference), h1 = b.in(m_zone->ceiling->reference);
        if (!std::isnan(h0) && !std::isnan(h1)) {
            above = std::max(0.0, std::min(h0, h1) - m_zone->ceiling->metres);
            roomOver = m_zone->ceiling->metres - std::max(h0, h1);
        }
    }
    const double radius = std::max(m_bottomRadius, m_topRadius);
    if (m_zone->kind == ZoneKind::Exclusion) {
        double horizontal = 0.0;
        if (m_round)
            horizontal = std::max(0.0, (point ? bg::distance(pa, m_center) : bg::distance(PlaneSegment(pa, pb), m_center)) - radius);
        else
            horizontal = point ? bg::distance(pa, m_polygons) : bg::distance(PlaneSegment(pa, pb), m_polygons);
        return std::max({horizontal, below, above});
    }
    // Inclusion: the room to the edge, sideways, under the ceiling and over the floor.
    double edge = 1e18;
    if (m_round) {
        edge = radius - std::max(bg::distance(pa, m_center), bg::distance(pb, m_center));
    } else {
        for (const PlanePolygon &poly : m_polygons) {
            edge = std::min(edge, lineDistance(pa, pb, PlaneLine(poly.outer().begin(), poly.outer().end())));
            for (const auto &inner : poly.inners())
                edge = std::min(edge, lineDistance(pa, pb, PlaneLine(inner.begin(), inner.end())));
        }
    }
    return std::min({edge, roomUnder, roomOver});
}

} // namespace sortie::airspace
