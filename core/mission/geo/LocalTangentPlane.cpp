#include "LocalTangentPlane.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace sortie::mission {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

LocalTangentPlane::LocalTangentPlane(const GeoPoint &origin)
    : m_originGeo(origin), m_origin(toEcef(origin))
{
    const double lat = origin.latitude * kDeg, lon = origin.longitude * kDeg;
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    m_east[0] = -so; m_east[1] = co; m_east[2] = 0;
    m_north[0] = -sl * co; m_north[1] = -sl * so; m_north[2] = cl;
    m_up[0] = cl * co; m_up[1] = cl * so; m_up[2] = sl;
}

GeoPoint LocalTangentPlane::centroidOf(const std::vector<GeoPoint> &points)
{
    double x = 0, y = 0, z = 0;
    for (const auto &p : points) {
        const Ecef e = toEcef(p);
        x += e.x; y += e.y; z += e.z;
    }
    if (points.empty())
        return {};
    const double n = double(points.size());
    return fromEcef({x / n, y / n, z / n});
}

PlanePoint LocalTangentPlane::project(const GeoPoint &p) const
{
    const Ecef e = toEcef(p);
    const double d[3] = {e.x - m_origin.x, e.y - m_origin.y, e.z - m_origin.z};
    return {d[0] * m_east[0] + d[1] * m_east[1] + d[2] * m_east[2],
            d[0] * m_north[0] + d[1] * m_north[1] + d[2] * m_north[2]};
}

GeoPoint LocalTangentPlane::unproject(const PlanePoint &p) const
{
    // Walk from the tangent-plane point along the local vertical to the ellipsoid surface.
    const Ellipsoid e = Ellipsoid::wgs84();
    const double a = e.a, b = a * (1 - e.f);
    const double P[3] = {m_origin.x + p.x * m_east[0] + p.y * m_north[0],
                         m_origin.y + p.x * m_east[1] + p.y * m_north[1],
                         m_origin.z + p.x * m_east[2] + p.y * m_north[2]};
    const double mp[3] = {P[0] / a, P[1] / a, P[2] / b};
    const double mu[3] = {m_up[0] / a, m_up[1] / a, m_up[2] / b};
    const double A = mu[0] * mu[0] + mu[1] * mu[1] + mu[2] * mu[2];
    const double B = mp[0] * mu[0] + mp[1] * mu[1] + mp[2] * mu[2];
    const double C = mp[0] * mp[0] + mp[1] * mp[1] + mp[2] * mp[2] - 1.0;
    const double disc = B * B - A * C;
    if (disc < 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan};
    }
    const double t = -C / (B + std::sqrt(disc));  // the root nearest the plane, stable form
    return fromEcef({P[0] + t * m_up[0], P[1] + t * m_up[1], P[2] + t * m_up[2]});
}

} // namespace sortie::mission
