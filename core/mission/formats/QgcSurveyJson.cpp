#include "QgcSurveyJson.h"

#include "AlgorithmCatalog.h"
#include "MavlinkMission.h"
#include "Photogrammetry.h"

#include <cmath>
#include <QCoreApplication>

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
            v.fail(QCoreApplication::translate("QgcSurveyJson", "latitude/longitude out of range"));
        scan.polygon.push_back(g);
    }
    if (scan.polygon.size() < 3)
        polygon.fail(QCoreApplication::translate("QgcSurveyJson", "a survey polygon needs at least 3 vertices, found %1").arg(scan.polygon.size()));
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
        p.camera.name = cam.stringOr("CameraName", QCoreApplication::translate("QgcSurveyJson", "Custom Camera"));
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
            cam.fail(QCoreApplication::translate("QgcSurveyJson", "the survey's camera has neither a sensor nor footprints"));
        p.camera.name = cam.stringOr("CameraName", QStringLiteral("Manual"));
        p.camera.focalLengthMm = distance;
        p.camera.sensorWidthMm = side / (1 - p.sideOverlapPercent / 100.0);
        p.camera.sensorHeightMm = frontal / (1 - p.frontOverlapPercent / 100.0);
        p.camera.imageWidthPx = p.camera.imageHeightPx = 1000;
        if (notices)
            *notices << QCoreApplication::translate("QgcSurveyJson", "%1: the survey's manual camera was replaced by one with the same footprints").arg(cam.pathText());
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

namespace {
QString number(double v) { return parameterNumberText(v); }

std::vector<FigurePoint> pointsAt(const JsonCursor &list, size_t minimum, const char *what)
{
    std::vector<FigurePoint> points;
    for (size_t i = 0; i < list.arraySize(); ++i) {
        const JsonCursor v = list.at(i);
        const GeoPoint g{v.at(size_t(0)).number(), v.at(size_t(1)).number()};
        if (!g.isValid())
            v.fail(QCoreApplication::translate("QgcSurveyJson", "latitude/longitude out of range"));
        points.push_back({g, 0.0, AltitudeType::Agl});
    }
    if (points.size() < minimum)
        list.fail(QCoreApplication::translate("QgcSurveyJson", "a %1 needs at least %2 points, found %3").arg(QCoreApplication::translate("QgcSurveyJson", what)).arg(minimum).arg(points.size()));
    return points;
}

// CameraCalc -> photogrammetry's camera, GSD, overlaps and altitude type.
void cameraCalcInto(const JsonCursor &cam, AlgorithmSegment &a, QStringList *notices)
{
    const QString name = cam.stringOr("CameraName", QString());
    const bool amsl = cam.find("DistanceMode") ? cam.at("DistanceMode").integer() == kAltitudeModeAmsl
                                               : !cam.booleanOr("DistanceToSurfaceRelative", true);
    a.setValue(QStringLiteral("altitudeType"), amsl ? QStringLiteral("AMSL") : QStringLiteral("AGL"));
    a.setValue(QStringLiteral("overlapForward"), number(cam.number("FrontalOverlap")));
    a.setValue(QStringLiteral("overlapSide"), number(cam.number("SideOverlap")));
    std::optional<Camera> camera = builtInCamera(name);
    if (!camera && cam.find("SensorWidth") && cam.find("FocalLength")) {
        camera = Camera{name, cam.number("SensorWidth"), cam.number("SensorHeight"), cam.number("FocalLength"),
                        cam.at("ImageWidth").integer(), cam.at("ImageHeight").integer(), 0.0};
        if (notices)
            *notices << QCoreApplication::translate("QgcSurveyJson", "%1: the camera \"%2\" is not one Sortie knows; it is kept by name, and the server must know it.")
                            .arg(cam.pathText(), name);
    }
    if (!name.isEmpty())
        a.setValue(QStringLiteral("camera"), name);
    const bool byDistance = cam.booleanOr("ValueSetIsDistance", true);
    if (!byDistance)
        a.setValue(QStringLiteral("groundSampleDistance"), number(cam.number("ImageDensity")));
    else if (camera && camera->isValid())
        a.setValue(QStringLiteral("groundSampleDistance"), number(photogrammetry::gsdAtHeight(*camera, cam.number("DistanceToSurface"))));
    else
        cam.fail(QCoreApplication::translate("QgcSurveyJson", "the corridor's camera has no sensor to turn its distance into a ground sample distance"));
    a.setValue(QStringLiteral("camTopFacingForward"), cam.booleanOr("Landscape", true) ? QStringLiteral("true") : QStringLiteral("false"));
}
} // namespace

