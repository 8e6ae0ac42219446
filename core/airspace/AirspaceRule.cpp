#include "AirspaceRule.h"

#include "ElevationService.h"
#include "Geodesy.h"
#include "RouteTiming.h"

#include <QLocale>

#include <algorithm>
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

FindingLevel findingLevel(const AirspaceViolation &v, const Zone &zone, const Authorisations &authorisations)
{
    if (v.kind != ViolationKind::InsideExclusion || !zone.geoZone)
        return FindingLevel::Error;
    switch (zone.geoZone->restriction) {
    case ed::Restriction::Prohibited: return FindingLevel::Error;
    case ed::Restriction::ReqAuthorisation: return authorisationFor(zone, authorisations).isEmpty() ? FindingLevel::Error : FindingLevel::Warning;
    case ed::Restriction::Conditional: return FindingLevel::Warning;
    case ed::Restriction::NoRestriction: return FindingLevel::Information;
    }
    return FindingLevel::Error;
}

QString authorisationFor(const Zone &zone, const Authorisations &authorisations)
{
    if (!zone.geoZone)
        return {};
    const auto it = authorisations.find(zone.geoZone->identifier);
    return it == authorisations.end() ? QString() : it->second;
}

namespace {
// What a geographical zone says beyond its restriction: message, reason, authority, when.
QString geoZoneDetails(const ed::GeoZone &g)
{
    QString out;
    if (!g.message.isEmpty()) {
        out += QLatin1Char(' ') + QCoreApplication::translate("AirspaceRule", "Message: %1").arg(g.message);
        if (!g.message.endsWith(QLatin1Char('.')) && !g.message.endsWith(QLatin1Char('!')) && !g.message.endsWith(QLatin1Char('?')))
            out += QLatin1Char('.');
    }
    QStringList reasons = g.reasons;
    if (!g.otherReasonInfo.isEmpty())
        reasons << g.otherReasonInfo;
    if (!reasons.isEmpty())
        out += QLatin1Char(' ') + QCoreApplication::translate("AirspaceRule", "Reason: %1.").arg(reasons.join(QStringLiteral(", ")));
    // The authority to ask first when the zone needs an authorisation, else the first named.
    const ed::Authority *authority = nullptr;
    for (const ed::Authority &a : g.authorities)
        if (!authority || (g.restriction == ed::Restriction::ReqAuthorisation && a.purpose == QLatin1String("AUTHORIZATION")
                           && authority->purpose != QLatin1String("AUTHORIZATION")))
            authority = &a;
    if (authority && !ed::contactText(*authority).isEmpty())
        out += QLatin1Char(' ') + QCoreApplication::translate("AirspaceRule", "Authority: %1.").arg(ed::contactText(*authority));
    if (!g.applicability.empty())
        out += QLatin1Char(' ') + QCoreApplication::translate("AirspaceRule", "Applies: %1.").arg(ed::applicabilityText(g.applicability, QTimeZone::systemTimeZone()));
    return out;
}
} // namespace

namespace {
// `details`: the zone's geoZoneDetails when the caller has them already (one zone, many findings).
QString violationText(const AirspaceViolation &v, const Zone &zone, const Authorisations &authorisations, const QString *details)
{
    const QString where = v.toDistance - v.fromDistance < 0.5 ? QCoreApplication::translate("AirspaceRule", "at %1").arg(metres(v.fromDistance))
                                                              : QCoreApplication::translate("AirspaceRule", "from %1 to %2").arg(metres(v.fromDistance), metres(v.toDistance));
    QString text;
    if (zone.geoZone && v.kind == ViolationKind::InsideExclusion) {
        // One sentence per restriction, each whole (word order differs between languages).
        const ed::GeoZone &g = *zone.geoZone;
        const QString reference = authorisationFor(zone, authorisations);
        switch (g.restriction) {
        case ed::Restriction::Prohibited:
            text = QCoreApplication::translate("AirspaceRule", "Leg %1 enters the prohibited zone '%2' (%3, volume %4) %5 (%6)")
                       .arg(v.leg).arg(zone.name, g.identifier).arg(zone.volume).arg(where, limits(zone));
            break;
        case ed::Restriction::ReqAuthorisation:
            text = reference.isEmpty()
                ? QCoreApplication::translate("AirspaceRule", "Leg %1 enters '%2' (%3, volume %4) %5 (%6), which needs an authorisation; none is recorded")
                      .arg(v.leg).arg(zone.name, g.identifier).arg(zone.volume).arg(where, limits(zone))
                : QCoreApplication::translate("AirspaceRule", "Leg %1 enters '%2' (%3, volume %4) %5 (%6) under authorisation %7")
                      .arg(v.leg).arg(zone.name, g.identifier).arg(zone.volume).arg(where, limits(zone), reference);
            break;
        case ed::Restriction::Conditional:
            text = QCoreApplication::translate("AirspaceRule", "Leg %1 enters the conditional zone '%2' (%3, volume %4) %5 (%6)")
                       .arg(v.leg).arg(zone.name, g.identifier).arg(zone.volume).arg(where, limits(zone));
            break;
        case ed::Restriction::NoRestriction:
            text = QCoreApplication::translate("AirspaceRule", "Leg %1 passes through '%2' (%3, volume %4) %5 (%6), a zone with no restriction")
                       .arg(v.leg).arg(zone.name, g.identifier).arg(zone.volume).arg(where, limits(zone));
            break;
        }
        if (v.heightUnknown)
            text += QCoreApplication::translate("AirspaceRule", "; its height there is unknown (no terrain data), so it counts as inside");
        return text + QLatin1Char('.') + (details ? *details : geoZoneDetails(g));
    }
    // One sentence each way: a verb put into a sentence is not translatable (word order differs).
    text = v.kind == ViolationKind::InsideExclusion
        ? QCoreApplication::translate("AirspaceRule", "Leg %1 enters '%2' %3 (%4)").arg(v.leg).arg(zone.name, where, limits(zone))
        : QCoreApplication::translate("AirspaceRule", "Leg %1 leaves '%2' %3 (%4)").arg(v.leg).arg(zone.name, where, limits(zone));
    if (v.heightUnknown)
        text += QCoreApplication::translate("AirspaceRule", "; its height there is unknown (no terrain data), so it counts as inside");
    return text + QLatin1Char('.');
}
} // namespace

