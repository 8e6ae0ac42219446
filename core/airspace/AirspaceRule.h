#pragma once

#include "AirspaceCheck.h"
#include "RouteRule.h"

#include <QPointer>

namespace sortie::terrain {
class ElevationService;
}

namespace sortie::airspace {

// "Leg 3 enters 'RIX CTR' from 1,210 m to 1,460 m (floor ground, ceiling 150 m AMSL)."
QString violationMessage(const AirspaceViolation &v, const Zone &zone);
// "Leg 4 passes within 12 m of 'RIX CTR' (buffer 20 m)."
QString warningMessage(const AirspaceWarning &w, const Zone &zone, double buffer);

// The airspace rules, with the culprit's row so a view can select it:
// - "airspace-exclusion" (error): a stretch of a leg inside an exclusion zone (3D: between its
//   floor and ceiling), with the zone and where along the route it enters and leaves;
// - "airspace-inclusion" (error): a stretch outside every inclusion zone (a fence left);
// - "airspace-near" (warning): a leg within the buffer of a zone it does not cross.
std::vector<mission::ValidationIssue> airspaceIssues(const AirspaceReport &report, const ZoneSet &zones, double buffer);

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
    std::unique_ptr<AirspaceChecker> m_checker;
    std::optional<mission::GeoPoint> m_frameOrigin;
    AirspaceReport m_lastReport;
    std::shared_ptr<const ZoneSet> m_lastZones;
    FlownPath m_lastPath;
};

} // namespace sortie::airspace
