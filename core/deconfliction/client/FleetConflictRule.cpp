#include "FleetConflictRule.h"

#include "FleetRoutes.h"
#include "RoutePreparation.h"
#include "RouteTiming.h"

#include <QLocale>

#include <cmath>

namespace sortie::deconfliction {

using client::FleetRoute;
using client::FleetRouteState;

namespace {
constexpr int kProgressRecheckMs = 5000;

QString clockText(double seconds)
{
    const long s = std::lround(std::max(0.0, seconds));
    return s >= 60 ? QObject::tr("%1 min %2 s").arg(s / 60).arg(s % 60) : QObject::tr("%1 s").arg(s);
}

// The same timeline with every height 0: two routes whose frames differ are compared across only.
mission::RouteTimeline flattened(const mission::RouteTimeline &timeline)
{
    std::vector<mission::TimedLeg> legs = timeline.legs();
    for (mission::TimedLeg &leg : legs) {
        leg.fromAltitude = leg.toAltitude = 0;
        leg.heightChange = leg.takeoffClimb = leg.landingDescent = 0;
    }
    return mission::RouteTimeline(std::move(legs));
}

int rowOfLeg(const mission::RouteTimeline &timeline, int legNumber)
{
    for (const mission::TimedLeg &leg : timeline.legs())
        if (leg.leg == legNumber)
            return leg.toSegment >= 0 ? leg.toSegment : leg.fromSegment;
    return -1;
}
} // namespace

FleetConflictRule::FleetConflictRule(client::FleetRoutes *routes, client::RoutePreparation *preparation, QObject *parent)
    : RouteRule(parent)
    , m_routes(routes)
    , m_preparation(preparation)
{
    // A route uploaded, gone, starting or stopping to fly: check again. Progress alone moves every
    // second; that is checked on a slower beat while something flies.
    connect(routes, &QAbstractItemModel::rowsInserted, this, &RouteRule::changed);
    connect(routes, &QAbstractItemModel::rowsRemoved, this, &RouteRule::changed);
    connect(routes, &QAbstractItemModel::modelReset, this, &RouteRule::changed);
    connect(routes, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex &, const QModelIndex &, const QList<int> &roles) {
        if (roles.isEmpty() || roles.contains(client::FleetRoutes::StateRole)) {
            watchFlying();
            emit changed();
        }
    });
    if (preparation)
        connect(preparation, &client::RoutePreparation::vehicleIdChanged, this, &RouteRule::changed);
    connect(&m_progress, &QTimer::timeout, this, &RouteRule::changed);
    m_progress.setInterval(kProgressRecheckMs);
    watchFlying();
}

void FleetConflictRule::watchFlying()
{
    bool flying = false;
    if (m_routes) {
        for (const FleetRoute &r : m_routes->routes())
            flying = flying || r.state == FleetRouteState::Flying;
    }
    if (flying && !m_progress.isActive())
        m_progress.start();
    else if (!flying)
        m_progress.stop();
}

void FleetConflictRule::setSeparation(const Separation &separation)
{
    m_separation = separation;
    emit changed();
}

void FleetConflictRule::check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<mission::ValidationIssue> &issues)
{
    std::vector<FleetConflict> found;
    const auto publish = [this, &found] {
        m_conflicts = std::move(found);
        emit conflictsChanged();
    };
    if (!m_routes || route.segments.empty()) {
        publish();
        return;
    }
    const mission::Result<mission::RouteTimeline> own = mission::timeRoute(route, mission::timingOf(route.settings), cache);
    if (!own || own->legs().empty()) {
        publish();  // a route the time model cannot fly has its own issue for that
        return;
    }
    const QString chosen = m_preparation ? m_preparation->vehicleId() : QString();
    const std::vector<FleetRoute> routes = m_routes->routes();
    for (size_t row = 0; row < routes.size(); ++row) {
        const FleetRoute &other = routes[row];
        if (other.vehicleId == chosen || (other.state != FleetRouteState::Flying && other.state != FleetRouteState::Uploaded))
            continue;
        const mission::Result<mission::RouteTimeline> theirs = mission::timeRoute(other.route, mission::timingOf(other.route.settings));
        if (!theirs || theirs->legs().empty())
            continue;
        const bool flying = other.state == FleetRouteState::Flying;
        double flown = 0;
        if (flying && other.progress) {
            const double total = theirs->totalSeconds();
            if (std::isfinite(other.progress->remainingSeconds))
                flown = std::clamp(total - other.progress->remainingSeconds, 0.0, total);
            else if (std::isfinite(other.progress->elapsedSeconds))
                flown = std::clamp(other.progress->elapsedSeconds, 0.0, total);
        }
        const bool framesDiffer = own->legs().front().altitudeType != theirs->legs().front().altitudeType;
        const QString vehicleName = m_routes->index(int(row)).data(client::FleetRoutes::VehicleNameRole).toString();
        std::vector<ScheduledFlight> flights{
            {route.settings.name, framesDiffer ? flattened(*own) : *own, 0.0, 0.0, std::nullopt},
            {vehicleName, framesDiffer ? flattened(*theirs) : *theirs, 0.0, flown, std::nullopt}};
        ConflictQuery query;
        query.separation = m_separation;
        query.against = 0;
        for (const Conflict &c : findConflicts(flights, query).conflicts) {
            FleetConflict fc;
            fc.conflict = c;
            fc.otherVehicle = other.vehicleId;
            fc.otherName = vehicleName;
            fc.otherRoute = other.route.settings.name;
            fc.otherFlying = flying;
            fc.framesDiffer = framesDiffer;
            const QLocale locale;
            const QString whose = flying ? tr("%1, flying \"%2\" (its leg %3)").arg(vehicleName, fc.otherRoute).arg(c.secondAt.leg)
                                         : tr("%1's uploaded \"%2\" (its leg %3) if it starts now").arg(vehicleName, fc.otherRoute).arg(c.secondAt.leg);
            fc.message = tr("Leg %1 comes within %2 m across and %3 m in height of %4, %5 after the start%6.")
                             .arg(c.firstAt.leg)
                             .arg(locale.toString(c.horizontal, 'f', 0), locale.toString(c.vertical, 'f', 0), whose, clockText(c.time),
                                  framesDiffer ? tr(" (heights in different frames: judged across only)") : QString());
            issues.push_back({flying ? mission::Severity::Error : mission::Severity::Warning,
                              flying ? QStringLiteral("deconfliction-flying") : QStringLiteral("deconfliction-uploaded"), fc.message,
                              rowOfLeg(*own, c.firstAt.leg)});
            found.push_back(std::move(fc));
        }
    }
    publish();
}

} // namespace sortie::deconfliction
