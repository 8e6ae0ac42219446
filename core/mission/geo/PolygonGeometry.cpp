#include "PolygonGeometry.h"

#include <algorithm>
#include <cmath>

namespace sortie::mission::polygon {

namespace {
double cross(const PlanePoint &o, const PlanePoint &a, const PlanePoint &b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

int orientation(const PlanePoint &o, const PlanePoint &a, const PlanePoint &b, double eps)
{
    const double c = cross(o, a, b);
    return c > eps ? 1 : (c < -eps ? -1 : 0);
}

bool onSegment(const PlanePoint &p, const PlanePoint &a, const PlanePoint &b, double eps)
{
    return std::min(a.x, b.x) - eps <= p.x && p.x <= std::max(a.x, b.x) + eps
        && std::min(a.y, b.y) - eps <= p.y && p.y <= std::max(a.y, b.y) + eps;
}

bool segmentsTouch(const PlanePoint &a, const PlanePoint &b, const PlanePoint &c, const PlanePoint &d)
{
    // Tolerance scaled to the segment lengths: a millimetre-scale margin for field-sized polygons.
    const double scale = std::max({std::hypot(b.x - a.x, b.y - a.y), std::hypot(d.x - c.x, d.y - c.y), 1.0});
    const double eps = 1e-9 * scale * scale;
    const int o1 = orientation(a, b, c, eps), o2 = orientation(a, b, d, eps);
    const int o3 = orientation(c, d, a, eps), o4 = orientation(c, d, b, eps);
    if (o1 != o2 && o3 != o4 && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0)
        return true;
    const double le = 1e-6;
    return (o1 == 0 && onSegment(c, a, b, le)) || (o2 == 0 && onSegment(d, a, b, le))
        || (o3 == 0 && onSegment(a, c, d, le)) || (o4 == 0 && onSegment(b, c, d, le))
        || (o1 != o2 && o3 != o4);
}
}

double signedArea(const std::vector<PlanePoint> &pts)
{
    double s = 0;
    const size_t n = pts.size();
    for (size_t i = 0; i < n; ++i) {
        const PlanePoint &p = pts[i], &q = pts[(i + 1) % n];
        s += p.x * q.y - q.x * p.y;
    }
    return s / 2;
}

std::optional<std::pair<int, int>> firstSelfIntersection(const std::vector<PlanePoint> &pts)
{
    const int n = int(pts.size());
    if (n < 3)
        return std::nullopt;
    for (int i = 0; i < n; ++i) {
        const PlanePoint &a = pts[i], &b = pts[(i + 1) % n];
        for (int j = i + 1; j < n; ++j) {
            const bool neighbours = j == i + 1 || (i == 0 && j == n - 1);
            const PlanePoint &c = pts[j], &d = pts[(j + 1) % n];
            if (neighbours) {
                // Neighbours share a vertex; they still overlap when they fold back on each other.
                const PlanePoint &shared = j == i + 1 ? b : a;
                const PlanePoint &u = j == i + 1 ? a : b;
                const PlanePoint &v = j == i + 1 ? d : c;
                const double ux = u.x - shared.x, uy = u.y - shared.y, vx = v.x - shared.x, vy = v.y - shared.y;
                const double lu = std::hypot(ux, uy), lv = std::hypot(vx, vy);
                if (lu == 0 || lv == 0)
                    return std::make_pair(i, j);  // repeated vertex
                const double sin = (ux * vy - uy * vx) / (lu * lv), cos = (ux * vx + uy * vy) / (lu * lv);
                if (std::abs(sin) < 1e-9 && cos > 0)
                    return std::make_pair(i, j);  // the boundary doubles back on itself
                continue;
            }
            if (segmentsTouch(a, b, c, d))
                return std::make_pair(i, j);
        }
    }
    return std::nullopt;
}

std::vector<double> crossingsAt(const std::vector<PlanePoint> &pts, double y)
{
    std::vector<double> xs;
    const size_t n = pts.size();
    for (size_t i = 0; i < n; ++i) {
        const PlanePoint &p = pts[i], &q = pts[(i + 1) % n];
        if ((p.y <= y && y < q.y) || (q.y <= y && y < p.y)) {
            const double t = (y - p.y) / (q.y - p.y);
            xs.push_back(p.x + t * (q.x - p.x));
        }
    }
    std::sort(xs.begin(), xs.end());
    return xs;
}

} // namespace sortie::mission::polygon
