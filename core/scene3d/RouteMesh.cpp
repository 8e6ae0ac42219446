#include "RouteMesh.h"

#include <algorithm>
#include <cmath>

namespace sortie::scene3d {

void addTube(Mesh &mesh, const std::vector<QVector3D> &points, float width, const QVector4D &colour)
{
    const float half = width / 2.0f;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const QVector3D a = points[i], b = points[i + 1];
        const QVector3D dir = b - a;
        if (dir.lengthSquared() < 1e-8f)
            continue;
        const QVector3D d = dir.normalized();
        // a side across the segment, horizontal unless the segment is vertical
        QVector3D side = QVector3D::crossProduct(d, QVector3D(0, 1, 0));
        if (side.lengthSquared() < 1e-6f)
            side = QVector3D(1, 0, 0);
        side.normalize();
        const QVector3D up = QVector3D::crossProduct(side, d).normalized();
        const QVector3D corners[4] = {side * half + up * half, -side * half + up * half, -side * half - up * half, side * half - up * half};
        const QVector3D faces[4] = {up, -side, -up, side};
        for (int f = 0; f < 4; ++f) {
            const QVector3D &p = corners[f], &q = corners[(f + 1) % 4];
            const QVector3D n = faces[f];
            const std::uint32_t v0 = mesh.addVertex(a + p, n, colour);
            const std::uint32_t v1 = mesh.addVertex(a + q, n, colour);
            const std::uint32_t v2 = mesh.addVertex(b + q, n, colour);
            const std::uint32_t v3 = mesh.addVertex(b + p, n, colour);
            // one winding: the views draw these meshes without back-face culling
            mesh.addTriangle(v0, v1, v2);
            mesh.addTriangle(v0, v2, v3);
        }
    }
}

void addOctahedron(Mesh &mesh, const QVector3D &c, float w, float h, const QVector4D &colour)
{
    const QVector3D top = c + QVector3D(0, h, 0), bottom = c - QVector3D(0, h, 0);
    const QVector3D ring[4] = {c + QVector3D(w, 0, 0), c + QVector3D(0, 0, -w), c + QVector3D(-w, 0, 0), c + QVector3D(0, 0, w)};
    for (int i = 0; i < 4; ++i) {
        const QVector3D &p = ring[i], &q = ring[(i + 1) % 4];
        for (const QVector3D &apex : {top, bottom}) {
            QVector3D n = QVector3D::crossProduct(q - p, apex - p).normalized();
            const bool outward = QVector3D::dotProduct(n, (p + q + apex) / 3.0f - c) > 0;
            if (!outward)
                n = -n;
            const std::uint32_t a = mesh.addVertex(p, n, colour), b = mesh.addVertex(q, n, colour), t = mesh.addVertex(apex, n, colour);
            mesh.addTriangle(a, b, t);
        }
    }
}

RouteMesh buildRoute(const airspace::FlownPath &path, const SceneFrame &frame, const HeightGrid &grid, const RouteStyle &style)
{
    RouteMesh out;
    const double fallbackGround = grid.lowest().value_or(frame.baseHeight());
    const QVector4D colour = rgba(style.colour, 1.0f);
    const QVector4D curtainColour = rgba(style.colour, style.curtainAlpha);
    struct Placed
    {
        QVector3D at;
        double east, north;
    };
    std::vector<Placed> placed;
    for (const airspace::FlownLeg &leg : path.legs) {
        const Placed *lastOfLeg = nullptr;
        for (const airspace::FlownPoint &p : leg.points) {
            const mission::PlanePoint pp = frame.toPlane(p.position);
            double h = p.in(terrain::HeightReference::Amsl);
            if (!std::isfinite(h)) {
                const double agl = p.in(terrain::HeightReference::AboveTerrain);
                const std::optional<double> g = grid.heightAt(pp.x, pp.y);
                h = std::isfinite(agl) && g ? *g + agl : std::numeric_limits<double>::quiet_NaN();
            }
            if (!std::isfinite(h)) {
                ++out.unknownHeights;
                continue;
            }
            const QVector3D at = frame.toScene(pp.x, pp.y, h);
            if (placed.empty() || placed.back().at != at)
                placed.push_back({at, pp.x, pp.y});
            lastOfLeg = &placed.back();
        }
        if (lastOfLeg)
            out.waypoints.push_back({leg.row, lastOfLeg->at});
    }
    if (!placed.empty() && !path.legs.empty())
        out.waypoints.insert(out.waypoints.begin(), WaypointMark{-1, placed.front().at});
    for (const Placed &p : placed)
        out.points.push_back(p.at);
    addTube(out.path, out.points, float(style.width), colour);
    for (const WaypointMark &w : out.waypoints)
        addOctahedron(out.path, w.position, float(style.markerSize * 0.6), float(style.markerSize), colour);

    // The curtain, its foot on the ground every grid step.
    const double step = std::max(grid.spacing, 1.0);
    const auto groundY = [&](double east, double north) {
        return float(frame.sceneY(grid.heightAt(east, north).value_or(fallbackGround)));
    };
    for (std::size_t i = 0; i + 1 < placed.size(); ++i) {
        const Placed &a = placed[i], &b = placed[i + 1];
        const double len = std::hypot(b.east - a.east, b.north - a.north);
        if (len < 1e-3)
            continue;  // a vertical move: no curtain
        const int pieces = std::max(1, int(std::ceil(len / step)));
        const QVector3D across = QVector3D::crossProduct(b.at - a.at, QVector3D(0, 1, 0)).normalized();
        std::uint32_t prevTop = 0, prevFoot = 0;
        for (int k = 0; k <= pieces; ++k) {
            const float f = float(k) / float(pieces);
            const QVector3D top = a.at + (b.at - a.at) * f;
            const double east = a.east + (b.east - a.east) * f, north = a.north + (b.north - a.north) * f;
            const float foot = std::min(groundY(east, north), top.y());
            const std::uint32_t t = out.curtain.addVertex(top, across, curtainColour);
            const std::uint32_t g = out.curtain.addVertex(QVector3D(top.x(), foot, top.z()), across, curtainColour);
            if (k > 0) {
                out.curtain.addTriangle(prevTop, prevFoot, g);
                out.curtain.addTriangle(prevTop, g, t);
            }
            prevTop = t;
            prevFoot = g;
        }
    }
    return out;
}

} // namespace sortie::scene3d
