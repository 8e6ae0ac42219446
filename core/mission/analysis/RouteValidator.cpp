#include "RouteValidator.h"

#include "AlgorithmCatalog.h"

#include "ScanPlanCache.h"
#include "SegmentPlanning.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <QCoreApplication>

namespace sortie::mission {

namespace {
constexpr double kDuplicateMeters = 0.1;
constexpr double kDuplicateAltitude = 0.01;

QString num(double v) { return QString::number(v, 'g', 8); }

// Equirectangular distance: plenty for "closer than 10 cm".
double nearDistance(const GeoPoint &a, const GeoPoint &b)
{
    constexpr double kMetersPerDegree = 111319.49;
    double dlon = std::abs(a.longitude - b.longitude);
    if (dlon > 180)
        dlon = 360 - dlon;
    const double x = dlon * kMetersPerDegree * std::cos(a.latitude * std::numbers::pi / 180.0);
    const double y = (a.latitude - b.latitude) * kMetersPerDegree;
    return std::hypot(x, y);
}

class Checker
{
public:
    Checker(const Route &route, ScanPlanCache *cache) : m_route(route), m_cache(cache) {}

    ValidationReport run()
    {
        const RouteSettings &rs = m_route.settings;
        int points = 0;
        int uncheckedAmsl = 0, firstUnchecked = -1;
        for (size_t i = 0; i < m_route.segments.size(); ++i) {
            const int row = int(i);
            const Segment &s = m_route.segments[i];
            if (const Waypoint *w = asWaypoint(s)) {
                ++points;
                if (!w->position.isValid() || !std::isfinite(w->altitude)) {
                    add(Severity::Error, "invalid-position", row, QCoreApplication::translate("RouteValidator", "%1: the position is not valid.").arg(label(row)));
                    continue;
                }
                if (!checkAltitude(row, w->altitude, w->altitudeType, w->role) && firstUnchecked < 0)
                    firstUnchecked = row;
                if (w->altitudeType == AltitudeType::Amsl && !rs.home)
                    ++uncheckedAmsl;
                checkSpeed(row, w->speed);
                checkNeighbour(row);
                continue;
            }
            const std::optional<AreaScan> planned = isAreaScan(s) ? scanOf(s) : std::nullopt;
            if (!planned) {
                checkAlgorithmSegment(row, std::get<AlgorithmSegment>(s));
                continue;
            }
            const AreaScan &scan = *planned;
            AreaScanOutcome scratch;
            const AreaScanOutcome &o = scanOutcome(scan, m_cache, scratch);
            if (o.ok()) {
                points += int(o.plan->path.size());
                const double alt = o.plan->altitude;
                if (!checkAltitude(row, alt, scan.parameters.altitudeType, WaypointRole::Pass) && firstUnchecked < 0)
                    firstUnchecked = row;
                if (scan.parameters.altitudeType == AltitudeType::Amsl && !rs.home)
                    ++uncheckedAmsl;
            } else if (o.problem == ScanProblem::SelfIntersecting) {
                add(Severity::Error, "scan-self-intersecting", row, QStringLiteral("%1: %2").arg(label(row), o.message));
            } else if (o.problem == ScanProblem::NoTransects || o.problem == ScanProblem::NoArea
                       || o.problem == ScanProblem::TooFewVertices) {
                add(Severity::Error, "scan-no-transects", row, QStringLiteral("%1: %2").arg(label(row), o.message));
            } else {
                add(Severity::Error, "scan-invalid", row, QStringLiteral("%1: %2").arg(label(row), o.message));
            }
            checkSpeed(row, scan.parameters.speed);
            checkNeighbour(row);
        }
        if (points < 2)
            m_report.issues.insert(m_report.issues.begin(), {Severity::Error, QStringLiteral("too-few-points"),
                QCoreApplication::translate("RouteValidator", "The route needs at least two points; it has %1.").arg(points), -1});
        if (uncheckedAmsl > 0)
            m_report.issues.insert(m_report.issues.begin(), {Severity::Warning, QStringLiteral("altitude-unchecked"),
                QCoreApplication::translate("RouteValidator", "%n AMSL altitude(s), the first at %1, were not checked against the "
                                            "route's limits: the take-off elevation is unknown.", nullptr, int(uncheckedAmsl))
                    .arg(label(firstUnchecked)),
                firstUnchecked});
        return std::move(m_report);
    }

private:
    QString label(int row) const { return segmentLabel(m_route, row); }

    void add(Severity sev, const char *rule, int row, QString message)
    {
        m_report.issues.push_back({sev, QString::fromLatin1(rule), std::move(message), row});
    }

