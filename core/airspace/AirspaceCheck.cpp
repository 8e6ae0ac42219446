#include "AirspaceCheck.h"

#include "PlaneZone.h"

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace sortie::airspace {

namespace bgi = boost::geometry::index;

namespace {
constexpr double kMetresPerDegree = 111320.0;
// A frame covers the route's box and this much around it, so dragging a waypoint keeps the frame.
constexpr double kFrameMargin = 2000.0;
constexpr double kSpanTolerance = 1e-6;  // metres: stretches this close are one

using GeoXY = bg::model::d2::point_xy<double>;  // longitude, latitude
using GeoRect = bg::model::box<GeoXY>;

GeoRect expanded(const mission::GeoBox &b, double metres)
{
    const double dLat = metres / kMetresPerDegree;
    const double cosLat = std::cos(std::max(std::abs(b.south), std::abs(b.north)) * M_PI / 180.0);
    const double dLon = cosLat > 0.01 ? dLat / cosLat : 360.0;
    return GeoRect({std::max(-180.0, b.west - dLon), std::max(-90.0, b.south - dLat)},
                   {std::min(180.0, b.east + dLon), std::min(90.0, b.north + dLat)});
}

mission::GeoBox boxOf(const Zone &z)
{
    mission::GeoBox b;
    const auto add = [&](const GeoPoint &p) {
        if (b.empty)
            b = {p.latitude, p.longitude, p.latitude, p.longitude, false};
        b.south = std::min(b.south, p.latitude);
        b.north = std::max(b.north, p.latitude);
        b.west = std::min(b.west, p.longitude);
        b.east = std::max(b.east, p.longitude);
    };
    double radius = 0.0;
    if (const auto *polygons = std::get_if<ZonePolygons>(&z.shape)) {
        for (const ZonePolygon &part : polygons->parts)
            if (!part.rings.empty())
                for (const GeoPoint &p : part.rings.front())
                    add(p);
    } else if (const auto *c = std::get_if<ZoneCircle>(&z.shape)) {
        add(c->center);
        radius = c->radius;
    } else if (const auto *cone = std::get_if<ZoneConeFrustum>(&z.shape)) {
        add(cone->center);
        radius = std::max(cone->bottomRadius, cone->topRadius);
    }
    if (radius > 0) {
        const GeoRect r = expanded(b, radius);
        b = {r.min_corner().y(), r.min_corner().x(), r.max_corner().y(), r.max_corner().x(), false};
    }
    return b;
}

} // namespace

QString violationKindName(ViolationKind kind)
{
    return kind == ViolationKind::InsideExclusion ? QStringLiteral("inside-exclusion") : QStringLiteral("outside-inclusion");
}

struct ZoneSet::Index
{
    bgi::rtree<std::pair<GeoRect, int>, bgi::rstar<16>> tree;
};

ZoneSet::ZoneSet(std::vector<Zone> zones) : m_zones(std::move(zones)), m_index(std::make_unique<Index>())
{
    std::vector<std::pair<GeoRect, int>> boxes;
    for (size_t i = 0; i < m_zones.size(); ++i) {
        if (!m_zones[i].active)
            continue;
        if (m_zones[i].kind == ZoneKind::Inclusion)
            m_inclusions.push_back(int(i));
        const mission::GeoBox b = boxOf(m_zones[i]);
        if (!b.empty)
            boxes.emplace_back(GeoRect({b.west, b.south}, {b.east, b.north}), int(i));
    }
    m_index->tree = decltype(m_index->tree)(boxes.begin(), boxes.end());  // packed: built once, queried often
}

ZoneSet::~ZoneSet() = default;

int ZoneSet::activeCount() const
{
    return int(std::count_if(m_zones.begin(), m_zones.end(), [](const Zone &z) { return z.active; }));
}

std::vector<int> ZoneSet::near(const mission::GeoBox &box) const
{
    std::vector<int> out;
    if (box.empty)
        return out;
    for (const auto &hit : m_index->tree | bgi::adaptors::queried(bgi::intersects(GeoRect({box.west, box.south}, {box.east, box.north}))))
        out.push_back(hit.second);
    std::sort(out.begin(), out.end());
    return out;
}

// The zones near a route on its tangent plane, with a plane R-tree over their envelopes.
struct AirspaceChecker::Frame
{
    GeoPoint origin;
    GeoRect covered;
    std::vector<PlaneZone> zones;
    bgi::rtree<std::pair<PlaneBox, int>, bgi::rstar<16>> tree;  // int: index into zones
};

// What one leg found, distances from the leg's start (so a leg found again elsewhere in the route
// keeps them).
struct AirspaceChecker::LegFindings
{
    struct Stretch
    {
        int zone;
        ViolationKind kind;
        double from, to;
        bool unknown;
    };
    std::vector<Stretch> violations;
    std::vector<std::pair<int, double>> warnings;  // zone, clearance
};

AirspaceChecker::AirspaceChecker(std::shared_ptr<const ZoneSet> zones, double buffer)
    : m_zones(std::move(zones)), m_buffer(std::max(0.0, buffer))
{
    setWindow(std::nullopt);
}

AirspaceChecker::~AirspaceChecker() = default;

void AirspaceChecker::setWindow(std::optional<ed::TimeWindow> window)
{
    m_window = std::move(window);
    std::vector<char> counted(m_zones->zones().size());
    for (size_t i = 0; i < counted.size(); ++i) {
        const Zone &z = m_zones->zones()[i];
        counted[i] = z.active && (!z.geoZone || !m_window || z.geoZone->appliesDuring(*m_window));
    }
    if (counted == m_counted)
        return;  // the same zones count: what each leg found stands
    m_counted = std::move(counted);
    m_frame.reset();
    m_lastLegs.clear();
    m_lastFindings.clear();
}

const AirspaceChecker::Frame &AirspaceChecker::frameFor(const FlownPath &path)
{
    const GeoRect wanted = expanded(path.bounds, m_buffer);
    if (m_frame && m_frame->origin == path.plane.origin() && bg::covered_by(wanted, m_frame->covered))
        return *m_frame;
    auto frame = std::make_unique<Frame>();
    frame->origin = path.plane.origin();
    frame->covered = expanded(path.bounds, m_buffer + kFrameMargin);
    const mission::GeoBox cover{frame->covered.min_corner().y(), frame->covered.min_corner().x(), frame->covered.max_corner().y(),
                                frame->covered.max_corner().x(), path.bounds.empty};
    std::vector<std::pair<PlaneBox, int>> boxes;
    for (int z : m_zones->near(cover)) {
        if (!counts(z))
            continue;
        frame->zones.emplace_back(m_zones->zones()[size_t(z)], z, path.plane);
        boxes.emplace_back(frame->zones.back().envelope(), int(frame->zones.size()) - 1);
    }
    frame->tree = decltype(frame->tree)(boxes.begin(), boxes.end());
    m_frame = std::move(frame);
    return *m_frame;
}

AirspaceChecker::LegFindings AirspaceChecker::checkLeg(const FlownLeg &leg, const Frame &frame) const
{
    LegFindings out;
    std::map<int, std::vector<LegFindings::Stretch>> inside;  // per zone, in order
    std::vector<LegFindings::Stretch> outside;
    std::map<int, double> closest;
    const bool fenced = !m_zones->activeInclusions().empty();
    std::vector<int> candidates;
    const auto add = [](std::vector<LegFindings::Stretch> &list, LegFindings::Stretch s) {
        if (!list.empty() && s.from <= list.back().to + kSpanTolerance) {
            list.back().to = std::max(list.back().to, s.to);
            list.back().unknown |= s.unknown;
        } else {
            list.push_back(s);
        }
    };
    for (size_t i = 0; i + 1 < leg.points.size(); ++i) {
        const FlownPoint &a = leg.points[i], &b = leg.points[i + 1];
        const auto along = [&](double t) { return a.along + t * (b.along - a.along); };
        const PlaneBox box({std::min(a.at.x, b.at.x) - m_buffer, std::min(a.at.y, b.at.y) - m_buffer},
                           {std::max(a.at.x, b.at.x) + m_buffer, std::max(a.at.y, b.at.y) + m_buffer});
        candidates.clear();
        for (const auto &hit : frame.tree | bgi::adaptors::queried(bgi::intersects(box)))
            candidates.push_back(hit.second);
        std::sort(candidates.begin(), candidates.end());
        std::vector<Span> permitted;  // where the piece is inside some inclusion zone
        int lastInclusion = -1;
        for (int c : candidates) {
            const PlaneZone &z = frame.zones[size_t(c)];
            std::vector<Span> spans = z.inside(a, b);
            if (z.zone().kind == ZoneKind::Exclusion) {
                for (const Span &s : spans)
                    add(inside[z.index()], {z.index(), ViolationKind::InsideExclusion, along(s.from), along(s.to), s.heightUnknown});
            } else {
                if (!spans.empty())
                    lastInclusion = z.index();
                permitted.insert(permitted.end(), spans.begin(), spans.end());
            }
            if (!spans.empty() && z.zone().kind == ZoneKind::Exclusion)
                continue;
            if (z.zone().kind == ZoneKind::Inclusion && spans.empty())
                continue;  // its edge matters only to a piece inside it
            if (z.zone().geoZone && z.zone().geoZone->restriction == ed::Restriction::NoRestriction)
                continue;  // nothing to keep clear of
            const double c2 = z.clearance(a, b);
            if (std::isfinite(c2) && c2 <= m_buffer) {
                auto [it, fresh] = closest.emplace(z.index(), c2);
                if (!fresh)
                    it->second = std::min(it->second, c2);
            }
        }
        if (!fenced)
            continue;
        // Where the height in an inclusion zone's reference is unknown, the piece may be above its
        // ceiling: it counts as outside (to be safe) and says so.
        std::vector<Span> known, unknown;
        for (const Span &s : permitted)
            (s.heightUnknown ? unknown : known).push_back(s);
        const std::vector<Span> maybe = joinSpans(std::move(unknown));
        for (const Span &s : complementSpans(joinSpans(std::move(known))))
            add(outside, {lastInclusion >= 0 ? lastInclusion : m_zones->activeInclusions().front(), ViolationKind::OutsideInclusion,
                          along(s.from), along(s.to), !intersectSpans({s}, maybe).empty()});
    }
    for (auto &[zone, list] : inside)
        out.violations.insert(out.violations.end(), list.begin(), list.end());
    out.violations.insert(out.violations.end(), outside.begin(), outside.end());
    std::sort(out.violations.begin(), out.violations.end(), [](const auto &x, const auto &y) { return x.from < y.from; });
    for (const auto &[zone, c] : closest) {
        const bool crossed = std::any_of(out.violations.begin(), out.violations.end(), [&, zone = zone](const auto &v) {
            return v.zone == zone || (v.kind == ViolationKind::OutsideInclusion && m_zones->zones()[size_t(zone)].kind == ZoneKind::Inclusion);
        });
        if (!crossed)
            out.warnings.emplace_back(zone, c);
    }
    return out;
}

AirspaceReport AirspaceChecker::check(const FlownPath &path)
{
    AirspaceReport report;
    for (size_t i = 0; i < m_counted.size(); ++i) {
        if (m_counted[i])
            ++report.zones;
        else if (m_zones->zones()[i].active)
            ++report.outsideWindow;
    }
    m_legsChecked = 0;
    if (path.legs.empty())
        return report;
    const Frame &frame = frameFor(path);
    std::vector<LegFindings> findings(path.legs.size());
    long shift = 0;  // the previous path's leg k + shift is this one's leg k, while they match
    for (size_t k = 0; k < path.legs.size(); ++k) {
        const FlownLeg &leg = path.legs[k];
        const LegFindings *before = nullptr;
        for (const long d : {shift, shift + 1, shift - 1}) {
            const long j = long(k) + d;
            if (j >= 0 && size_t(j) < m_lastLegs.size() && m_lastLegs[size_t(j)].sameShape(leg)) {
                before = &m_lastFindings[size_t(j)];
                shift = d;
                break;
            }
        }
        if (before) {
            findings[k] = *before;
        } else {
            findings[k] = checkLeg(leg, frame);
            ++m_legsChecked;
        }
        for (const auto &v : findings[k].violations)
            report.violations.push_back({v.zone, v.kind, leg.leg, leg.row, leg.start + v.from, leg.start + v.to, v.unknown});
        for (const auto &[zone, c] : findings[k].warnings)
            report.warnings.push_back({zone, leg.leg, leg.row, c});
    }
    m_lastLegs = path.legs;  // copy-assigned: the legs' storage is reused
    m_lastFindings = std::move(findings);
    return report;
}

AirspaceReport checkAirspace(const FlownPath &path, const std::vector<Zone> &zones, double buffer, const std::optional<ed::TimeWindow> &window)
{
    AirspaceChecker checker(std::make_shared<const ZoneSet>(zones), buffer);
    checker.setWindow(window);
    return checker.check(path);
}

} // namespace sortie::airspace
