#include "QgcSurveyJson.h"

#include "MavlinkMission.h"

#include <cmath>

namespace sortie::mission::formats {

namespace {
constexpr int kAltitudeModeAmsl = 2;  // QGroundControl's AltitudeMode: 1 relative, 2 AMSL, 3/4 terrain

Json simpleItem(int jumpId, int command, int frame, std::array<double, 7> params)
{
    Json p = Json::array();
    for (double v : params)
        p.push_back(v);
    return Json{{"autoContinue", true}, {"command", command}, {"doJumpId", jumpId}, {"frame", frame}, {"params", std::move(p)},
                {"type", "SimpleItem"}};
}
}

AreaScan surveyFromJson(const JsonCursor &item, QStringList *notices)
{
    AreaScan scan;
    const JsonCursor polygon = item.at("polygon");
    for (size_t i = 0; i < polygon.arraySize(); ++i) {
        const JsonCursor v = polygon.at(i);
        const GeoPoint g{v.at(size_t(0)).number(), v.at(size_t(1)).number()};
        if (!g.isValid())
            v.fail(QStringLiteral("latitude/longitude out of range"));
        scan.polygon.push_back(g);
    }
    if (scan.polygon.size() < 3)
        polygon.fail(QStringLiteral("a survey polygon needs at least 3 vertices, found %1").arg(scan.polygon.size()));
    AreaScanParameters &p = scan.parameters;
    p.directionDeg = item.numberOr("angle", 0);
    const JsonCursor transect = item.at("TransectStyleComplexItem");
    p.turnaroundMeters = transect.numberOr("TurnAroundDistance", 0);
    const JsonCursor cam = transect.at("CameraCalc");
    p.frontOverlapPercent = cam.number("FrontalOverlap");
    p.sideOverlapPercent = cam.number("SideOverlap");
    const double distance = cam.number("DistanceToSurface");
    bool amsl = false;
    if (const auto mode = cam.find("DistanceMode"))
        amsl = mode->integer() == kAltitudeModeAmsl;
    else
        amsl = !cam.booleanOr("DistanceToSurfaceRelative", true);
    p.altitudeType = amsl ? AltitudeType::Amsl : AltitudeType::Agl;
    if (cam.find("SensorWidth") && cam.find("FocalLength")) {
        p.camera.name = cam.stringOr("CameraName", QStringLiteral("Custom Camera"));
        p.camera.sensorWidthMm = cam.number("SensorWidth");
        p.camera.sensorHeightMm = cam.number("SensorHeight");
        p.camera.focalLengthMm = cam.number("FocalLength");
        p.camera.imageWidthPx = cam.at("ImageWidth").integer();
        p.camera.imageHeightPx = cam.at("ImageHeight").integer();
        if (!cam.booleanOr("Landscape", true)) {  // portrait: the image's height runs across the track
            std::swap(p.camera.sensorWidthMm, p.camera.sensorHeightMm);
            std::swap(p.camera.imageWidthPx, p.camera.imageHeightPx);
        }
    } else {
        // A "manual" camera gives only the footprints: make a camera with those footprints at that distance.
        const double side = cam.number("AdjustedFootprintSide"), frontal = cam.number("AdjustedFootprintFrontal");
        if (!(side > 0 && frontal > 0 && distance > 0))
            cam.fail(QStringLiteral("the survey's camera has neither a sensor nor footprints"));
        p.camera.name = cam.stringOr("CameraName", QStringLiteral("Manual"));
        p.camera.focalLengthMm = distance;
        p.camera.sensorWidthMm = side / (1 - p.sideOverlapPercent / 100.0);
        p.camera.sensorHeightMm = frontal / (1 - p.frontOverlapPercent / 100.0);
        p.camera.imageWidthPx = p.camera.imageHeightPx = 1000;
        if (notices)
            *notices << QStringLiteral("%1: the survey's manual camera was replaced by one with the same footprints").arg(cam.pathText());
    }
    if (cam.booleanOr("ValueSetIsDistance", true)) {
        p.heightMode = ScanHeightMode::Altitude;
        p.altitude = distance;
    } else {
        p.heightMode = ScanHeightMode::GroundSampleDistance;
        p.groundSampleDistanceCm = cam.number("ImageDensity");
    }
    syncDerivedFields(p);
    return scan;
}

Json surveyToJson(const AreaScan &scan, const AreaScanPlan &plan, int firstJumpId, int *itemsUsed)
{
    const AreaScanParameters &p = scan.parameters;
    const double across = footprintAcrossMeters(p), along = footprintAlongMeters(p);
    Json polygon = Json::array();
    for (const GeoPoint &g : scan.polygon)
        polygon.push_back({g.latitude, g.longitude});
    const int frame = p.altitudeType == AltitudeType::Amsl ? mav::Global : mav::GlobalRelativeAlt;
    Json items = Json::array();
    Json visual = Json::array();
    int id = firstJumpId;
    // Trigger by distance over the whole survey, turnarounds included, then stop.
    items.push_back(simpleItem(id++, mav::DoSetCamTriggDist, mav::Mission, {plan.triggerDistance, 0, 1, 0, 0, 0, 0}));
    for (const GeoPoint &g : plan.path)
        items.push_back(simpleItem(id++, mav::NavWaypoint, frame, {0, 0, 0, 0, g.latitude, g.longitude, plan.altitude}));
    items.push_back(simpleItem(id++, mav::DoSetCamTriggDist, mav::Mission, {0, 0, 0, 0, 0, 0, 0}));
    for (const Transect &t : plan.transects) {
        visual.push_back({t.start.latitude, t.start.longitude});
        visual.push_back({t.end.latitude, t.end.longitude});
    }
    *itemsUsed = id - firstJumpId;
    const Json camera{
        {"AdjustedFootprintFrontal", along * (1 - p.frontOverlapPercent / 100.0)},
        {"AdjustedFootprintSide", across * (1 - p.sideOverlapPercent / 100.0)},
        {"CameraName", p.camera.name.toStdString()}, {"DistanceToSurface", plan.altitude},
        {"DistanceToSurfaceRelative", p.altitudeType == AltitudeType::Agl}, {"FixedOrientation", false},
        {"FocalLength", p.camera.focalLengthMm}, {"FrontalOverlap", p.frontOverlapPercent}, {"ImageDensity", plan.groundSampleDistanceCm},
        {"ImageHeight", p.camera.imageHeightPx}, {"ImageWidth", p.camera.imageWidthPx}, {"Landscape", true}, {"MinTriggerInterval", 0},
        {"SensorHeight", p.camera.sensorHeightMm}, {"SensorWidth", p.camera.sensorWidthMm}, {"SideOverlap", p.sideOverlapPercent},
        {"ValueSetIsDistance", p.heightMode == ScanHeightMode::Altitude}, {"version", 1}};
    return Json{
        {"TransectStyleComplexItem", {{"CameraCalc", camera}, {"CameraShots", plan.photoCount}, {"CameraTriggerInTurnAround", true},
                                      {"FollowTerrain", false}, {"HoverAndCapture", false}, {"Items", std::move(items)},
                                      {"Refly90Degrees", false}, {"TurnAroundDistance", p.turnaroundMeters},
                                      {"VisualTransectPoints", std::move(visual)}, {"version", 1}}},
        {"angle", p.directionDeg}, {"complexItemType", "survey"}, {"entryLocation", 0}, {"flyAlternateTransects", false},
        {"polygon", std::move(polygon)}, {"splitConcavePolygons", false}, {"type", "ComplexItem"}, {"version", 5}};
}

} // namespace sortie::mission::formats
