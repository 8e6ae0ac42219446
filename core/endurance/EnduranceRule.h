#pragma once

#include "EnduranceEstimate.h"
#include "RouteRule.h"

#include <optional>

namespace sortie::endurance {

// The endurance rules, with the culprit's row so a view can select it:
// - "endurance-battery" (error): the route needs another battery where it plans no change. A
//   planned change is a landing (a Land waypoint) the battery reaches with its reserve intact;
//   Sortie expects the battery to be changed there. Also: one leg alone needs more than a battery.
// - "endurance-wind" (error): a leg cannot be flown against the wind given.
// - "endurance-reserve" (warning): the route lands with less than its reserve plus 10 % of the
//   battery left (e.g. below 30 % with a 20 % reserve).
std::vector<mission::ValidationIssue> enduranceIssues(const mission::Route &route, const EnergyProfile &profile,
                                                      const mission::Result<EnduranceEstimate> &estimate);

// The rules above for RouteAnalyzer, with the profile in use (none: no endurance issues, the
// estimate is missing rather than guessed); re-runs when the profile or the conditions change.
class EnduranceRule : public mission::RouteRule
{
    Q_OBJECT

public:
    using RouteRule::RouteRule;
    void setProfile(const std::optional<EnergyProfile> &profile);
    void setConditions(const FlightConditions &conditions);
    const std::optional<EnergyProfile> &profile() const { return m_profile; }
    void check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<mission::ValidationIssue> &issues) override;

private:
    std::optional<EnergyProfile> m_profile;
    FlightConditions m_conditions;
};

} // namespace sortie::endurance
