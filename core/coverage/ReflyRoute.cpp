#include "ReflyRoute.h"

#include "AreaScanPlanner.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace sortie::coverage {

ReflyOptions reflyOptionsFor(const CoverageReport &report, const mission::Camera &camera)
{
    ReflyOptions options;
    options.camera = camera;
    auto measured = [](const std::optional<Spread> &s) { return s && s->count > 0; };
    if (measured(report.heightAboveGround))
        options.heightAboveGround = std::round(report.heightAboveGround->p50);
    if (measured(report.forwardOverlap))
        options.frontOverlapPercent = std::clamp(std::round(report.forwardOverlap->p50), 50.0, 95.0);
    if (measured(report.sideOverlap))
        options.sideOverlapPercent = std::clamp(std::round(report.sideOverlap->p50), 30.0, 95.0);
    options.legBearing = report.legBearing;
    return options;
}

std::optional<mission::Route> reflyRoute(const std::vector<Hole> &holes, const ReflyOptions &options, QStringList *notes)
{
    mission::Route route;
    route.settings.name = QCoreApplication::translate("Coverage", "Re-fly the gaps");
    route.settings.initialSpeed = options.speed;
    route.settings.maxAltitude = std::max(route.settings.maxAltitude, options.heightAboveGround);
    route.settings.safeAltitude = std::min(route.settings.safeAltitude, options.heightAboveGround);
    for (size_t i = 0; i < holes.size(); ++i) {
        const Hole &hole = holes[i];
        mission::AreaScan scan;
        for (size_t k = 0; k + 1 < hole.scanRing.size(); ++k) // the ring is closed; a scan's polygon is not
            scan.polygon.push_back({hole.scanRing[k].second, hole.scanRing[k].first});
        mission::AreaScanParameters &p = scan.parameters;
        p.camera = options.camera;
        p.heightMode = mission::ScanHeightMode::Altitude;
        p.altitude = options.heightAboveGround;
        p.altitudeType = mission::AltitudeType::Agl;
        p.frontOverlapPercent = options.frontOverlapPercent;
        p.sideOverlapPercent = options.sideOverlapPercent;
        p.speed = options.speed;
        if (options.legBearing)
            p.directionDeg = *options.legBearing;
        mission::syncDerivedFields(p);
        const mission::AreaScanOutcome planned = mission::planAreaScan(scan);
        if (!planned.ok()) {
            if (notes)
                *notes << QCoreApplication::translate("Coverage", "The hole of %1 m² at %2, %3 is not in the route: %4")
                              .arg(std::lround(hole.areaSquareMeters))
                              .arg(hole.centreLatitude, 0, 'f', 6)
                              .arg(hole.centreLongitude, 0, 'f', 6)
                              .arg(planned.message);
            continue;
        }
        route.segments.push_back(std::move(scan));
    }
    if (route.segments.empty())
        return std::nullopt;
    return route;
}

} // namespace sortie::coverage
