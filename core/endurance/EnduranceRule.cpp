#include "EnduranceRule.h"

#include "RouteValidator.h"

#include <cmath>

namespace sortie::endurance {

using namespace sortie::mission;

namespace {
constexpr double kReserveMargin = 0.10;  // of the battery, above the reserve: the warning band

QString percent(double fraction)
{
    return QStringLiteral("%1 %").arg(std::round(fraction * 100));
}

QString placeName(const Route &route, const RoutePlace &at)
{
    return at.segment >= 0 ? QStringLiteral("%1 (leg %2)").arg(segmentLabel(route, at.segment)).arg(at.leg)
                           : QStringLiteral("leg %1").arg(at.leg);
}
} // namespace

std::vector<ValidationIssue> enduranceIssues(const Route &route, const EnergyProfile &profile, const Result<EnduranceEstimate> &estimate)
{
    std::vector<ValidationIssue> issues;
    if (!estimate) {
        if (estimate.error().message.contains(QStringLiteral("wind")))
            issues.push_back({Severity::Error, QStringLiteral("endurance-wind"), estimate.error().message, -1});
        return issues;  // a leg with no speed is the speed rule's to report
    }
    const EnduranceEstimate &e = *estimate;
    if (e.legTooLong) {
        const TimedLeg &leg = e.timeline.legs()[size_t(e.legTooLong - 1)];
        issues.push_back({Severity::Error, QStringLiteral("endurance-battery"),
                          QStringLiteral("Leg %1 alone needs more than one battery with the %2 reserve").arg(e.legTooLong).arg(percent(profile.reserve)),
                          leg.toSegment});
    }
    for (const BatteryChange &c : e.changes) {
        if (c.planned)
            continue;
        issues.push_back({Severity::Error, QStringLiteral("endurance-battery"),
                          QStringLiteral("Needs %1 batteries: the battery reaches its %2 reserve after %3, and the route plans no landing "
                                         "there to change it")
                              .arg(e.batteriesNeeded).arg(percent(profile.reserve)).arg(placeName(route, c.at)),
                          c.at.segment});
    }
    const bool errors = !issues.empty();
    if (!errors && e.lastBatteryAtEnd < profile.reserve + kReserveMargin)
        issues.push_back({Severity::Warning, QStringLiteral("endurance-reserve"),
                          QStringLiteral("Lands with %1 of the battery left, within 10 % of the %2 reserve")
                              .arg(percent(e.lastBatteryAtEnd)).arg(percent(profile.reserve)),
                          -1});
    return issues;
}

void EnduranceRule::setProfile(const std::optional<EnergyProfile> &profile)
{
    if (profile == m_profile)
        return;
    m_profile = profile;
    emit changed();
}

void EnduranceRule::setConditions(const FlightConditions &conditions)
{
    if (conditions.wind == m_conditions.wind && conditions.turns == m_conditions.turns)
        return;
    m_conditions = conditions;
    emit changed();
}

void EnduranceRule::check(const Route &route, ScanPlanCache *cache, std::vector<ValidationIssue> &issues)
{
    if (!m_profile || !m_profile->problem().isEmpty())
        return;
    const std::vector<ValidationIssue> found = enduranceIssues(route, *m_profile, estimateEndurance(route, *m_profile, m_conditions, cache));
    issues.insert(issues.end(), found.begin(), found.end());
}

} // namespace sortie::endurance
