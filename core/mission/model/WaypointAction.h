#pragma once

#include "GeoPoint.h"
#include "MissionEnums.h"

#include <QByteArray>
#include <QString>

#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace sortie::mission {

// Actions performed at a waypoint, in order. Units: seconds, metres, degrees (clockwise from north).
struct WaitAction
{
    double seconds = 0.0;
    bool waitForOperator = false;
    bool operator==(const WaitAction &) const = default;
};

struct HeadingAction
{
    double headingDeg = 0.0;        // yaw; relative to north unless relativeToNextWaypoint
    bool relativeToNextWaypoint = false;
    bool operator==(const HeadingAction &) const = default;
};

struct PoiAction
{
    GeoPoint position;
    double altitude = 0.0;
    AltitudeType altitudeType = AltitudeType::Agl;
    bool operator==(const PoiAction &) const = default;
};

enum class TriggerState { SingleShot, StartRecording, StopRecording, ToggleRecording };

struct CameraTriggerAction
{
    TriggerState state = TriggerState::SingleShot;
    bool operator==(const CameraTriggerAction &) const = default;
};

struct CameraSeriesByTimeAction
{
    double intervalSeconds = 1.0;
    int shots = 0;  // 0: until the next camera action
    double startDelaySeconds = 0.0;
    bool operator==(const CameraSeriesByTimeAction &) const = default;
};

struct CameraSeriesByDistanceAction
{
    double intervalMeters = 10.0;  // 0 stops a running series
    int shots = 0;                 // 0: until the next camera action
    double startDelaySeconds = 0.0;
    bool operator==(const CameraSeriesByDistanceAction &) const = default;
};

enum class RotationDirection { Clockwise, CounterClockwise };
enum class PanoramaMode { Photo, Video };

struct PanoramaAction
{
    double angleDeg = 360.0;
    double stepAngleDeg = 45.0;
    double stepDelaySeconds = 1.0;
    RotationDirection direction = RotationDirection::Clockwise;
    double rotationSpeedDegPerSecond = 30.0;
    PanoramaMode mode = PanoramaMode::Photo;
    bool operator==(const PanoramaAction &) const = default;
};

// Points the camera's gimbal and sets its zoom (UgCS's camera control). A value not set is left
// as it is. Angles in degrees: tilt 90° looks straight down, 0° ahead (UgCS's convention); roll and
// yaw relative to the vehicle. The zoom level is the camera's own step number.
struct CameraControlAction
{
    std::optional<double> tiltDeg;
    std::optional<double> rollDeg;
    std::optional<double> yawDeg;
    std::optional<int> zoomLevel;
    bool operator==(const CameraControlAction &) const = default;
};

// An action Sortie keeps in the server's own terms (servo, VTOL transition, lidar, hop, drop, and
// any a newer schema adds): the UgCS ActionDefinition itself, as its protobuf bytes, edited field by
// field through its schema (ServerActions.h), so whatever Sortie does not know of it goes back
// unchanged. Equal when the bytes are.
struct ServerAction
{
    QByteArray definition;  // a serialized ActionDefinition; empty: none
    bool operator==(const ServerAction &) const = default;
};

using WaypointAction = std::variant<WaitAction, HeadingAction, PoiAction, CameraTriggerAction,
                                    CameraSeriesByTimeAction, CameraSeriesByDistanceAction, PanoramaAction,
                                    CameraControlAction, ServerAction>;

QString altitudeTypeName(AltitudeType type);                 // "AGL" / "AMSL"
bool parseAltitudeType(const QString &name, AltitudeType *out);
QString actionKindName(const WaypointAction &action);        // "wait", "heading", ..., "setServo"
QString describeAction(const WaypointAction &action);        // "Wait 5 s", "Camera every 20 m", ...
QString describeActions(const std::vector<WaypointAction> &actions);

} // namespace sortie::mission
