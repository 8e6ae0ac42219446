// Writing a route as DJI WPML: the aircraft and payload checked, the plan printed, the KMZ packed.
#include "WpmlFormat.h"

#include "DjiDroneModels.h"
#include "Egm96Geoid.h"
#include "Geodesy.h"
#include "ScanPlanCache.h"
#include "NumberText.h"
#include "WpmlDocuments.h"
#include "WpmlGeoidAccess.h"
#include "WpmlPlan.h"
#include "ZipArchive.h"

namespace sortie::mission::formats {

using namespace wpml;

QString wpmlHeightModeName(WpmlHeightMode mode)
{
    switch (mode) {
    case WpmlHeightMode::RelativeToTakeoff: return QStringLiteral("relative");
    case WpmlHeightMode::Egm96: return QStringLiteral("amsl");
    case WpmlHeightMode::AboveGroundLevel: return QStringLiteral("agl");
    case WpmlHeightMode::Wgs84: return QStringLiteral("wgs84");
    }
    return {};
}

bool parseWpmlHeightMode(const QString &name, WpmlHeightMode *out)
{
    for (auto m : {WpmlHeightMode::RelativeToTakeoff, WpmlHeightMode::Egm96, WpmlHeightMode::AboveGroundLevel, WpmlHeightMode::Wgs84}) {
        if (wpmlHeightModeName(m).compare(name, Qt::CaseInsensitive) == 0) {
            *out = m;
            return true;
        }
    }
    return false;
}

namespace {

QString routeText(const Route &route, size_t index, size_t count)
{
    return count == 1 ? QStringLiteral("the route") : QStringLiteral("route %1 (\"%2\")").arg(index + 1).arg(route.settings.name);
}

// wpml:takeOffRefPoint of the first route: where it takes off (its home, else the climb point) and
// the take-off's AMSL altitude as an ellipsoidal height. Empty, with a notice, where the geoid is
// missing: the file is still right without it.
QString takeOffRefPoint(const Route &route, const WpmlExportOptions &o, GeoidAccess *geoid, QStringList *notices)
{
    const std::optional<double> amsl = takeoffAltitude(o, route);
    const std::optional<GeoPoint> where = route.settings.home ? std::optional<GeoPoint>(route.settings.home->position) : o.climbOver;
    if (!amsl || !where)
        return {};
    const Result<const datum::Egm96Geoid *> g = geoid->get(QStringLiteral("the take-off point (wpml:takeOffRefPoint) is not written"));
    if (!g) {
        *notices << g.error().message;
        return {};
    }
    const auto h = (*g)->ellipsoidalFromAmsl(where->latitude, where->longitude, *amsl);
    if (!h)
        return {};
    return QStringLiteral("%1,%2,%3").arg(QString::fromLatin1(shortestNumber(where->latitude)), QString::fromLatin1(shortestNumber(where->longitude)),
                                          QString::number(*h, 'f', 3));
}

} // namespace

Result<WpmlExport> writeWpml(const Route &route, const WpmlExportOptions &options, ScanPlanCache *cache)
{
    return writeWpml(std::vector<const Route *>{&route}, options, cache);
}

Result<WpmlExport> writeWpml(const std::vector<const Route *> &routes, const WpmlExportOptions &options, ScanPlanCache *cache)
{
    QStringList notices;
    if (routes.empty())
        return refuse(QStringLiteral("no route to write"));
    const Route &first = *routes.front();
    const DjiDroneModel *model = options.drone.isEmpty() ? findDjiDroneModel(first.settings.profile.name) : findDjiDroneModel(options.drone);
    if (!model && options.drone.isEmpty()) {
        model = findDjiDroneModel(QStringLiteral("m350"));
        notices << (first.settings.profile.name.isEmpty()
                        ? QStringLiteral("written for the %1: the route names no DJI aircraft (--drone chooses)").arg(model->name)
                        : QStringLiteral("written for the %1: the route's vehicle profile \"%2\" is not a DJI aircraft")
                              .arg(model->name, first.settings.profile.name));
    }
    if (!model)
        return refuse(QStringLiteral("unknown DJI aircraft \"%1\" (known: %2)").arg(options.drone, djiDroneKeys()));
    if (options.drone.isEmpty())
        for (size_t r = 1; r < routes.size(); ++r)
            if (const DjiDroneModel *other = findDjiDroneModel(routes[r]->settings.profile.name); other && other != model)
                return refuse(QStringLiteral("%1 is planned for the %2 and route 1 for the %3: one file flies one aircraft (--drone chooses)")
                                  .arg(routeText(*routes[r], r, routes.size()), other->name, model->name));
    const DjiPayload *payload = findDjiPayload(*model, options.payload);
    if (!payload)
        return refuse(QStringLiteral("the %1 carries no payload \"%2\"").arg(model->name, options.payload));
    if (options.heightMode == WpmlHeightMode::AboveGroundLevel && !model->followsSurface)
        return refuse(QStringLiteral("the %1 cannot follow the terrain in flight (realTimeFollowSurface); write heights relative to take-off or AMSL").arg(model->name));
    if (options.takeoffSecurityHeight < kWpmlMinTakeoffSecurityHeight || options.takeoffSecurityHeight > kWpmlMaxTakeoffSecurityHeight)
        return refuse(QStringLiteral("the take-off security height must be %1 to %2 m, not %3")
                          .arg(kWpmlMinTakeoffSecurityHeight).arg(kWpmlMaxTakeoffSecurityHeight).arg(options.takeoffSecurityHeight));
    ScanPlanCache local;
    GeoidAccess geoid(options.geoid);
    std::vector<Plan> plans;
    plans.reserve(routes.size());
    for (size_t r = 0; r < routes.size(); ++r) {
        Result<Plan> plan = planOf(*routes[r], options, *model, *payload, cache ? cache : &local, &geoid);
        if (!plan)
            return routes.size() == 1 ? plan.error()
                                      : refuse(QStringLiteral("%1: %2").arg(routeText(*routes[r], r, routes.size()), plan.error().message.mid(QStringLiteral("DJI WPML: ").size())));
        // One finish action ends the file: only the last wayline may return home or land.
        if (r + 1 < routes.size() && plan->finish != FinishAction::NoAction)
            return refuse(QStringLiteral("%1 ends by %2, but a WPML file has one finish action, after its last wayline")
                              .arg(routeText(*routes[r], r, routes.size()),
                                   plan->finish == FinishAction::AutoLand ? QStringLiteral("landing") : QStringLiteral("returning home")));
        if (r > 0 && plan->points.front().speed != plans.front().points.front().speed)
            notices << QStringLiteral("%1: the flight to its first waypoint is at the file's transitional speed, %2 m/s")
                           .arg(routeText(*routes[r], r, routes.size())).arg(plans.front().points.front().speed);
        for (const QString &n : plan->notices)
            notices << (routes.size() == 1 ? n : routeText(*routes[r], r, routes.size()) + QStringLiteral(": ") + n);
        plans.push_back(std::move(plan).value());
    }
    if (!(plans.front().points.front().speed > 0.0) || plans.front().points.front().speed > model->maxWaypointSpeed)
        return refuse(QStringLiteral("the transit speed %1 m/s is outside 0 to %2 m/s").arg(plans.front().points.front().speed).arg(model->maxWaypointSpeed));
    wpml::Mission mission;
    int waypoints = 0;
    for (const Plan &p : plans) {
        double distance = 0.0, duration = 0.0;
        for (size_t k = 1; k < p.points.size(); ++k) {
            const double d = geodesicDistance(p.points[k - 1].position, p.points[k].position);
            distance += d;
            duration += d / p.points[k].speed;
        }
        mission.waylines.push_back({&p, distance, duration});
        waypoints += int(p.points.size());
    }
    mission.takeOffRefPoint = takeOffRefPoint(first, options, &geoid, &notices);
    WpmlExport out;
    out.templateKml = templateOf(mission, options, *model, *payload);
    out.waylinesWpml = waylinesOf(mission, options, *model, *payload);
    const Result<QByteArray> zip = writeZip({{QStringLiteral("wpmz/template.kml"), out.templateKml},
                                            {QStringLiteral("wpmz/waylines.wpml"), out.waylinesWpml}});
    if (!zip)
        return zip.error();
    out.kmz = *zip;
    out.waypointCount = waypoints;
    out.notices = notices;
    return out;
}

} // namespace sortie::mission::formats
