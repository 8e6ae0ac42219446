#include "WaypointAction.h"

#include "ServerActions.h"

#include <QStringList>
#include <QCoreApplication>

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
            return a.waitForOperator ? QCoreApplication::translate("WaypointAction", "Wait for operator") : QCoreApplication::translate("WaypointAction", "Wait %1 s").arg(number(a.seconds));
        },
        [](const HeadingAction &a) {
            return QCoreApplication::translate("WaypointAction", "Heading %1°%2").arg(number(a.headingDeg),
                a.relativeToNextWaypoint ? QCoreApplication::translate("WaypointAction", " from course") : QString());
        },
        [](const PoiAction &a) {
            return QCoreApplication::translate("WaypointAction", "Look at %1, %2").arg(number(a.position.latitude), number(a.position.longitude));
        },
        [](const CameraTriggerAction &a) {
            switch (a.state) {
            case TriggerState::SingleShot: return QCoreApplication::translate("WaypointAction", "Take photo");
            case TriggerState::StartRecording: return QCoreApplication::translate("WaypointAction", "Start video");
            case TriggerState::StopRecording: return QCoreApplication::translate("WaypointAction", "Stop video");
            case TriggerState::ToggleRecording: return QCoreApplication::translate("WaypointAction", "Toggle video");
            }
            return QString();
        },
        [](const CameraSeriesByTimeAction &a) { return QCoreApplication::translate("WaypointAction", "Photo every %1 s").arg(number(a.intervalSeconds)); },
        [](const CameraSeriesByDistanceAction &a) {
            return a.intervalMeters > 0 ? QCoreApplication::translate("WaypointAction", "Photo every %1 m").arg(number(a.intervalMeters))
                                        : QCoreApplication::translate("WaypointAction", "Stop photos");
        },
        [](const PanoramaAction &a) { return QCoreApplication::translate("WaypointAction", "Panorama %1°").arg(number(a.angleDeg)); },
        [](const CameraControlAction &a) {
            QStringList parts;
            if (a.tiltDeg) parts << QCoreApplication::translate("WaypointAction", "tilt %1°").arg(number(*a.tiltDeg));
            if (a.rollDeg) parts << QCoreApplication::translate("WaypointAction", "roll %1°").arg(number(*a.rollDeg));
            if (a.yawDeg) parts << QCoreApplication::translate("WaypointAction", "yaw %1°").arg(number(*a.yawDeg));
            if (a.zoomLevel) parts << QCoreApplication::translate("WaypointAction", "zoom %1").arg(*a.zoomLevel);
            return parts.isEmpty() ? QCoreApplication::translate("WaypointAction", "Gimbal (nothing set)") : QStringLiteral("Gimbal ") + parts.join(QStringLiteral(", "));
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
