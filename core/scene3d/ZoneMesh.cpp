#include "ZoneMesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::scene3d {

using mission::PlanePoint;

namespace {

double signedArea(const std::vector<PlanePoint> &ring)
{
    double a = 0.0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const PlanePoint &p = ring[i], &q = ring[(i + 1) % n];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2.0;
}

double cross(const PlanePoint &o, const PlanePoint &a, const PlanePoint &b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool inTriangle(const PlanePoint &p, const PlanePoint &a, const PlanePoint &b, const PlanePoint &c)
{
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

// Edges cut so no piece is longer than `step` (the AGL limits then follow the ground).
std::vector<PlanePoint> densify(const std::vector<PlanePoint> &ring, double step)
{
    std::vector<PlanePoint> out;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const PlanePoint &p = ring[i], &q = ring[(i + 1) % n];
        const int pieces = std::max(1, int(std::ceil(std::hypot(q.x - p.x, q.y - p.y) / step)));
        for (int k = 0; k < pieces; ++k) {
            const double f = double(k) / pieces;
            out.push_back({p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f});
        }
    }
    return out;
}

} // namespace

std::vector<std::uint32_t> triangulate(const std::vector<PlanePoint> &ring)
{
    std::vector<std::uint32_t> out;
    const std::size_t n = ring.size();
    if (n < 3)
        return out;
    std::vector<std::uint32_t> left(n);
    for (std::size_t i = 0; i < n; ++i)
        left[i] = std::uint32_t(i);
    if (signedArea(ring) < 0)
        std::reverse(left.begin(), left.end());
    std::size_t guard = 0;
    while (left.size() > 3 && guard < n * n) {
        ++guard;
        bool clipped = false;
        for (std::size_t i = 0; i < left.size(); ++i) {
            const std::uint32_t ia = left[(i + left.size() - 1) % left.size()], ib = left[i], ic = left[(i + 1) % left.size()];
            const PlanePoint &a = ring[ia], &b = ring[ib], &c = ring[ic];
            if (cross(a, b, c) <= 0)
                continue;  // reflex (or flat): not an ear
            bool empty = true;
            for (std::uint32_t j : left)
                if (j != ia && j != ib && j != ic && inTriangle(ring[j], a, b, c)) {
                    empty = false;
                    break;
                }
            if (!empty)
                continue;
            out.insert(out.end(), {ia, ib, ic});
            left.erase(left.begin() + std::ptrdiff_t(i));
            clipped = true;
            break;
        }
        if (!clipped)
            break;  // not simple: what is left stays open
    }
    if (left.size() == 3)
        out.insert(out.end(), {left[0], left[1], left[2]});
    return out;
}

ZoneMesh buildZone(const airspace::Zone &zone, const SceneFrame &frame, const HeightGrid &grid, const ZoneStyle &style)
{
    ZoneMesh out;
    out.hasFloor = zone.floor.has_value();
    out.hasLid = zone.ceiling.has_value();
    const QVector4D colour = rgba(style.colour, style.alpha);
    const double fallbackGround = grid.lowest().value_or(frame.baseHeight());
    const double home = style.homeGround.value_or(frame.baseHeight());
    const auto ground = [&](const PlanePoint &p) { return grid.heightAt(p.x, p.y).value_or(fallbackGround); };
    const auto limitAt = [&](const std::optional<airspace::HeightLimit> &limit, const PlanePoint &p, double otherwise) {
        if (!limit)
            return otherwise;
        switch (limit->reference) {
        case terrain::HeightReference::Amsl: return limit->metres;
        case terrain::HeightReference::AboveTerrain: return ground(p) + limit->metres;
        case terrain::HeightReference::AboveHome: return home + limit->metres;
        }
        return limit->metres;
    };
    const auto floorAt = [&](const PlanePoint &p) { return limitAt(zone.floor, p, ground(p)); };
    const auto ceilingAt = [&](const PlanePoint &p) { return std::max(limitAt(zone.ceiling, p, style.sceneTop), floorAt(p)); };
    const double step = std::max(grid.spacing * 2.0, 10.0);

    // radius at a height fraction (0 floor, 1 ceiling), and the walls of one ring
    const auto walls = [&](const std::vector<PlanePoint> &ring, const std::vector<PlanePoint> *topRing, bool inward) {
        const std::size_t n = ring.size();
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            const PlanePoint &p = ring[i], &q = ring[j];
            const PlanePoint &pt = topRing ? (*topRing)[i] : p, &qt = topRing ? (*topRing)[j] : q;
            QVector3D normal(float(q.y - p.y), 0.0f, float(q.x - p.x));  // outward for a counter-clockwise ring (z south)
            normal.normalize();
            if (inward)
                normal = -normal;
            const std::uint32_t a = out.mesh.addVertex(frame.toScene(p.x, p.y, floorAt(p)), normal, colour);
            const std::uint32_t b = out.mesh.addVertex(frame.toScene(q.x, q.y, floorAt(q)), normal, colour);
            const std::uint32_t c = out.mesh.addVertex(frame.toScene(qt.x, qt.y, ceilingAt(q)), normal, colour);
            const std::uint32_t d = out.mesh.addVertex(frame.toScene(pt.x, pt.y, ceilingAt(p)), normal, colour);
            out.mesh.addTriangle(a, b, c);
            out.mesh.addTriangle(a, c, d);
        }
    };
    const auto cap = [&](const std::vector<PlanePoint> &ring, bool lid) {
        const std::vector<std::uint32_t> tris = triangulate(ring);
        const QVector3D normal(0.0f, lid ? 1.0f : -1.0f, 0.0f);
        const std::uint32_t first = out.mesh.vertexCount();
        for (const PlanePoint &p : ring)
            out.mesh.addVertex(frame.toScene(p.x, p.y, lid ? ceilingAt(p) : floorAt(p)), normal, colour);
        for (std::size_t k = 0; k + 2 < tris.size(); k += 3) {
            out.mesh.addTriangle(first + tris[k], first + tris[k + 1], first + tris[k + 2]);
        }
    };
    const auto ccw = [](std::vector<PlanePoint> ring) {
        if (signedArea(ring) < 0)
            std::reverse(ring.begin(), ring.end());
        return ring;
    };
    const auto circle = [&](const GeoPoint &centre, double radius) {
        const PlanePoint c = frame.toPlane(centre);
        std::vector<PlanePoint> ring;
        const int n = std::max(style.circleSegments, 8);
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * std::numbers::pi * k / n;
            ring.push_back({c.x + radius * std::cos(a), c.y + radius * std::sin(a)});
        }
        return ring;
    };

    if (const auto *polygons = std::get_if<airspace::ZonePolygons>(&zone.shape)) {
        for (const airspace::ZonePolygon &part : polygons->parts)
            for (std::size_t r = 0; r < part.rings.size(); ++r) {
                std::vector<PlanePoint> ring;
                for (const GeoPoint &g : part.rings[r])
                    ring.push_back(frame.toPlane(g));
                if (ring.size() > 1 && ring.front().x == ring.back().x && ring.front().y == ring.back().y)
                    ring.pop_back();
                if (ring.size() < 3)
                    continue;
                ring = ccw(std::move(ring));
                const std::vector<PlanePoint> dense = densify(ring, step);
                walls(dense, nullptr, r > 0);
                if (r == 0) {
                    out.outline.insert(out.outline.end(), ring.begin(), ring.end());
                    if (out.hasLid)
                        cap(dense, true);
                    if (out.hasFloor)
                        cap(dense, false);
                }
            }
    } else if (const auto *c = std::get_if<airspace::ZoneCircle>(&zone.shape)) {
        const std::vector<PlanePoint> ring = circle(c->center, c->radius);
        out.outline = ring;
        walls(ring, nullptr, false);
        if (out.hasLid)
            cap(ring, true);
        if (out.hasFloor)
            cap(ring, false);
    } else if (const auto *cone = std::get_if<airspace::ZoneConeFrustum>(&zone.shape)) {
        const std::vector<PlanePoint> bottom = circle(cone->center, cone->bottomRadius);
        const std::vector<PlanePoint> top = circle(cone->center, cone->topRadius);
        out.outline = bottom;
        walls(bottom, &top, false);
        if (out.hasLid)
            cap(top, true);
        if (out.hasFloor)
            cap(bottom, false);
    }
    return out;
}

} // namespace sortie::scene3d
