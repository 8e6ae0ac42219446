#pragma once

#include "AirspaceCheck.h"
#include "RouteRule.h"

#include <QPointer>

#include <map>

namespace sortie::terrain {
class ElevationService;
}

namespace sortie::airspace {

// The authorisations the operator recorded: a geographical zone's identifier -> the
// authorisation's reference (what the authority gave).
using Authorisations = std::map<QString, QString>;

// What a stretch inside a zone means (docs/airspace.md, "UAS geographical zones"): an error for an
// exclusion or inclusion zone and for a PROHIBITED or REQ_AUTHORISATION one without an
// authorisation; a warning for REQ_AUTHORISATION with one and for CONDITIONAL; information for
// NO_RESTRICTION.
enum class FindingLevel { Error, Warning, Information };
FindingLevel findingLevel(const AirspaceViolation &v, const Zone &zone, const Authorisations &authorisations);
// The authorisation recorded for a zone's geographical zone; empty when none is.
QString authorisationFor(const Zone &zone, const Authorisations &authorisations);

// "Leg 3 enters 'RIX CTR' from 1,210 m to 1,460 m (floor ground, ceiling 150 m AMSL)." For a
// geographical zone: its identifier and volume, what its restriction asks, its message, reason,
// authority and when it applies (in the operator's time zone).
QString violationMessage(const AirspaceViolation &v, const Zone &zone, const Authorisations &authorisations = {});
// "Leg 4 passes within 12 m of 'RIX CTR' (buffer 20 m)."
QString warningMessage(const AirspaceWarning &w, const Zone &zone, double buffer);

// The flight's window: from `start` to its end by the time model (the route's own timing). A route
// the time model cannot time: the start alone, and `note` (when given) says why.
ed::TimeWindow flightWindow(const mission::Route &route, const QDateTime &start, mission::ScanPlanCache *cache = nullptr,
                            QString *note = nullptr);

// The airspace rules, with the culprit's row so a view can select it:
// - "airspace-exclusion" (error): a stretch of a leg inside an exclusion zone (3D: between its
//   floor and ceiling), with the zone and where along the route it enters and leaves;
// - "airspace-inclusion" (error): a stretch outside every inclusion zone (a fence left);
// - "airspace-near" (warning): a leg within the buffer of a zone it does not cross.
// Geographical zones by their restriction: errors as above, "airspace-authorised" (warning:
// REQ_AUTHORISATION with a recorded authorisation), "airspace-conditional" (warning, with the
// zone's message); NO_RESTRICTION zones are information, not an issue.
std::vector<mission::ValidationIssue> airspaceIssues(const AirspaceReport &report, const ZoneSet &zones, double buffer,
                                                     const Authorisations &authorisations = {});

// The rules above for RouteAnalyzer: the route's flown path (with the ground from `service`, when
// given) against the zones; re-runs when the zones, the buffer or the ground change. Re-checks
// only the legs an edit changed.
class AirspaceRule : public mission::RouteRule
{
    Q_OBJECT

public:
    explicit AirspaceRule(terrain::ElevationService *service = nullptr, QObject *parent = nullptr);
    void setZones(std::shared_ptr<const ZoneSet> zones);
    void setBuffer(double metres);
    double buffer() const { return m_buffer; }
    // The flight's window and the authorisations come from the route checked (its plannedStart,
    // or now, to its end by the time model; its authorisations); these are the last check's.
    const Authorisations &lastAuthorisations() const { return m_lastAuthorisations; }
    // The flight's window of the last check (UTC): which geographical zones applied to it.
    const ed::TimeWindow &lastWindow() const { return m_lastWindow; }
    // What the last check found, and the zone set its zone indices refer to (none before a check
    // or without zones): the client's views draw where the route crosses which zone.
    const AirspaceReport &lastReport() const { return m_lastReport; }
    const std::shared_ptr<const ZoneSet> &lastZones() const { return m_lastZones; }
    const FlownPath &lastPath() const { return m_lastPath; }
    void check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<mission::ValidationIssue> &issues) override;

private:
    QPointer<terrain::ElevationService> m_service;
    std::shared_ptr<const ZoneSet> m_zones;
    double m_buffer = 20.0;
    Authorisations m_lastAuthorisations;
    ed::TimeWindow m_lastWindow;
    std::unique_ptr<AirspaceChecker> m_checker;
    std::optional<mission::GeoPoint> m_frameOrigin;
    AirspaceReport m_lastReport;
    std::shared_ptr<const ZoneSet> m_lastZones;
    FlownPath m_lastPath;
};

} // namespace sortie::airspace
