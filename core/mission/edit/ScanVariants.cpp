#include "ScanVariants.h"

#include <QVariantList>

namespace sortie::mission {

QVariantMap scanParametersToVariant(const AreaScanParameters &p)
{
    return {
        {"cameraName", p.camera.name}, {"sensorWidthMm", p.camera.sensorWidthMm}, {"sensorHeightMm", p.camera.sensorHeightMm},
        {"focalLengthMm", p.camera.focalLengthMm}, {"imageWidthPx", p.camera.imageWidthPx}, {"imageHeightPx", p.camera.imageHeightPx},
        {"byGroundSampleDistance", p.heightMode == ScanHeightMode::GroundSampleDistance},
        {"altitude", scanAltitude(p)}, {"groundSampleDistanceCm", scanGroundSampleDistanceCm(p)},
        {"altitudeType", altitudeTypeName(p.altitudeType)}, {"frontOverlapPercent", p.frontOverlapPercent},
        {"sideOverlapPercent", p.sideOverlapPercent}, {"directionDeg", p.directionDeg},
        {"turnaroundMeters", p.turnaroundMeters}, {"speed", p.speed},
    };
}

bool applyScanVariant(AreaScanParameters &target, const QVariantMap &map)
{
    AreaScanParameters p = target;
    bool ok = true;
    auto number = [&](const char *key, double &field) {
        const auto it = map.constFind(QLatin1String(key));
        if (it == map.constEnd())
            return;
        bool good = false;
        const double v = it->toDouble(&good);
        ok &= good;
        if (good)
            field = v;
    };
    auto integer = [&](const char *key, int &field) {
        double v = field;
        number(key, v);
        field = int(v);
    };
    if (map.contains(QStringLiteral("cameraName")))
        p.camera.name = map.value(QStringLiteral("cameraName")).toString();
    number("sensorWidthMm", p.camera.sensorWidthMm);
    number("sensorHeightMm", p.camera.sensorHeightMm);
    number("focalLengthMm", p.camera.focalLengthMm);
    integer("imageWidthPx", p.camera.imageWidthPx);
    integer("imageHeightPx", p.camera.imageHeightPx);
    if (map.contains(QStringLiteral("byGroundSampleDistance")))
        p.heightMode = map.value(QStringLiteral("byGroundSampleDistance")).toBool() ? ScanHeightMode::GroundSampleDistance
                                                                                    : ScanHeightMode::Altitude;
    number("altitude", p.altitude);
    number("groundSampleDistanceCm", p.groundSampleDistanceCm);
    if (map.contains(QStringLiteral("altitudeType")))
        ok &= parseAltitudeType(map.value(QStringLiteral("altitudeType")).toString(), &p.altitudeType);
    number("frontOverlapPercent", p.frontOverlapPercent);
    number("sideOverlapPercent", p.sideOverlapPercent);
    number("directionDeg", p.directionDeg);
    number("turnaroundMeters", p.turnaroundMeters);
    number("speed", p.speed);
    if (!ok)
        return false;
    syncDerivedFields(p);
    target = p;
    return true;
}

QVariantMap scanPlanToVariant(const AreaScanOutcome &o)
{
    if (!o.ok())
        return {{"ok", false}, {"message", o.message}};
    const AreaScanPlan &p = *o.plan;
    QVariantList path;
    path.reserve(qsizetype(p.path.size()));
    for (const GeoPoint &g : p.path)
        path << QVariantMap{{"latitude", g.latitude}, {"longitude", g.longitude}};
    return {{"ok", true}, {"message", QString()}, {"transects", int(p.transects.size())}, {"cells", p.cells},
            {"photoCount", p.photoCount}, {"altitude", p.altitude}, {"groundSampleDistanceCm", p.groundSampleDistanceCm},
            {"transectSpacingMeters", p.transectSpacing}, {"triggerDistanceMeters", p.triggerDistance},
            {"pathLengthMeters", p.pathLength}, {"areaSquareMeters", p.areaSquareMeters}, {"path", path}};
}

} // namespace sortie::mission
