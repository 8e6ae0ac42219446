#include "PathSampling.h"

#include "Geodesy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::terrain {

namespace {
constexpr double kRad = std::numbers::pi / 180.0;

struct Unit
{
    double x, y, z;
};

Unit unitOf(const GeoPoint &p)
{
    const double lat = p.latitude * kRad, lon = p.longitude * kRad;
    return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

GeoPoint pointOf(const Unit &u)
{
    return {std::atan2(u.z, std::hypot(u.x, u.y)) / kRad, std::atan2(u.y, u.x) / kRad};
}

// Interpolates a leg by spherical linear interpolation of the end points' unit vectors.
class Leg
{
public:
    Leg(const GeoPoint &a, const GeoPoint &b) : m_a(unitOf(a)), m_b(unitOf(b)), m_pa(a), m_pb(b)
    {
        const double dot = std::clamp(m_a.x * m_b.x + m_a.y * m_b.y + m_a.z * m_b.z, -1.0, 1.0);
        m_omega = std::acos(dot);
        m_sin = std::sin(m_omega);
    }
    GeoPoint at(double f) const
    {
        if (f <= 0.0)
            return m_pa;
        if (f >= 1.0)
            return m_pb;
        if (m_sin < 1e-12) {  // same point (or antipodes, which no leg is)
            return m_pa;
        }
        const double wa = std::sin((1.0 - f) * m_omega) / m_sin, wb = std::sin(f * m_omega) / m_sin;
        return pointOf({wa * m_a.x + wb * m_b.x, wa * m_a.y + wb * m_b.y, wa * m_a.z + wb * m_b.z});
    }

private:
    Unit m_a, m_b;
    GeoPoint m_pa, m_pb;
    double m_omega = 0.0, m_sin = 0.0;
};
} // namespace

GeoPoint greatCircleFraction(const GeoPoint &a, const GeoPoint &b, double f)
{
    return Leg(a, b).at(f);
}

SampledPath samplePath(std::vector<GeoPoint> vertices, double step)
{
    SampledPath out;
    out.step = (std::isfinite(step) && step > 0.0) ? step : 30.0;
    out.vertices = std::move(vertices);
    const auto &v = out.vertices;
    if (v.empty())
        return out;
    out.vertexDistance.reserve(v.size());
    out.vertexSample.reserve(v.size());
    double total = 0.0;
    for (size_t i = 0; i + 1 < v.size(); ++i) {
        const double length = mission::geodesicDistance(v[i], v[i + 1]);
        out.vertexDistance.push_back(total);
        out.vertexSample.push_back(int(out.points.size()));
        out.points.push_back({v[i], total, int(i)});
        if (length > 0.0) {
            const Leg leg(v[i], v[i + 1]);
            const int inner = int(std::ceil(length / out.step)) - 1;  // points strictly inside the leg
            for (int k = 1; k <= inner; ++k) {
                const double d = k * out.step;
                out.points.push_back({leg.at(d / length), total + d, int(i)});
            }
        }
        total += length;
    }
    out.vertexDistance.push_back(total);
    out.vertexSample.push_back(int(out.points.size()));
    out.points.push_back({v.back(), total, std::max(0, int(v.size()) - 2)});
    return out;
}

} // namespace sortie::terrain
