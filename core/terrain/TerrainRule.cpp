#include "TerrainRule.h"

#include <QCoreApplication>

#include <cmath>
#include <optional>

namespace sortie::terrain {

using mission::Severity;
using mission::ValidationIssue;

namespace {
QString metres(double v) { return QString::number(v, 'f', 1); }

QString waypointName(const ProfileRoute &route, size_t i)
{
    return route.waypoints[i].label.isEmpty() ? QCoreApplication::translate("TerrainRule", "Waypoint %1").arg(i + 1) : route.waypoints[i].label;
}

int rowOf(const ProfileRoute &route, int waypoint)
{
    return waypoint >= 0 && size_t(waypoint) < route.waypoints.size() ? route.waypoints[size_t(waypoint)].row : -1;
}
} // namespace

std::vector<ValidationIssue> terrainIssues(const ProfileRoute &route, const TerrainProfile &profile)
{
    std::vector<ValidationIssue> out;
    const QString tried = profile.sourcesTried.join(QStringLiteral(", "));

    // Waypoints whose height depends on ground nobody knows.
    for (size_t i = 0; i < route.waypoints.size() && i < profile.waypoints.size();) {
        const bool unknown = std::isnan(profile.waypoints[i].altitudeAmsl) && profile.waypoints[i].ground.status != SampleStatus::Pending
                             && !(profile.homeGround.status == SampleStatus::Pending && route.waypoints[i].reference == HeightReference::AboveHome);
        if (!unknown) {
            ++i;
            continue;
        }
        size_t last = i;
        while (last + 1 < route.waypoints.size() && std::isnan(profile.waypoints[last + 1].altitudeAmsl)
               && profile.waypoints[last + 1].ground.status != SampleStatus::Pending)
            ++last;
        const bool home = route.waypoints[i].reference == HeightReference::AboveHome;
        const QString who = last == i ? waypointName(route, i)
                                      : QCoreApplication::translate("TerrainRule", "%1 to %2").arg(waypointName(route, i), waypointName(route, last));
        out.push_back({Severity::Error, QStringLiteral("terrain-agl-no-data"),
                       (home ? QCoreApplication::translate("TerrainRule", "%1: the altitude is above home, but there is no terrain data at home "
                                                                   "(tried: %2), so the height above sea level is unknown.")
                             : QCoreApplication::translate("TerrainRule", "%1: the altitude is above the ground, but there is no terrain data there "
                                                                   "(tried: %2), so the height above sea level is unknown."))
                           .arg(who, tried),
                       rowOf(route, int(i))});
        i = last + 1;
    }

    // Legs flown too close to the ground.
    for (const LowStretch &s : profile.lowStretches) {
        const double legStart = profile.path.vertexDistance[size_t(s.leg)];
        const double c = s.lowest.clearance;
        const QString how = c >= 0 ? QCoreApplication::translate("TerrainRule", "%1 m above the ground").arg(metres(c))
                                   : QCoreApplication::translate("TerrainRule", "%1 m below the ground").arg(metres(-c));
        const QString span = s.toDistance > s.fromDistance
                                 ? QCoreApplication::translate("TerrainRule", " (too low from %1 m to %2 m along it)").arg(metres(s.fromDistance - legStart),
                                                                                              metres(s.toDistance - legStart))
                                 : QString();
        out.push_back({Severity::Error, QStringLiteral("terrain-clearance"),
                       QCoreApplication::translate("TerrainRule", "%1 flies %2 at %3 m along it%4, closer than the safe distance of %5 m.")
                           .arg(legLabel(route, s.leg), how, metres(s.lowest.distanceAlongLeg), span, metres(route.safeDistance)),
                       rowOf(route, s.leg)});
    }

    // Legs flown higher above the surface than the limit: the highest point of each.
    std::optional<ClearancePoint> highest;
    auto reportHighest = [&] {
        if (!highest)
            return;
        out.push_back({Severity::Warning, QStringLiteral("terrain-above-surface-limit"),
                       QCoreApplication::translate("TerrainRule", "%1 flies up to %2 m above the ground at %3 m along it; "
                                                                  "the open category allows %4 m above the surface.")
                           .arg(legLabel(route, highest->leg), metres(highest->clearance), metres(highest->distanceAlongLeg),
                                metres(route.surfaceHeightLimit)),
                       rowOf(route, highest->leg)});
        highest.reset();
    };
    for (size_t i = 0; i < profile.size(); ++i) {
        const PathSamplePoint &p = profile.path.points[i];
        if (highest && highest->leg != p.leg)
            reportHighest();
        const double c = profile.clearance(i);
        if (!(c > route.surfaceHeightLimit) || (highest && c <= highest->clearance))
            continue;
        highest = ClearancePoint{p.leg, p.distance, p.distance - profile.path.vertexDistance[size_t(p.leg)], c};
    }
    reportHighest();

    // Stretches without data; a run over several whole legs is one issue.
    const auto &nd = profile.noData;
    for (size_t i = 0; i < nd.size();) {
        size_t last = i;
        while (last + 1 < nd.size() && nd[last + 1].leg == nd[last].leg + 1
               && nd[last].toDistance >= profile.path.vertexDistance[size_t(nd[last].leg) + 1] - 1e-6
               && nd[last + 1].fromDistance <= profile.path.vertexDistance[size_t(nd[last + 1].leg)] + 1e-6)
            ++last;
        const NoDataStretch &a = nd[i], &b = nd[last];
        const double aStart = profile.path.vertexDistance[size_t(a.leg)], bStart = profile.path.vertexDistance[size_t(b.leg)];
        QString where;
        if (last == i)
            where = QCoreApplication::translate("TerrainRule", "%1: no terrain data from %2 m to %3 m along it").arg(legLabel(route, a.leg),
                                                                                       metres(a.fromDistance - aStart), metres(a.toDistance - aStart));
        else
            where = QCoreApplication::translate("TerrainRule", "No terrain data from %1 m along %2 to %3 m along %4")
                        .arg(metres(a.fromDistance - aStart), legLabel(route, a.leg), metres(b.toDistance - bStart), legLabel(route, b.leg));
        out.push_back({Severity::Warning, QStringLiteral("terrain-no-data"),
                       QCoreApplication::translate("TerrainRule", "%1 (tried: %2); the clearance there is not checked.").arg(where, tried), rowOf(route, a.leg)});
        i = last + 1;
    }
    return out;
}

TerrainRule::TerrainRule(ElevationService *service, double step, QObject *parent)
    : RouteRule(parent), m_service(service), m_step(step)
{
    if (service)
        connect(service, &ElevationService::changed, this, &RouteRule::changed);
}

void TerrainRule::check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<ValidationIssue> &issues)
{
    if (!m_service)
        return;
    const ProfileRoute pr = profileRouteOf(route, cache);
    if (pr.waypoints.size() < 2)
        return;
    const TerrainProfile profile = computeProfile(pr, *m_service, m_step);
    const std::vector<ValidationIssue> found = terrainIssues(pr, profile);
    issues.insert(issues.end(), found.begin(), found.end());
}

} // namespace sortie::terrain
