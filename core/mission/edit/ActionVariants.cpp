#include "ActionVariants.h"

namespace sortie::mission {

namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

double num(const QVariantMap &m, const char *key, double fallback)
{
    const auto it = m.constFind(QLatin1String(key));
    bool ok = false;
    const double v = it == m.constEnd() ? fallback : it->toDouble(&ok);
    return ok ? v : fallback;
}

const char *triggerName(TriggerState s)
{
    switch (s) {
    case TriggerState::SingleShot: return "singleShot";
    case TriggerState::StartRecording: return "startRecording";
    case TriggerState::StopRecording: return "stopRecording";
    case TriggerState::ToggleRecording: return "toggleRecording";
    }
    return "singleShot";
}
}

QVariantMap actionToVariant(const WaypointAction &action)
{
    QVariantMap m = std::visit(Overloaded{
        [](const WaitAction &a) { return QVariantMap{{"seconds", a.seconds}, {"waitForOperator", a.waitForOperator}}; },
        [](const HeadingAction &a) { return QVariantMap{{"headingDeg", a.headingDeg}, {"relativeToNextWaypoint", a.relativeToNextWaypoint}}; },
        [](const PoiAction &a) {
            return QVariantMap{{"latitude", a.position.latitude}, {"longitude", a.position.longitude},
                               {"altitude", a.altitude}, {"altitudeType", altitudeTypeName(a.altitudeType)}};
        },
        [](const CameraTriggerAction &a) { return QVariantMap{{"state", QString::fromLatin1(triggerName(a.state))}}; },
        [](const CameraSeriesByTimeAction &a) {
            return QVariantMap{{"intervalSeconds", a.intervalSeconds}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const CameraSeriesByDistanceAction &a) {
            return QVariantMap{{"intervalMeters", a.intervalMeters}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const PanoramaAction &a) {
            return QVariantMap{{"angleDeg", a.angleDeg}, {"stepAngleDeg", a.stepAngleDeg}, {"stepDelaySeconds", a.stepDelaySeconds},
                               {"clockwise", a.direction == RotationDirection::Clockwise},
                               {"rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond},
                               {"video", a.mode == PanoramaMode::Video}};
        },
        [](const OpaqueAction &a) { return QVariantMap{{"description", a.description}}; },
    }, action);
    m.insert(QStringLiteral("kind"), actionKindName(action));
    m.insert(QStringLiteral("summary"), describeAction(action));
    return m;
}

std::optional<WaypointAction> actionFromVariant(const QVariantMap &m)
{
    const QString kind = m.value(QStringLiteral("kind")).toString();
    if (kind == QLatin1String("wait"))
        return WaitAction{num(m, "seconds", 0), m.value(QStringLiteral("waitForOperator")).toBool()};
    if (kind == QLatin1String("heading"))
        return HeadingAction{num(m, "headingDeg", 0), m.value(QStringLiteral("relativeToNextWaypoint")).toBool()};
    if (kind == QLatin1String("poi")) {
        PoiAction a;
        a.position = {num(m, "latitude", 0), num(m, "longitude", 0)};
        a.altitude = num(m, "altitude", 0);
        parseAltitudeType(m.value(QStringLiteral("altitudeType"), QStringLiteral("AGL")).toString(), &a.altitudeType);
        return a;
    }
    if (kind == QLatin1String("cameraTrigger")) {
        CameraTriggerAction a;
        const QString s = m.value(QStringLiteral("state")).toString();
        for (TriggerState t : {TriggerState::SingleShot, TriggerState::StartRecording, TriggerState::StopRecording, TriggerState::ToggleRecording})
            if (s == QLatin1String(triggerName(t)))
                a.state = t;
        return a;
    }
    if (kind == QLatin1String("cameraSeriesByTime")) {
        CameraSeriesByTimeAction d;
        return CameraSeriesByTimeAction{num(m, "intervalSeconds", d.intervalSeconds), int(num(m, "shots", 0)), num(m, "startDelaySeconds", 0)};
    }
    if (kind == QLatin1String("cameraSeriesByDistance")) {
        CameraSeriesByDistanceAction d;
        return CameraSeriesByDistanceAction{num(m, "intervalMeters", d.intervalMeters), int(num(m, "shots", 0)), num(m, "startDelaySeconds", 0)};
    }
    if (kind == QLatin1String("panorama")) {
        PanoramaAction a;
        a.angleDeg = num(m, "angleDeg", a.angleDeg);
        a.stepAngleDeg = num(m, "stepAngleDeg", a.stepAngleDeg);
        a.stepDelaySeconds = num(m, "stepDelaySeconds", a.stepDelaySeconds);
        a.direction = m.value(QStringLiteral("clockwise"), true).toBool() ? RotationDirection::Clockwise : RotationDirection::CounterClockwise;
        a.rotationSpeedDegPerSecond = num(m, "rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond);
        a.mode = m.value(QStringLiteral("video")).toBool() ? PanoramaMode::Video : PanoramaMode::Photo;
        return a;
    }
    return std::nullopt;
}

} // namespace sortie::mission
