// Waypoint actions to and from the JSON of a .sortie file.
#include "SortieActionJson.h"

#include "ServerActions.h"

namespace sortie::mission::formats {
namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

const char *const kTriggers[] = {"singleShot", "startRecording", "stopRecording", "toggleRecording"};
} // namespace

Json actionJson(const WaypointAction &action)
{
    return std::visit(Overloaded{
        [](const WaitAction &a) { return Json{{"type", "wait"}, {"seconds", a.seconds}, {"waitForOperator", a.waitForOperator}}; },
        [](const HeadingAction &a) { return Json{{"type", "heading"}, {"headingDeg", a.headingDeg}, {"relativeToNextWaypoint", a.relativeToNextWaypoint}}; },
        [](const PoiAction &a) {
            return Json{{"type", "poi"}, {"latitude", a.position.latitude}, {"longitude", a.position.longitude},
                        {"altitude", a.altitude}, {"altitudeType", altitudeTypeName(a.altitudeType).toStdString()}};
        },
        [](const CameraTriggerAction &a) { return Json{{"type", "cameraTrigger"}, {"state", kTriggers[int(a.state)]}}; },
        [](const CameraSeriesByTimeAction &a) {
            return Json{{"type", "cameraSeriesByTime"}, {"intervalSeconds", a.intervalSeconds}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const CameraSeriesByDistanceAction &a) {
            return Json{{"type", "cameraSeriesByDistance"}, {"intervalMeters", a.intervalMeters}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const PanoramaAction &a) {
            return Json{{"type", "panorama"}, {"angleDeg", a.angleDeg}, {"stepAngleDeg", a.stepAngleDeg}, {"stepDelaySeconds", a.stepDelaySeconds},
                        {"clockwise", a.direction == RotationDirection::Clockwise}, {"rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond},
                        {"video", a.mode == PanoramaMode::Video}};
        },
        [](const CameraControlAction &a) {
            Json j{{"type", "cameraControl"}};  // a value not set has no key
            if (a.tiltDeg) j["tiltDeg"] = *a.tiltDeg;
            if (a.rollDeg) j["rollDeg"] = *a.rollDeg;
            if (a.yawDeg) j["yawDeg"] = *a.yawDeg;
            if (a.zoomLevel) j["zoomLevel"] = *a.zoomLevel;
            return j;
        },
        [](const ServerAction &a) {
            // The type keeps its first name; "description" is for whoever reads the file, the definition is the action.
            Json j{{"type", "opaque"}, {"description", describeAction(a).toStdString()}};
            j["hci"] = a.definition.toBase64().toStdString();
            return j;
        },
    }, action);
}

WaypointAction readAction(const JsonCursor &c)
{
    const QString type = c.at("type").string();
    if (type == QLatin1String("wait"))
        return WaitAction{c.number("seconds"), c.booleanOr("waitForOperator", false)};
    if (type == QLatin1String("heading"))
        return HeadingAction{c.number("headingDeg"), c.booleanOr("relativeToNextWaypoint", false)};
    if (type == QLatin1String("poi")) {
        PoiAction a{{c.number("latitude"), c.number("longitude")}, c.number("altitude"), AltitudeType::Agl};
        if (!parseAltitudeType(c.at("altitudeType").string(), &a.altitudeType))
            c.at("altitudeType").fail(QStringLiteral("expected \"AGL\" or \"AMSL\""));
        return a;
    }
    if (type == QLatin1String("cameraTrigger"))
        return CameraTriggerAction{TriggerState(indexOf(kTriggers, c.at("state")))};
    if (type == QLatin1String("cameraSeriesByTime"))
        return CameraSeriesByTimeAction{c.number("intervalSeconds"), c.integerOr("shots", 0), c.numberOr("startDelaySeconds", 0)};
    if (type == QLatin1String("cameraSeriesByDistance"))
        return CameraSeriesByDistanceAction{c.number("intervalMeters"), c.integerOr("shots", 0), c.numberOr("startDelaySeconds", 0)};
    if (type == QLatin1String("panorama")) {
        PanoramaAction a;
        a.angleDeg = c.number("angleDeg");
        a.stepAngleDeg = c.numberOr("stepAngleDeg", a.stepAngleDeg);
        a.stepDelaySeconds = c.numberOr("stepDelaySeconds", a.stepDelaySeconds);
        a.direction = c.booleanOr("clockwise", true) ? RotationDirection::Clockwise : RotationDirection::CounterClockwise;
        a.rotationSpeedDegPerSecond = c.numberOr("rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond);
        a.mode = c.booleanOr("video", false) ? PanoramaMode::Video : PanoramaMode::Photo;
        return a;
    }
    if (type == QLatin1String("cameraControl")) {
        CameraControlAction a;
        if (const auto v = c.find("tiltDeg")) a.tiltDeg = v->number();
        if (const auto v = c.find("rollDeg")) a.rollDeg = v->number();
        if (const auto v = c.find("yawDeg")) a.yawDeg = v->number();
        if (const auto v = c.find("zoomLevel")) a.zoomLevel = v->integer();
        return a;
    }
    if (type == QLatin1String("opaque")) {
        const auto h = c.find("hci");
        if (!h)
            c.fail(QStringLiteral("a server action needs its \"hci\" definition"));
        std::optional<ServerAction> action =
            serverActionFromBytes(QByteArray::fromBase64(h->string().toLatin1(), QByteArray::AbortOnBase64DecodingErrors));
        if (!action)
            h->fail(QStringLiteral("not a valid UgCS ActionDefinition"));
        return *action;
    }
    c.at("type").fail(QStringLiteral("unknown action type \"%1\"").arg(type));
}

} // namespace sortie::mission::formats
