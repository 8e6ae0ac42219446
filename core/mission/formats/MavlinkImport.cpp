#include "MavlinkMission.h"
#include "ServerActions.h"

#include <cmath>

namespace sortie::mission::formats {

QString mavCommandName(int command)
{
    switch (command) {
    case mav::NavWaypoint: return QStringLiteral("NAV_WAYPOINT");
    case mav::NavLoiterUnlimited: return QStringLiteral("NAV_LOITER_UNLIM");
    case mav::NavLoiterTurns: return QStringLiteral("NAV_LOITER_TURNS");
    case mav::NavLoiterTime: return QStringLiteral("NAV_LOITER_TIME");
    case mav::NavReturnToLaunch: return QStringLiteral("NAV_RETURN_TO_LAUNCH");
    case mav::NavLand: return QStringLiteral("NAV_LAND");
    case mav::NavTakeoff: return QStringLiteral("NAV_TAKEOFF");
    case mav::NavLoiterToAltitude: return QStringLiteral("NAV_LOITER_TO_ALT");
    case mav::NavSplineWaypoint: return QStringLiteral("NAV_SPLINE_WAYPOINT");
    case mav::NavVtolTakeoff: return QStringLiteral("NAV_VTOL_TAKEOFF");
    case mav::NavVtolLand: return QStringLiteral("NAV_VTOL_LAND");
    case mav::NavDelay: return QStringLiteral("NAV_DELAY");
    case mav::ConditionDelay: return QStringLiteral("CONDITION_DELAY");
    case mav::ConditionYaw: return QStringLiteral("CONDITION_YAW");
    case mav::DoJump: return QStringLiteral("DO_JUMP");
    case mav::DoChangeSpeed: return QStringLiteral("DO_CHANGE_SPEED");
    case mav::DoSetServo: return QStringLiteral("DO_SET_SERVO");
    case mav::DoRepeatServo: return QStringLiteral("DO_REPEAT_SERVO");
    case mav::DoVtolTransition: return QStringLiteral("DO_VTOL_TRANSITION");
    case mav::DoLandStart: return QStringLiteral("DO_LAND_START");
    case mav::DoSetRoiLocation: return QStringLiteral("DO_SET_ROI_LOCATION");
    case mav::DoSetRoiNone: return QStringLiteral("DO_SET_ROI_NONE");
    case mav::DoSetRoi: return QStringLiteral("DO_SET_ROI");
    case mav::DoDigicamControl: return QStringLiteral("DO_DIGICAM_CONTROL");
    case mav::DoMountControl: return QStringLiteral("DO_MOUNT_CONTROL");
    case mav::DoSetCamTriggDist: return QStringLiteral("DO_SET_CAM_TRIGG_DIST");
    case mav::DoGimbalManagerPitchYaw: return QStringLiteral("DO_GIMBAL_MANAGER_PITCHYAW");
    case mav::ImageStartCapture: return QStringLiteral("IMAGE_START_CAPTURE");
    case mav::ImageStopCapture: return QStringLiteral("IMAGE_STOP_CAPTURE");
    case mav::VideoStartCapture: return QStringLiteral("VIDEO_START_CAPTURE");
    case mav::VideoStopCapture: return QStringLiteral("VIDEO_STOP_CAPTURE");
    default: return QStringLiteral("command %1").arg(command);
    }
}

namespace {
QString where(const MavlinkItem &item)
{
    if (item.line > 0)
        return QStringLiteral("line %1").arg(item.line);
    return item.jsonPath;
}

MissionError errorAt(const MavlinkItem &item, const QString &message)
{
    return MissionError{message, {}, item.line, 0, item.jsonPath};
}

bool isNavigation(int command) { return command < 100; }  // MAVLink's NAV range

bool hasPosition(const MavlinkItem &i) { return std::isfinite(i.latitude) && std::isfinite(i.longitude) && !(i.latitude == 0 && i.longitude == 0); }

class Importer
{
public:
    Importer(std::optional<HomePosition> home, double startSpeed) : m_home(home), m_speed(startSpeed)
    {
        m_out.route.settings.home = home;
        m_out.route.settings.initialSpeed = startSpeed;
    }