AlgorithmSegment corridorFromJson(const JsonCursor &item, QStringList *notices)
{
    AlgorithmSegment a;
    a.algorithm = algorithmClassName(AlgorithmKind::Corridor);
    a.figure = FigureType::Polyline;
    a.points = pointsAt(item.at("polyline"), 2, QT_TRANSLATE_NOOP("QgcSurveyJson", "corridor centre line"));
    a.setValue(QStringLiteral("width"), number(item.number("CorridorWidth")));
    cameraCalcInto(item.at("TransectStyleComplexItem").at("CameraCalc"), a, notices);
    return a;
}

Json corridorToJson(const AlgorithmSegment &corridor, const SegmentPlan &plan, int firstJumpId, int *itemsUsed)
{
    const ParameterReader read(*AlgorithmCatalog::builtIn().byKind(AlgorithmKind::Corridor), corridor.parameters);
    const bool amsl = read.selection(u"altitudeType") == QLatin1String("AMSL");
    const int frame = amsl ? mav::Global : mav::GlobalRelativeAlt;
    Json polyline = Json::array();
    for (const FigurePoint &p : corridor.points)
        polyline.push_back({p.position.latitude, p.position.longitude});
    Json items = Json::array();
    int id = firstJumpId;
    items.push_back(simpleItem(id++, mav::DoSetCamTriggDist, mav::Mission, {plan.triggerDistance, 0, 1, 0, 0, 0, 0}));
    for (const PlannedPoint &p : plan.points)
        items.push_back(simpleItem(id++, mav::NavWaypoint, frame, {0, 0, 0, 0, p.position.latitude, p.position.longitude, p.height}));
    items.push_back(simpleItem(id++, mav::DoSetCamTriggDist, mav::Mission, {0, 0, 0, 0, 0, 0, 0}));
    *itemsUsed = id - firstJumpId;
    const Camera camera = plan.camera.value_or(Camera{});
    const Json cameraCalc{
        {"AdjustedFootprintFrontal", plan.triggerDistance}, {"AdjustedFootprintSide", plan.passSpacing},
        {"CameraName", camera.name.toStdString()}, {"DistanceToSurface", plan.height}, {"DistanceToSurfaceRelative", !amsl},
        {"FixedOrientation", false}, {"FocalLength", camera.focalLengthMm}, {"FrontalOverlap", read.number(u"overlapForward", 60)},
        {"ImageDensity", plan.gsdCm}, {"ImageHeight", camera.imageHeightPx}, {"ImageWidth", camera.imageWidthPx},
        {"Landscape", read.boolean(u"camTopFacingForward", true)}, {"MinTriggerInterval", camera.minTriggerIntervalS},
        {"SensorHeight", camera.sensorHeightMm}, {"SensorWidth", camera.sensorWidthMm}, {"SideOverlap", read.number(u"overlapSide", 30)},
        {"ValueSetIsDistance", false}, {"version", 1}};
    return Json{
        {"CorridorWidth", read.number(u"width", 30)}, {"EntryPoint", 0},
        {"TransectStyleComplexItem", {{"CameraCalc", cameraCalc}, {"CameraShots", plan.photos}, {"CameraTriggerInTurnAround", true},
                                      {"FollowTerrain", false}, {"HoverAndCapture", false}, {"Items", std::move(items)},
                                      {"Refly90Degrees", false}, {"TurnAroundDistance", 0}, {"VisualTransectPoints", Json::array()},
                                      {"version", 1}}},
        {"complexItemType", "CorridorScan"}, {"polyline", std::move(polyline)}, {"type", "ComplexItem"}, {"version", 2}};
}

AlgorithmSegment structureScanFromJson(const JsonCursor &item, QStringList *notices)
{
    AlgorithmSegment a;
    a.algorithm = algorithmClassName(AlgorithmKind::Perimeter);
    a.figure = FigureType::Polygon;
    a.points = pointsAt(item.at("polygon"), 3, QT_TRANSLATE_NOOP("QgcSurveyJson", "structure polygon"));
    const JsonCursor cam = item.at("CameraCalc");
    const bool amsl = cam.find("DistanceMode") ? cam.at("DistanceMode").integer() == kAltitudeModeAmsl
                                               : !cam.booleanOr("DistanceToSurfaceRelative", true);
    a.setValue(QStringLiteral("height"), number(item.number("Altitude")));
    a.setValue(QStringLiteral("heightAgl"), amsl ? QStringLiteral("false") : QStringLiteral("true"));
    const int layers = std::max(1, item.integerOr("Layers", 1));
    a.setValue(QStringLiteral("loops"), QString::number(layers));
    if (notices)
        *notices << QCoreApplication::translate("QgcSurveyJson", "%1: the structure scan became a perimeter flight at %2 m%3.")
                        .arg(item.pathText(), number(item.number("Altitude")),
                             layers > 1 ? QCoreApplication::translate("QgcSurveyJson", ", its %1 layers as %1 loops at one height").arg(layers) : QString());
    return a;
}

} // namespace sortie::mission::formats
