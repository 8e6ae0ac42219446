#pragma once

#include "VciMissionPlanner.h"
#include "VciRoutePoints.h"

#include <optional>
#include <vector>

namespace sortie::vehicle {

// Puts a route's points into a VCI mission, each height made relative to the vehicle's home, the
// only height a VCI vehicle flies: an AMSL height less the home's altitude, an AGL one over the
// ground under its point (flown above home, with a notice, where the ground or the home is unknown);
// AGL area tools follow the ground (VciTerrainFollow).
class VciMissionBuilder
{
public:
    VciMissionBuilder(const mission::Route &route, const VciHeights &heights);

    // Where the last segment added ended (a UgCS tool plans from there).
    std::optional<mission::GeoPoint> lastPosition() const { return m_lastPosition; }

    // Adds segment `row`'s points; an AGL area tool (followTolerance set) follows the ground.
    std::optional<mission::MissionError> add(int row, const std::vector<VciRoutePoint> &points,
                                             std::optional<double> followTolerance);
    // The mission, with a notice for the points flown above home for want of the ground.
    VciMission finish();
    // An error naming segment `row`.
    mission::MissionError at(int row, const QString &why) const;

private:
    std::optional<double> ground(const mission::GeoPoint &p);
    std::optional<double> aboveHome(const VciRoutePoint &p);
    bool canFollow(const std::vector<VciRoutePoint> &points) const;

    const mission::Route &m_route;
    const VciHeights &m_heights;
    VciMission m_mission;
    std::optional<mission::GeoPoint> m_lastPosition;
    int m_levelGround = 0;
};

} // namespace sortie::vehicle
