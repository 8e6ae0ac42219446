#include "VciMissionBuilder.h"

#include "ElevationService.h"
#include "RouteValidator.h"
#include "VciTerrainFollow.h"

namespace sortie::vehicle {

using namespace sortie::mission;

VciMissionBuilder::VciMissionBuilder(const Route &route, const VciHeights &heights) : m_route(route), m_heights(heights) {}

std::optional<MissionError> VciMissionBuilder::add(int row, const std::vector<VciRoutePoint> &points, std::optional<double> followTolerance)
{
    if (points.empty())
        return std::nullopt;
    m_lastPosition = points.back().position;
    if (followTolerance && canFollow(points)) {
        VciFollowedPoints followed = followGround(points, *followTolerance, *m_heights.elevation, *m_heights.homeAmsl);
        if (followed.pending)
            m_mission.waitingFor = m_heights.elevation->triedText();
        if (followed.ok) {
            for (MissionItem &item : followed.items)
                m_mission.items.push_back(std::move(item));
            return std::nullopt;
        }
    }
    for (const VciRoutePoint &p : points) {
        const std::optional<double> altitude = aboveHome(p);
        if (!altitude)
            return at(row, QStringLiteral("an AMSL altitude needs the vehicle's home altitude, which it has not reported; "
                                          "wait for its telemetry or use AGL"));
        m_mission.items.push_back({p.position.latitude, p.position.longitude, *altitude, p.speed, p.acceptanceRadius, p.actions});
    }
    return std::nullopt;
}

VciMission VciMissionBuilder::finish()
{
    if (m_levelGround > 0) {
        const QString why = !m_heights.homeAmsl ? QStringLiteral("the vehicle has not reported its home")
                          : !m_heights.elevation || m_heights.elevation->sourceCount() == 0
                              ? QStringLiteral("no terrain source is set")
                              : QStringLiteral("no ground is known under them (tried: %1)").arg(m_heights.elevation->triedText());
        m_mission.notices << QStringLiteral("%1 point(s) fly their height above the ground as a height above home, right only over "
                                            "level ground: %2")
                                 .arg(m_levelGround)
                                 .arg(why);
    }
    return std::move(m_mission);
}

MissionError VciMissionBuilder::at(int row, const QString &why) const
{
    MissionError e;
    e.message = QStringLiteral("%1: %2").arg(segmentLabel(m_route, row), why);
    return e;
}

// The ground under a point, nullopt where unknown (noting a source still asking).
std::optional<double> VciMissionBuilder::ground(const GeoPoint &p)
{
    if (!m_heights.elevation)
        return std::nullopt;
    const terrain::GroundSample g = m_heights.elevation->sample(p);
    if (g.status == terrain::SampleStatus::Pending)
        m_mission.waitingFor = m_heights.elevation->triedText();
    return g.hasValue() ? std::optional<double>(g.ground) : std::nullopt;
}

// The point's height above home; nullopt for an AMSL height without the home's altitude.
std::optional<double> VciMissionBuilder::aboveHome(const VciRoutePoint &p)
{
    if (p.type == AltitudeType::Amsl) {
        if (!m_heights.homeAmsl)
            return std::nullopt;
        return p.height - *m_heights.homeAmsl;
    }
    if (m_heights.homeAmsl)
        if (const std::optional<double> g = ground(p.position))
            return *g + p.height - *m_heights.homeAmsl;
    ++m_levelGround;
    return p.height;
}

bool VciMissionBuilder::canFollow(const std::vector<VciRoutePoint> &points) const
{
    if (!m_heights.elevation || !m_heights.homeAmsl)
        return false;
    for (const VciRoutePoint &p : points)
        if (p.type != AltitudeType::Agl)
            return false;
    return true;
}

} // namespace sortie::vehicle