    Result<ImportedRoute> run(const std::vector<MavlinkItem> &items)
    {
        for (const MavlinkItem &item : items) {
            if (m_returned && isNavigation(item.command))
                return errorAt(item, QStringLiteral("%1 after RETURN_TO_LAUNCH: the vehicle never gets there").arg(mavCommandName(item.command)));
            if (auto e = take(item))
                return *e;
        }
        if (!m_pending.empty())
            m_out.notices << QStringLiteral("%1 action(s) after the last waypoint were dropped: no waypoint to attach them to")
                                 .arg(m_pending.size());
        if (m_relativeFrames)
            m_out.notices << QStringLiteral("Altitudes relative to home were imported as AGL; they match only over level ground.");
        return std::move(m_out);
    }

private:
    std::optional<MissionError> take(const MavlinkItem &item)
    {
        if (item.segment) {
            m_out.route.segments.push_back(*item.segment);
            m_last = -1;
            return std::nullopt;
        }
        if (item.scan) {
            AreaScan scan = *item.scan;
            scan.parameters.speed = m_speed;
            m_out.route.segments.push_back(std::move(scan));
            m_last = -1;  // actions that follow belong to the next waypoint
            return std::nullopt;
        }
        switch (item.command) {
        case mav::NavReturnToLaunch:
            m_out.route.settings.endAction = EndAction::ReturnHome;
            m_returned = true;
            return std::nullopt;
        case mav::DoChangeSpeed:
            if (item.param[1] > 0)
                m_speed = item.param[1];
            return std::nullopt;
        case mav::NavDelay:
        case mav::ConditionDelay:
            if (item.param[0] >= 0)
                attach(item, WaitAction{item.param[0], false});
            else
                m_out.notices << QStringLiteral("%1: a delay until a time of day is not supported; skipped").arg(where(item));
            return std::nullopt;
        case mav::ConditionYaw:
            if (item.param[3] != 0)
                m_out.notices << QStringLiteral("%1: a relative yaw is not supported; skipped").arg(where(item));
            else
                attach(item, HeadingAction{item.param[0], false});
            return std::nullopt;
        case mav::DoSetRoiLocation:
        case mav::DoSetRoi:
            if (item.command == mav::DoSetRoi && item.param[0] != 0 && item.param[0] != 2) {
                m_out.notices << QStringLiteral("%1: ROI mode %2 is not supported; skipped").arg(where(item)).arg(item.param[0]);
                return std::nullopt;
            }
            if (!hasPosition(item)) {
                m_out.notices << QStringLiteral("%1: ROI without a location (clears the ROI); skipped").arg(where(item));
                return std::nullopt;
            }
            if (auto t = altitudeTypeOf(item))
                attach(item, PoiAction{{item.latitude, item.longitude}, item.altitude, *t});
            else
                return errorAt(item, QStringLiteral("altitude frame %1 is not supported").arg(item.frame));
            return std::nullopt;
        case mav::DoSetServo:
            return serverAction(item, QStringLiteral("setServo"), {{QStringLiteral("servoId"), item.param[0]}, {QStringLiteral("pwm"), item.param[1]}});
        case mav::DoRepeatServo:
            return serverAction(item, QStringLiteral("repeatServo"), {{QStringLiteral("servoId"), item.param[0]}, {QStringLiteral("pwm"), item.param[1]},
                                                                      {QStringLiteral("count"), item.param[2]}, {QStringLiteral("delay"), item.param[3]}});
        case mav::DoVtolTransition:
            if (item.param[0] == double(mav::VtolStateMulticopter))
                return serverAction(item, QStringLiteral("transitionVtol"), {});
            if (item.param[0] == double(mav::VtolStateFixedWing))
                return serverAction(item, QStringLiteral("transitionFixed"), {});
            return errorAt(item, QStringLiteral("DO_VTOL_TRANSITION to state %1: only 3 (multicopter) and 4 (fixed-wing) are states").arg(item.param[0]));
        case mav::DoDigicamControl:
            attach(item, CameraTriggerAction{TriggerState::SingleShot});
            return std::nullopt;
        case mav::DoSetCamTriggDist:
            attach(item, CameraSeriesByDistanceAction{item.param[0], 0, 0});
            return std::nullopt;
        case mav::DoMountControl: {
            // Pitch, roll, yaw in degrees, pitch -90 looking down; UgCS's tilt is 90 there.
            CameraControlAction a;
            if (!std::isnan(item.param[0])) a.tiltDeg = -item.param[0];
            if (!std::isnan(item.param[1])) a.rollDeg = item.param[1];
            if (!std::isnan(item.param[2])) a.yawDeg = item.param[2];
            attach(item, a);
            return std::nullopt;
        }
        case mav::DoGimbalManagerPitchYaw: {
            CameraControlAction a;  // NaN: leave as it is
            if (!std::isnan(item.param[0])) a.tiltDeg = -item.param[0];
            if (!std::isnan(item.param[1])) a.yawDeg = item.param[1];
            attach(item, a);
            return std::nullopt;
        }
        case mav::ImageStartCapture:
            if (item.param[2] == 1 && item.param[1] == 0)
                attach(item, CameraTriggerAction{TriggerState::SingleShot});
            else
                attach(item, CameraSeriesByTimeAction{item.param[1], int(item.param[2]), 0});
            return std::nullopt;
        case mav::ImageStopCapture:
            attach(item, CameraSeriesByDistanceAction{0, 0, 0});
            return std::nullopt;
        case mav::VideoStartCapture:
            attach(item, CameraTriggerAction{TriggerState::StartRecording});
            return std::nullopt;
        case mav::VideoStopCapture:
            attach(item, CameraTriggerAction{TriggerState::StopRecording});
            return std::nullopt;
        default:
            break;
        }
        if (!isNavigation(item.command)) {
            m_out.notices << QStringLiteral("%1: %2 is not supported; skipped").arg(where(item), mavCommandName(item.command));
            return std::nullopt;
        }
        return navigation(item);
    }

