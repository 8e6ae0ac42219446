#include "PreflightVerdict.h"

namespace sortie::preflight {

namespace {
ItemVerdict atLeast(const std::optional<double> &value, const std::optional<double> &minimum)
{
    if (!value)
        return {Outcome::Missing, std::nullopt};
    return {*value >= minimum.value_or(0) ? Outcome::Pass : Outcome::Fail, value};
}

ItemVerdict yes(const std::optional<bool> &value)
{
    if (!value)
        return {Outcome::Missing, std::nullopt};
    return {*value ? Outcome::Pass : Outcome::Fail, std::nullopt};
}
} // namespace

ItemVerdict judge(const ChecklistItem &item, const PreflightFacts &facts, bool ticked)
{
    switch (item.check) {
    case Check::Manual: return {ticked ? Outcome::Ticked : Outcome::Unticked, std::nullopt};
    case Check::Link: return {facts.linkUp ? Outcome::Pass : Outcome::Fail, std::nullopt};
    case Check::RouteOnBoard: return yes(facts.routeOnBoard);
    case Check::RouteCheck:
        if (!facts.routeErrors)
            return {Outcome::Missing, std::nullopt};
        return {*facts.routeErrors == 0 ? Outcome::Pass : Outcome::Fail, double(*facts.routeErrors)};
    default: break;
    }
    // What the vehicle reports: old values without the link.
    if (!facts.linkUp)
        return {Outcome::Missing, std::nullopt};
    switch (item.check) {
    case Check::GpsFix: return atLeast(facts.gpsFix, item.minimum);
    case Check::Satellites: return atLeast(facts.satellites, item.minimum);
    case Check::Battery: return atLeast(facts.batteryPercent, item.minimum);
    case Check::Home:
        if (!facts.homeReportable)
            return {Outcome::NotReported, std::nullopt};
        return yes(facts.homeSet);
    case Check::Camera: return yes(facts.cameraPresent);
    default: return {Outcome::Missing, std::nullopt};
    }
}

bool holdsBack(const ChecklistItem &item, const ItemVerdict &verdict, Gate gate)
{
    if (!item.required || (item.gates & gate) == 0)
        return false;
    return verdict.outcome != Outcome::Pass && verdict.outcome != Outcome::Ticked && verdict.outcome != Outcome::NotReported;
}

} // namespace sortie::preflight
