#include "WaypointAction.h"

#include "ServerActions.h"

#include <QStringList>

namespace sortie::mission {

namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

QString number(double v) { return QString::number(v, 'g', 10); }
}

QString altitudeTypeName(AltitudeType type)
{
    return type == AltitudeType::Agl ? QStringLiteral("AGL") : QStringLiteral("AMSL");
}

bool parseAltitudeType(const QString &name, AltitudeType *out)
{
    if (name.compare(QLatin1String("AGL"), Qt::CaseInsensitive) == 0)
        *out = AltitudeType::Agl;
    else if (name.compare(QLatin1String("AMSL"), Qt::CaseInsensitive) == 0)
        *out = AltitudeType::Amsl;
    else
        return false;
    return true;
}

QString actionKindName(const WaypointAction &action)
{
    return std::visit(Overloaded{
        [](const WaitAction &) { return QStringLiteral("wait"); },
        [](const HeadingAction &) { return QStringLiteral("heading"); },
        [](const PoiAction &) { return QStringLiteral("poi"); },
        [](const CameraTriggerAction &) { return QStringLiteral("cameraTrigger"); },
        [](const CameraSeriesByTimeAction &) { return QStringLiteral("cameraSeriesByTime"); },
        [](const CameraSeriesByDistanceAction &) { return QStringLiteral("cameraSeriesByDistance"); },
        [](const PanoramaAction &) { return QStringLiteral("panorama"); },
        [](const CameraControlAction &) { return QStringLiteral("cameraControl"); },
        [](const ServerAction &a) {
            const ServerActionKind *kind = serverActionKindOf(a);
            return kind ? kind->kind : QStringLiteral("server");
        },
    }, action);
}

QString describeAction(const WaypointAction &action)
{
    return std::visit(Overloaded{
        [](const WaitAction &a) {
            return a.waitForOperator ? QStringLiteral("Wait for operator") : QStringLiteral("Wait %1 s").arg(number(a.seconds));
        },
        [](const HeadingAction &a) {
            return QStringLiteral("Heading %1°%2").arg(number(a.headingDeg),
                a.relativeToNextWaypoint ? QStringLiteral(" from course") : QString());
        },
        [](const PoiAction &a) {
            return QStringLiteral("Look at %1, %2").arg(number(a.position.latitude), number(a.position.longitude));
        },
        [](const CameraTriggerAction &a) {
            switch (a.state) {
            case TriggerState::SingleShot: return QStringLiteral("Take photo");
            case TriggerState::StartRecording: return QStringLiteral("Start video");
            case TriggerState::StopRecording: return QStringLiteral("Stop video");
            case TriggerState::ToggleRecording: return QStringLiteral("Toggle video");
            }
            return QString();
        },
        [](const CameraSeriesByTimeAction &a) { return QStringLiteral("Photo every %1 s").arg(number(a.intervalSeconds)); },
        [](const CameraSeriesByDistanceAction &a) {
            return a.intervalMeters > 0 ? QStringLiteral("Photo every %1 m").arg(number(a.intervalMeters))
                                        : QStringLiteral("Stop photos");
        },
        [](const PanoramaAction &a) { return QStringLiteral("Panorama %1°").arg(number(a.angleDeg)); },
        [](const CameraControlAction &a) {
            QStringList parts;
            if (a.tiltDeg) parts << QStringLiteral("tilt %1°").arg(number(*a.tiltDeg));
            if (a.rollDeg) parts << QStringLiteral("roll %1°").arg(number(*a.rollDeg));
            if (a.yawDeg) parts << QStringLiteral("yaw %1°").arg(number(*a.yawDeg));
            if (a.zoomLevel) parts << QStringLiteral("zoom %1").arg(*a.zoomLevel);
            return parts.isEmpty() ? QStringLiteral("Gimbal (nothing set)") : QStringLiteral("Gimbal ") + parts.join(QStringLiteral(", "));
        },
        [](const ServerAction &a) { return describeServerAction(a); },
    }, action);
}

QString describeActions(const std::vector<WaypointAction> &actions)
{
    QStringList parts;
    for (const auto &a : actions)
        parts << describeAction(a);
    return parts.join(QStringLiteral(" · "));
}

} // namespace sortie::mission