    std::optional<AltitudeType> altitudeTypeOf(const MavlinkItem &item)
    {
        switch (item.frame) {
        case mav::Global:
        case mav::GlobalInt: return AltitudeType::Amsl;
        case mav::GlobalRelativeAlt:
        case mav::GlobalRelativeAltInt: m_relativeFrames = true; return AltitudeType::Agl;
        case mav::GlobalTerrainAlt:
        case mav::GlobalTerrainAltInt: return AltitudeType::Agl;
        default: return std::nullopt;
        }
    }

    std::optional<MissionError> navigation(const MavlinkItem &item)
    {
        Waypoint w;
        const auto type = altitudeTypeOf(item);
        if (!type)
            return errorAt(item, QStringLiteral("altitude frame %1 is not supported for %2").arg(item.frame).arg(mavCommandName(item.command)));
        w.altitudeType = *type;
        w.altitude = item.altitude;
        w.speed = m_speed;
        w.turnType = item.command == mav::NavSplineWaypoint ? TurnType::Spline : TurnType::Straight;
        const bool takeoff = item.command == mav::NavTakeoff || item.command == mav::NavVtolTakeoff;
        const bool land = item.command == mav::NavLand || item.command == mav::NavVtolLand;
        w.role = takeoff ? WaypointRole::Takeoff : (land ? WaypointRole::Land : WaypointRole::Pass);
        if (hasPosition(item)) {
            w.position = {item.latitude, item.longitude};
            if (!w.position.isValid())
                return errorAt(item, QStringLiteral("latitude %1, longitude %2 is not a position").arg(item.latitude).arg(item.longitude));
        } else if (takeoff || land) {
            // 0,0 means "here": the home position for a take-off, the previous point for a landing.
            const Waypoint *prev = m_last >= 0 ? asWaypoint(m_out.route.segments[size_t(m_last)]) : nullptr;
            if (takeoff && m_home)
                w.position = m_home->position;
            else if (prev)
                w.position = prev->position;
            else if (m_home)
                w.position = m_home->position;
            else
                return errorAt(item, QStringLiteral("%1 at the current position, but no position precedes it").arg(mavCommandName(item.command)));
        } else {
            return errorAt(item, QStringLiteral("%1 has no position").arg(mavCommandName(item.command)));
        }
        if (item.command == mav::NavWaypoint || item.command == mav::NavSplineWaypoint || item.command == mav::NavLoiterTime) {
            if (item.param[0] > 0)
                w.actions.push_back(WaitAction{item.param[0], false});
        }
        if (item.command == mav::NavWaypoint)
            w.acceptanceRadius = std::max(0.0, item.param[1]);
        if (item.command == mav::NavLoiterUnlimited || item.command == mav::NavLoiterTurns || item.command == mav::NavLoiterToAltitude
            || (!takeoff && !land && item.command != mav::NavWaypoint && item.command != mav::NavSplineWaypoint
                && item.command != mav::NavLoiterTime))
            m_out.notices << QStringLiteral("%1: %2 was imported as a plain waypoint").arg(where(item), mavCommandName(item.command));
        for (auto &a : m_pending)
            w.actions.push_back(std::move(a));
        if (!m_pending.empty())
            m_out.notices << QStringLiteral("%1: actions before the first waypoint now run at it").arg(where(item));
        m_pending.clear();
        m_out.route.segments.push_back(std::move(w));
        m_last = int(m_out.route.segments.size()) - 1;
        return std::nullopt;
    }

    // A servo or VTOL transition, as the UgCS action that says the same.
    std::optional<MissionError> serverAction(const MavlinkItem &item, const QString &kind, const QVariantMap &values)
    {
        std::optional<ServerAction> action = makeServerAction(kind, values);
        if (!action)
            return errorAt(item, QStringLiteral("%1: a value does not fit (servo and PWM are whole numbers)").arg(mavCommandName(item.command)));
        attach(item, std::move(*action));
        return std::nullopt;
    }

    void attach(const MavlinkItem &, WaypointAction action)
    {
        if (m_last < 0) {
            m_pending.push_back(std::move(action));
            return;
        }
        std::get<Waypoint>(m_out.route.segments[size_t(m_last)]).actions.push_back(std::move(action));
    }

    std::optional<HomePosition> m_home;
    double m_speed;
    ImportedRoute m_out;
    std::vector<WaypointAction> m_pending;
    int m_last = -1;
    bool m_returned = false;
    bool m_relativeFrames = false;
};
}

Result<ImportedRoute> routeFromMavlink(const std::vector<MavlinkItem> &items, std::optional<HomePosition> home, double startSpeed)
{
    return Importer(home, startSpeed).run(items);
}

} // namespace sortie::mission::formats