QString violationMessage(const AirspaceViolation &v, const Zone &zone, const Authorisations &authorisations)
{
    return violationText(v, zone, authorisations, nullptr);
}

QString warningMessage(const AirspaceWarning &w, const Zone &zone, double buffer)
{
    return QCoreApplication::translate("AirspaceRule", "Leg %1 passes within %2 of %3 '%4' (buffer %5).")
        .arg(w.leg)
        .arg(metres(std::max(0.0, w.clearance)), zone.kind == ZoneKind::Exclusion ? QCoreApplication::translate("AirspaceRule", "exclusion zone")
                                                                                 : QCoreApplication::translate("AirspaceRule", "the edge of inclusion zone"),
             zone.name, metres(buffer));
}

ed::TimeWindow flightWindow(const mission::Route &route, const QDateTime &start, mission::ScanPlanCache *cache, QString *note)
{
    const QDateTime from = start.toUTC();
    const mission::Result<mission::RouteTimeline> timeline = mission::timeRoute(route, mission::timingOf(route.settings), cache);
    if (!timeline) {
        if (note)
            *note = timeline.error().message;
        return {from, from};
    }
    return {from, from.addMSecs(qint64(std::ceil(timeline->totalSeconds() * 1000.0)))};
}

std::vector<ValidationIssue> airspaceIssues(const AirspaceReport &report, const ZoneSet &zones, double buffer, const Authorisations &authorisations)
{
    std::vector<ValidationIssue> out;
    std::map<const ed::GeoZone *, QString> details;  // composed once per zone, not per finding
    for (const AirspaceViolation &v : report.violations) {
        const Zone &zone = zones.zones()[size_t(v.zone)];
        const FindingLevel level = findingLevel(v, zone, authorisations);
        if (level == FindingLevel::Information)
            continue;
        QString rule = v.kind == ViolationKind::InsideExclusion ? QStringLiteral("airspace-exclusion") : QStringLiteral("airspace-inclusion");
        if (level == FindingLevel::Warning)
            rule = zone.geoZone->restriction == ed::Restriction::Conditional ? QStringLiteral("airspace-conditional") : QStringLiteral("airspace-authorised");
        const QString *said = nullptr;
        if (zone.geoZone) {
            auto [it, fresh] = details.try_emplace(zone.geoZone.get());
            if (fresh)
                it->second = geoZoneDetails(*zone.geoZone);
            said = &it->second;
        }
        out.push_back({level == FindingLevel::Error ? Severity::Error : Severity::Warning, rule, violationText(v, zone, authorisations, said), v.row});
    }
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
    m_lastAuthorisations = route.settings.authorisations;
    m_lastWindow = {};
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
    // Geographical zones count when they apply during the flight (timed only when there are any).
    const auto &all = m_zones->zones();
    if (std::any_of(all.begin(), all.end(), [](const Zone &z) { return z.geoZone != nullptr; }))
        m_checker->setWindow(m_lastWindow = flightWindow(route, route.settings.plannedStart.value_or(QDateTime::currentDateTimeUtc()), cache));
    m_lastReport = m_checker->check(path);
    m_lastPath = std::move(path);  // kept (not copied) for the views: where each violation is
    const std::vector<ValidationIssue> found = airspaceIssues(m_lastReport, *m_zones, m_buffer, m_lastAuthorisations);
    issues.insert(issues.end(), found.begin(), found.end());
}

} // namespace sortie::airspace
