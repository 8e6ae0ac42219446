#pragma once

#include "RouteRule.h"
#include "TerrainProfile.h"

#include <QPointer>

namespace sortie::terrain {

// The terrain rules, with the culprit's row so that a view can select it:
// - "terrain-clearance" (error): a leg flies closer to the ground than the vehicle profile's safe
//   distance, between waypoints too; names the leg and the distance along it of the lowest point;
// - "terrain-no-data" (warning): a stretch where no source had terrain data, naming the leg(s) and
//   the sources tried; consecutive legs without data are one issue;
// - "terrain-above-surface-limit" (warning): a leg flies higher above the ground under it than the
//   route's surface height limit (the open category's 120 m); one issue per leg, naming its highest
//   point. A warning, not an error: an authorisation in the specific category allows more;
// - "terrain-agl-no-data" (error): a waypoint above ground (or home) where the ground is unknown, so
//   its height is unknown; consecutive waypoints are one issue.
std::vector<mission::ValidationIssue> terrainIssues(const ProfileRoute &route, const TerrainProfile &profile);

// The rules above for RouteAnalyzer: profiles the route at `step` from the service and re-runs when
// the service's data changes.
class TerrainRule : public mission::RouteRule
{
    Q_OBJECT

public:
    explicit TerrainRule(ElevationService *service, double step = 30.0, QObject *parent = nullptr);
    void check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<mission::ValidationIssue> &issues) override;

private:
    QPointer<ElevationService> m_service;
    double m_step;
};

} // namespace sortie::terrain
