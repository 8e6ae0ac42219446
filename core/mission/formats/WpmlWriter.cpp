// Writing a route as DJI WPML: the aircraft and payload checked, the plan printed, the KMZ packed.
#include "WpmlFormat.h"

#include "DjiDroneModels.h"
#include "Geodesy.h"
#include "ScanPlanCache.h"
#include "WpmlDocuments.h"
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
    }
    return {};
}

bool parseWpmlHeightMode(const QString &name, WpmlHeightMode *out)
{
    for (auto m : {WpmlHeightMode::RelativeToTakeoff, WpmlHeightMode::Egm96, WpmlHeightMode::AboveGroundLevel}) {
        if (wpmlHeightModeName(m).compare(name, Qt::CaseInsensitive) == 0) {
            *out = m;
            return true;
        }
    }
    return false;
}

Result<WpmlExport> writeWpml(const Route &route, const WpmlExportOptions &options, ScanPlanCache *cache)
{
    QStringList notices;
    const DjiDroneModel *model = options.drone.isEmpty() ? findDjiDroneModel(route.settings.profile.name) : findDjiDroneModel(options.drone);
    if (!model && options.drone.isEmpty()) {
        model = findDjiDroneModel(QStringLiteral("m350"));
        notices << (route.settings.profile.name.isEmpty()
                        ? QStringLiteral("written for the %1: the route names no DJI aircraft (--drone chooses)").arg(model->name)
                        : QStringLiteral("written for the %1: the route's vehicle profile \"%2\" is not a DJI aircraft")
                              .arg(model->name, route.settings.profile.name));
    }
    if (!model)
        return refuse(QStringLiteral("unknown DJI aircraft \"%1\" (known: %2)").arg(options.drone, djiDroneKeys()));
    const DjiPayload *payload = findDjiPayload(*model, options.payload);
    if (!payload)
        return refuse(QStringLiteral("the %1 carries no payload \"%2\"").arg(model->name, options.payload));
    if (options.heightMode == WpmlHeightMode::AboveGroundLevel && !model->followsSurface)
        return refuse(QStringLiteral("the %1 cannot follow the terrain in flight (realTimeFollowSurface); write heights relative to take-off or AMSL").arg(model->name));
    if (options.takeoffSecurityHeight < kWpmlMinTakeoffSecurityHeight || options.takeoffSecurityHeight > kWpmlMaxTakeoffSecurityHeight)
        return refuse(QStringLiteral("the take-off security height must be %1 to %2 m, not %3")
                          .arg(kWpmlMinTakeoffSecurityHeight).arg(kWpmlMaxTakeoffSecurityHeight).arg(options.takeoffSecurityHeight));
    ScanPlanCache local;
    Result<Plan> plan = planOf(route, options, *model, *payload, cache ? cache : &local);
    if (!plan)
        return plan.error();
    const Plan &p = *plan;
    if (!(p.points.front().speed > 0.0) || p.points.front().speed > model->maxWaypointSpeed)
        return refuse(QStringLiteral("the transit speed %1 m/s is outside 0 to %2 m/s").arg(p.points.front().speed).arg(model->maxWaypointSpeed));
    double distance = 0.0, duration = 0.0;
    for (size_t k = 1; k < p.points.size(); ++k) {
        const double d = geodesicDistance(p.points[k - 1].position, p.points[k].position);
        distance += d;
        duration += d / p.points[k].speed;
    }
    WpmlExport out;
    out.templateKml = templateOf(p, options, *model, *payload);
    out.waylinesWpml = waylinesOf(p, options, *model, *payload, distance, duration);
    const Result<QByteArray> zip = writeZip({{QStringLiteral("wpmz/template.kml"), out.templateKml},
                                            {QStringLiteral("wpmz/waylines.wpml"), out.waylinesWpml}});
    if (!zip)
        return zip.error();
    out.kmz = *zip;
    out.waypointCount = int(p.points.size());
    out.notices = notices + p.notices;
    return out;
}

} // namespace sortie::mission::formats
