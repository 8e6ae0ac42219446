#include "AirspaceRule.h"

#include "ElevationService.h"
#include "Geodesy.h"

#include <QLocale>

#include <cmath>
#include <QCoreApplication>

namespace sortie::airspace {

using mission::Severity;
using mission::ValidationIssue;

namespace {
constexpr double kFrameDrift = 5000.0;  // metres the route's centre may move before the frame follows

QString metres(double v)
{
    return QLocale(QLocale::English).toString(std::llround(v)) + QStringLiteral(" m");
}

QString limits(const Zone &z)
{
    return QCoreApplication::translate("AirspaceRule", "floor %1, ceiling %2").arg(limitText(z.floor, false), limitText(z.ceiling, true));
}
} // namespace

QString violationMessage(const AirspaceViolation &v, const Zone &zone)
{
    const QString where = v.toDistance - v.fromDistance < 0.5 ? QCoreApplication::translate("AirspaceRule", "at %1").arg(metres(v.fromDistance))
                                                              : QCoreApplication::translate("AirspaceRule", "from %1 to %2").arg(metres(v.fromDistance), metres(v.toDistance));
    // One sentence each way: a verb put into a sentence is not translatable (word order differs).
    QString text = v.kind == ViolationKind::InsideExclusion
        ? QCoreApplication::translate("AirspaceRule", "Leg %1 enters '%2' %3 (%4)").arg(v.leg).arg(zone.name, where, limits(zone))
        : QCoreApplication::translate("AirspaceRule", "Leg %1 leaves '%2' %3 (%4)").arg(v.leg).arg(zone.name, where, limits(zone));
    if (v.heightUnknown)
        text += QCoreApplication::translate("AirspaceRule", "; its height there is unknown (no terrain data), so it counts as inside");
    return text + QLatin1Char('.');
}

QString warningMessage(const AirspaceWarning &w, const Zone &zone, double buffer)
{
    return QCoreApplication::translate("AirspaceRule", "Leg %1 passes within %2 of %3 '%4' (buffer %5).")
        .arg(w.leg)
        .arg(metres(std::max(0.0, w.clearance)), zone.kind == ZoneKind::Exclusion ? QCoreApplication::translate("AirspaceRule", "exclusion zone")
                                                                                 : QCoreApplication::translate("AirspaceRule", "the edge of inclusion zone"),
             zone.name, metres(buffer));
}

std::vector<ValidationIssue> airspaceIssues(const AirspaceReport &report, const ZoneSet &zones, double buffer)
{
    std::vector<ValidationIssue> out;
    for (const AirspaceViolation &v : report.violations)
        out.push_back({Severity::Error,
                       v.kind == ViolationKind::InsideExclusion ? QStringLiteral("airspace-exclusion") : QStringLiteral("airspace-inclusion"),
                       violationMessage(v, zones.zones()[size_t(v.zone)]), v.row});
    for (const AirspaceWarning &w : report.warnings)
        out.push_back({Severity::Warning, QStringLiteral("airspace-near"), warningMessage(w, zones.zones()[size_t(w.zone)], buffer), w.row});
    return out;
}

AirspaceRule::AirspaceRule(terrain::ElevationService *service, QObject *parent) : RouteRule(parent), m_service(service)
{
    if (service)
        connect(service, &terrain::ElevationService::changed, this, &RouteRule::changed);
}

void AirspaceRule::setZones(std::shared_ptr<const ZoneSet> zones)
{
    m_zones = std::move(zones);
    m_checker.reset();
    emit changed();
}

void AirspaceRule::setBuffer(double metres)
{
    if (metres == m_buffer || !(metres >= 0))
        return;
    m_buffer = metres;
    m_checker.reset();
    emit changed();
}

void AirspaceRule::check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<ValidationIssue> &issues)
{
    m_lastReport = {};
    m_lastZones = m_zones;
    m_lastPath = {};
    if (!m_zones || m_zones->zones().empty())
        return;
    if (!m_checker)
        m_checker = std::make_unique<AirspaceChecker>(m_zones, m_buffer);
    const terrain::ProfileRoute pr = terrain::profileRouteOf(route, cache);
    if (pr.waypoints.empty())
        return;
    std::optional<terrain::TerrainProfile> ground;
    if (m_service)
        ground = terrain::computeProfile(pr, *m_service);
    // One frame while the route is edited, so unchanged legs keep their findings; a new one when
    // the route's centre has moved far (another route opened).
    std::vector<mission::GeoPoint> points;
    points.reserve(pr.waypoints.size());
    for (const terrain::ProfileWaypoint &w : pr.waypoints)
        points.push_back(w.position);
    const mission::GeoPoint centre = mission::LocalTangentPlane::centroidOf(points);
    if (!m_frameOrigin || mission::geodesicDistance(centre, *m_frameOrigin) > kFrameDrift)
        m_frameOrigin = centre;
    const mission::LocalTangentPlane plane(*m_frameOrigin);
    FlownPath path = flownPath(pr, ground ? &*ground : nullptr, flightEndsOf(route), &plane);
    m_lastReport = m_checker->check(path);
    m_lastPath = std::move(path);  // kept (not copied) for the views: where each violation is
    const std::vector<ValidationIssue> found = airspaceIssues(m_lastReport, *m_zones, m_buffer);
    issues.insert(issues.end(), found.begin(), found.end());
}

} // namespace sortie::airspace
