#include "SimFence.h"

#include <cmath>
#include <limits>

namespace sortie::sim {

namespace profile = vci::profile;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kEarthRadius = 6371008.8;
} // namespace

void SimFence::set(profile::Fence fence)
{
    m_fence = std::move(fence);
    ++m_version;
    m_breached = false;
    m_breaches = 0;
    m_item = -1;
    m_kind.clear();
    m_action.clear();
}

bool SimFence::insideHorizontally(const profile::FenceItem &item, double latitude, double longitude)
{
    if (item.center)
        return sphericalDistance(latitude, longitude, item.center->latitude / kDeg, item.center->longitude / kDeg) <= item.radius;
    // Even-odd crossing test on a plane tangent at the point (metres east and north of it): the
    // polygons a fence holds are small enough for the plane to be exact to centimetres.
    const double cosLat = std::cos(latitude * kDeg);
    bool inside = false;
    const size_t n = item.polygon.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double xi = (item.polygon[i].longitude / kDeg - longitude) * kDeg * kEarthRadius * cosLat;
        const double yi = (item.polygon[i].latitude / kDeg - latitude) * kDeg * kEarthRadius;
        const double xj = (item.polygon[j].longitude / kDeg - longitude) * kDeg * kEarthRadius * cosLat;
        const double yj = (item.polygon[j].latitude / kDeg - latitude) * kDeg * kEarthRadius;
        if ((yi > 0) != (yj > 0) && 0 < (xj - xi) * (0 - yi) / (yj - yi) + xi)
            inside = !inside;
    }
    return inside;
}

bool SimFence::betweenLimits(const profile::FenceItem &item, double altitudeAmsl, double aboveHome)
{
    const auto height = [&](const profile::FenceLimit &l) { return l.reference == profile::FenceReference::Amsl ? altitudeAmsl : aboveHome; };
    if (item.floor && height(*item.floor) < item.floor->altitude)
        return false;
    if (item.ceiling && height(*item.ceiling) > item.ceiling->altitude)
        return false;
    return true;
}

std::optional<profile::BreachAction> SimFence::check(const FlightModel::State &s)
{
    int item = -1;
    std::string kind;
    if (s.armed && s.airborne()) {
        const double amsl = s.altitudeAmsl(), aboveHome = s.altitudeAgl;
        int firstInclusion = -1, overInclusion = -1;
        bool permitted = false;
        for (size_t i = 0; i < m_fence.items.size() && item < 0; ++i) {
            const profile::FenceItem &f = m_fence.items[i];
            const bool over = insideHorizontally(f, s.latitude, s.longitude);
            if (f.kind == profile::FenceKind::Exclusion) {
                if (over && betweenLimits(f, amsl, aboveHome)) {
                    item = int(i);
                    kind = "inside-exclusion";
                }
                continue;
            }
            if (firstInclusion < 0)
                firstInclusion = int(i);
            if (over && overInclusion < 0)
                overInclusion = int(i);
            permitted = permitted || (over && betweenLimits(f, amsl, aboveHome));
        }
        if (item < 0 && firstInclusion >= 0 && !permitted) {
            item = overInclusion >= 0 ? overInclusion : firstInclusion; // the one it left through its floor or ceiling
            kind = "outside-inclusion";
        }
    }
    const bool began = item >= 0 && !m_breached;
    m_breached = item >= 0;
    if (!m_breached)
        return std::nullopt;
    m_item = item;
    m_kind = kind;
    if (!began)
        return std::nullopt;
    ++m_breaches;
    m_action = std::string(profile::breachActionName(m_fence.breachAction));
    return m_fence.breachAction;
}

profile::FenceStatus SimFence::status(int64_t time) const
{
    profile::FenceStatus s;
    s.state = m_fence.empty() ? "none" : m_breached ? "breached" : "clear";
    s.breaches = m_breaches;
    s.time = time;
    s.action = m_action;
    if (m_breached && m_item >= 0 && size_t(m_item) < m_fence.items.size()) {
        s.item = m_item;
        s.name = m_fence.items[size_t(m_item)].name;
        s.kind = m_kind;
    }
    return s;
}

} // namespace sortie::sim
