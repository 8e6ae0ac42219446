#include "VciMissionActions.h"

#include <numbers>

namespace sortie::vehicle {

using namespace sortie::mission;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

MissionError missionError(const QString &message)
{
    MissionError e;
    e.message = message;
    return e;
}

QString triggerName(TriggerState state)
{
    switch (state) {
    case TriggerState::SingleShot: return QStringLiteral("single");
    case TriggerState::StartRecording: return QStringLiteral("start_recording");
    case TriggerState::StopRecording: return QStringLiteral("stop_recording");
    case TriggerState::ToggleRecording: return QStringLiteral("toggle_recording");
    }
    return {};
}

} // namespace

// The action in the VCI profile's words, or an error for the operator.
Result<MissionAction> vciAction(const WaypointAction &action)
{
    struct Visitor
    {
        Result<MissionAction> operator()(const WaitAction &a) const
        {
            if (a.waitForOperator)
                return missionError(QStringLiteral("a wait for the operator has no VCI form (a vehicle flying alone cannot be released)"));
            return MissionAction{QStringLiteral("wait"), {{QStringLiteral("seconds"), a.seconds}}};
        }
        Result<MissionAction> operator()(const HeadingAction &a) const
        {
            return MissionAction{QStringLiteral("heading"), {{QStringLiteral("heading"), a.headingDeg * kRad},
                                                             {QStringLiteral("relativeToNext"), a.relativeToNextWaypoint}}};
        }
        Result<MissionAction> operator()(const PoiAction &a) const
        {
            if (a.altitudeType != AltitudeType::Agl)
                return missionError(QStringLiteral("a point of interest with an AMSL altitude has no VCI form (altitudes are above home)"));
            return MissionAction{QStringLiteral("poi"), {{QStringLiteral("latitude"), a.position.latitude * kRad},
                                                         {QStringLiteral("longitude"), a.position.longitude * kRad},
                                                         {QStringLiteral("altitude"), a.altitude}}};
        }
        Result<MissionAction> operator()(const CameraTriggerAction &a) const
        {
            return MissionAction{QStringLiteral("camera"), {{QStringLiteral("state"), triggerName(a.state)}}};
        }
        Result<MissionAction> operator()(const CameraSeriesByTimeAction &a) const
        {
            return MissionAction{QStringLiteral("camera_by_time"), {{QStringLiteral("interval"), a.intervalSeconds},
                                                                    {QStringLiteral("shots"), a.shots},
                                                                    {QStringLiteral("delay"), a.startDelaySeconds}}};
        }
        Result<MissionAction> operator()(const CameraSeriesByDistanceAction &a) const
        {
            return MissionAction{QStringLiteral("camera_by_distance"), {{QStringLiteral("interval"), a.intervalMeters},
                                                                        {QStringLiteral("shots"), a.shots},
                                                                        {QStringLiteral("delay"), a.startDelaySeconds}}};
        }
        Result<MissionAction> operator()(const PanoramaAction &a) const
        {
            return MissionAction{QStringLiteral("panorama"),
                                 {{QStringLiteral("angle"), a.angleDeg * kRad},
                                  {QStringLiteral("step"), a.stepAngleDeg * kRad},
                                  {QStringLiteral("stepDelay"), a.stepDelaySeconds},
                                  {QStringLiteral("direction"), a.direction == RotationDirection::Clockwise ? QStringLiteral("cw") : QStringLiteral("ccw")},
                                  {QStringLiteral("rate"), a.rotationSpeedDegPerSecond * kRad},
                                  {QStringLiteral("mode"), a.mode == PanoramaMode::Photo ? QStringLiteral("photo") : QStringLiteral("video")}}};
        }
        Result<MissionAction> operator()(const CameraControlAction &a) const
        {
            QVariantMap fields;  // a value not set is left out: the vehicle keeps it
            if (a.tiltDeg) fields.insert(QStringLiteral("tilt"), *a.tiltDeg * kRad);
            if (a.rollDeg) fields.insert(QStringLiteral("roll"), *a.rollDeg * kRad);
            if (a.yawDeg) fields.insert(QStringLiteral("yaw"), *a.yawDeg * kRad);
            if (a.zoomLevel) fields.insert(QStringLiteral("zoom"), *a.zoomLevel);
            return MissionAction{QStringLiteral("gimbal"), fields};
        }
        Result<MissionAction> operator()(const ServerAction &a) const
        {
            return missionError(QStringLiteral("the action \"%1\" is a UgCS server's and has no VCI form").arg(describeAction(a)));
        }
    };
    return std::visit(Visitor{}, action);
}

} // namespace sortie::vehicle