    // Returns false when the altitude could not be compared with the limits.
    bool checkAltitude(int row, double altitude, AltitudeType type, WaypointRole role)
    {
        const RouteSettings &rs = m_route.settings;
        double agl = altitude;
        if (type == AltitudeType::Amsl) {
            if (!rs.home)
                return false;
            agl = altitude - rs.home->altitudeAmsl;  // above the take-off point
        }
        auto shown = [&] { return QStringLiteral("%1 m %2").arg(num(altitude), altitudeTypeName(type)); };
        // Says what was compared: the height above the take-off point, not above the ground under
        // the waypoint (the terrain rules judge that where the ground is known).
        if (agl > rs.maxAltitude)
            add(Severity::Error, "altitude-above-max", row,
                QCoreApplication::translate("RouteValidator", "%1: %2 m above the take-off point (altitude %3); the route's limit is %4 m above it.")
                    .arg(label(row), QString::number(agl, 'f', 1), shown(), num(rs.maxAltitude)));
        else if (agl < rs.safeAltitude && role == WaypointRole::Pass)
            add(Severity::Warning, "altitude-below-safe", row, QCoreApplication::translate("RouteValidator", "%1: altitude %2 is below the route's safe altitude of %3 m.")
                .arg(label(row), shown(), num(rs.safeAltitude)));
        return true;
    }

    void checkSpeed(int row, double speed)
    {
        const double limit = m_route.settings.profile.maxHorizontalSpeed;
        if (!(speed > 0))
            add(Severity::Error, "speed-not-positive", row, QCoreApplication::translate("RouteValidator", "%1: the speed must be positive.").arg(label(row)));
        else if (limit > 0 && speed > limit)
            add(Severity::Error, "speed-above-limit", row, QCoreApplication::translate("RouteValidator", "%1: speed %2 m/s is above the vehicle's limit of %3 m/s.")
                .arg(label(row), num(speed), num(limit)));
    }

    // A segment Sortie keeps as the server describes it: its values against the definition, its
    // figure against the points the tool needs. An algorithm no definition describes is kept and
    // flagged, not refused: the server decides.
    void checkAlgorithmSegment(int row, const AlgorithmSegment &a)
    {
        const AlgorithmDefinition *def = AlgorithmCatalog::builtIn().byClassName(a.algorithm);
        if (!def) {
            add(Severity::Warning, "unknown-algorithm", row,
                QCoreApplication::translate("RouteValidator", "%1: Sortie does not know the algorithm %2; the server checks it when it processes the route.")
                    .arg(label(row), a.algorithm));
            return;
        }
        // What the planner (the same one sortie-sim processes with) cannot plan, by parameter or point.
        const SegmentPlanOutcome o = planSegment(*def, plannerFigure(a), a.parameters, planContextOf(m_route.settings));
        for (const QString &problem : o.errors)
            add(Severity::Error, "segment-plan", row, QStringLiteral("%1: %2").arg(label(row), problem));
        if (o.ok())
            for (const QString &warning : o.plan->warnings)
                add(Severity::Warning, "segment-plan", row, QStringLiteral("%1: %2").arg(label(row), warning));
    }

    void checkNeighbour(int row)
    {
        if (row == 0)
            return;
        const Segment &prev = m_route.segments[row - 1], &cur = m_route.segments[row];
        const Waypoint *a = asWaypoint(prev), *b = asWaypoint(cur);
        if (a && b && a->altitudeType == b->altitudeType && nearDistance(a->position, b->position) < kDuplicateMeters
            && std::abs(a->altitude - b->altitude) < kDuplicateAltitude && a->role == b->role)
            add(Severity::Warning, "duplicate-waypoint", row, QCoreApplication::translate("RouteValidator", "%1 repeats %2.").arg(label(row), label(row - 1)));
        if (altitudeTypeOf(prev) != altitudeTypeOf(cur))
            add(Severity::Warning, "mixed-altitude-types", row,
                QCoreApplication::translate("RouteValidator", "%1 is %2 but %3 is %4: the climb between them is not estimated.")
                    .arg(label(row), altitudeTypeName(altitudeTypeOf(cur)), label(row - 1), altitudeTypeName(altitudeTypeOf(prev))));
    }

    const Route &m_route;
    ScanPlanCache *m_cache;
    ValidationReport m_report;
};
}

int ValidationReport::errorCount() const
{
    return int(std::count_if(issues.begin(), issues.end(), [](const ValidationIssue &i) { return i.severity == Severity::Error; }));
}

int ValidationReport::warningCount() const
{
    return int(issues.size()) - errorCount();
}

QString segmentLabel(const Route &route, int row)
{
    if (row < 0 || row >= int(route.segments.size()))
        return QCoreApplication::translate("RouteValidator", "The route");
    return segmentLabel(row, route.segments[size_t(row)]);
}

ValidationReport validateRoute(const Route &route, ScanPlanCache *cache)
{
    return Checker(route, cache).run();
}

} // namespace sortie::mission
