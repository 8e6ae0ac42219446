#include "MavlinkMission.h"

#include "AlgorithmCatalog.h"

#include "ScanPlanCache.h"
#include "SegmentPlanning.h"
#include "ServerActions.h"

#include <QSet>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

MavlinkItem command(int cmd, double p1 = 0, double p2 = 0, double p3 = 0, double p4 = 0)
{
    MavlinkItem i;
    i.command = cmd;
    i.frame = mav::Mission;
    i.param[0] = p1; i.param[1] = p2; i.param[2] = p3; i.param[3] = p4;
    return i;
}

int frameOf(AltitudeType t) { return t == AltitudeType::Amsl ? mav::Global : mav::GlobalRelativeAlt; }

class Exporter
{
public:
    Exporter(double startSpeed, std::vector<ProfileCamera> cameras, ScanPlanCache *cache, bool keepScans)
        : m_speed(startSpeed), m_cameras(std::move(cameras)), m_cache(cache), m_keepScans(keepScans) {}

    MavlinkExport run(const Route &route)
    {
        for (size_t i = 0; i < route.segments.size(); ++i) {
            const Segment &s = route.segments[i];
            if (const Waypoint *w = asWaypoint(s))
                waypoint(*w, int(i));
            else if (const std::optional<AreaScan> planned = scanOf(s, m_cameras))
                scan(*planned, int(i));
            else
                algorithm(std::get<AlgorithmSegment>(s), int(i));
        }
        if (route.settings.endAction == EndAction::ReturnHome)
            m_out.items.push_back(command(mav::NavReturnToLaunch));
        for (const QString &n : m_once)
            m_out.notices << n;
        return std::move(m_out);
    }

private:
    void speed(double v)
    {
        if (v == m_speed || !(v > 0))
            return;
        m_out.items.push_back(command(mav::DoChangeSpeed, 1, v, -1, 0));  // ground speed, throttle unchanged
        m_speed = v;
    }

    void waypoint(const Waypoint &w, int row)
    {
        speed(w.speed);
        MavlinkItem nav;
        nav.frame = frameOf(w.altitudeType);
        nav.latitude = w.position.latitude;
        nav.longitude = w.position.longitude;
        nav.altitude = w.altitude;
        size_t firstAction = 0;
        switch (w.role) {
        case WaypointRole::Takeoff: nav.command = mav::NavTakeoff; break;
        case WaypointRole::Land: nav.command = mav::NavLand; break;
        case WaypointRole::Pass:
            nav.command = w.turnType == TurnType::Spline ? mav::NavSplineWaypoint : mav::NavWaypoint;
            if (w.turnType == TurnType::StopAndTurn || w.turnType == TurnType::BankTurn)
                m_once.insert(QCoreApplication::translate("MavlinkExport", "MAVLink has no stop-and-turn or bank-turn waypoints: they were written as plain waypoints."));
            // A leading wait is the waypoint's own hold time.
            if (!w.actions.empty())
                if (const auto *wait = std::get_if<WaitAction>(&w.actions.front()); wait && !wait->waitForOperator && wait->seconds > 0) {
                    nav.param[0] = wait->seconds;
                    firstAction = 1;
                }
            if (nav.command == mav::NavWaypoint)
                nav.param[1] = w.acceptanceRadius;
            break;
        }
        m_out.items.push_back(nav);
        for (size_t i = firstAction; i < w.actions.size(); ++i)
            action(w.actions[i], row);
    }

    void skipped(int row, const QString &what)
    {
        m_out.notices << QCoreApplication::translate("MavlinkExport", "Waypoint %1: %2 has no MAVLink equivalent and was left out.").arg(row + 1).arg(what);
    }

    // Servos and VTOL transitions have MAVLink commands; the rest of what a server defines has none.
    void serverAction(const ServerAction &x, int row)
    {
        const QString kind = actionKindName(x);
        const auto value = [&x](const char *field) { return serverActionValue(x, QLatin1String(field)); };
        if (kind == QLatin1String("setServo") || kind == QLatin1String("repeatServo")) {
            const QVariant servo = value("servoId"), pwm = value("pwm");
            if (!servo.isValid() || !pwm.isValid())
                return skipped(row, QCoreApplication::translate("MavlinkExport", "a servo action without its servo and PWM"));
            if (kind == QLatin1String("setServo"))
                return m_out.items.push_back(command(mav::DoSetServo, servo.toDouble(), pwm.toDouble()));
            const QVariant count = value("count"), cycle = value("delay");
            if (!count.isValid() || !cycle.isValid())
                return skipped(row, QCoreApplication::translate("MavlinkExport", "a repeated servo without its count and cycle time"));
            return m_out.items.push_back(command(mav::DoRepeatServo, servo.toDouble(), pwm.toDouble(), count.toDouble(), cycle.toDouble()));
        }
        if (kind == QLatin1String("transitionVtol"))
            return m_out.items.push_back(command(mav::DoVtolTransition, mav::VtolStateMulticopter));
        if (kind == QLatin1String("transitionFixed"))
            return m_out.items.push_back(command(mav::DoVtolTransition, mav::VtolStateFixedWing));
        skipped(row, QStringLiteral("\"%1\"").arg(describeAction(x)));
    }

    void action(const WaypointAction &a, int row)
    {
        std::visit(Overloaded{
            [&](const WaitAction &x) {
                if (x.waitForOperator) skipped(row, QCoreApplication::translate("MavlinkExport", "waiting for the operator"));
                else m_out.items.push_back(command(mav::NavDelay, x.seconds, -1, -1, -1));
            },
            [&](const HeadingAction &x) {
                if (x.relativeToNextWaypoint) skipped(row, QCoreApplication::translate("MavlinkExport", "a heading relative to the course"));
                else m_out.items.push_back(command(mav::ConditionYaw, x.headingDeg, 0, 0, 0));
            },
            [&](const PoiAction &x) {
                MavlinkItem i = command(mav::DoSetRoiLocation);
                i.frame = frameOf(x.altitudeType);
                i.latitude = x.position.latitude;
                i.longitude = x.position.longitude;
                i.altitude = x.altitude;
                m_out.items.push_back(i);
            },
            [&](const CameraTriggerAction &x) {
                switch (x.state) {
                case TriggerState::SingleShot: m_out.items.push_back(command(mav::ImageStartCapture, 0, 0, 1, 0)); break;
                case TriggerState::StartRecording: m_out.items.push_back(command(mav::VideoStartCapture)); break;
                case TriggerState::StopRecording: m_out.items.push_back(command(mav::VideoStopCapture)); break;
                case TriggerState::ToggleRecording: skipped(row, QCoreApplication::translate("MavlinkExport", "toggling video")); break;
                }
            },
            [&](const CameraSeriesByTimeAction &x) {
                if (x.startDelaySeconds != 0) skipped(row, QCoreApplication::translate("MavlinkExport", "the series' start delay"));
                m_out.items.push_back(command(mav::ImageStartCapture, 0, x.intervalSeconds, x.shots, 0));
            },
            [&](const CameraSeriesByDistanceAction &x) {
                if (x.shots != 0 || x.startDelaySeconds != 0) skipped(row, QCoreApplication::translate("MavlinkExport", "the series' shot count and start delay"));
                m_out.items.push_back(command(mav::DoSetCamTriggDist, x.intervalMeters, 0, 0, 0));
            },
            [&](const PanoramaAction &) { skipped(row, QCoreApplication::translate("MavlinkExport", "a panorama")); },
            [&](const CameraControlAction &x) {
                // DO_MOUNT_CONTROL has no "leave as it is": an angle not set is written as 0, and said so.
                QStringList unset;
                //: A gimbal's axis, listed in "the gimbal's %2 was not set" (tilt, roll, yaw).
                if (!x.tiltDeg) unset << QCoreApplication::translate("MavlinkExport", "tilt");
                //: A gimbal's axis, listed in "the gimbal's %2 was not set" (tilt, roll, yaw).
                if (!x.rollDeg) unset << QCoreApplication::translate("MavlinkExport", "roll");
                //: A gimbal's axis, listed in "the gimbal's %2 was not set" (tilt, roll, yaw).
                if (!x.yawDeg) unset << QCoreApplication::translate("MavlinkExport", "yaw");
                if (!unset.isEmpty())
                    m_out.notices << QCoreApplication::translate("MavlinkExport", "Waypoint %1: the gimbal's %2 was not set and is written as 0° (MAVLink has no \"unchanged\").")
                                         .arg(row + 1).arg(unset.join(QStringLiteral(", ")));
                if (x.zoomLevel) skipped(row, QCoreApplication::translate("MavlinkExport", "a zoom level"));
                MavlinkItem i = command(mav::DoMountControl, -x.tiltDeg.value_or(0.0), x.rollDeg.value_or(0.0), x.yawDeg.value_or(0.0), 0);
                i.altitude = mav::MountModeMavlinkTargeting;  // param 7: the mount mode
                m_out.items.push_back(i);
            },
            [&](const ServerAction &x) { serverAction(x, row); },
        }, a);
    }

    // A corridor stays whole where the format has one (.plan); anything else flies its planned
    // path as waypoints, with the camera series the planner puts on it.
    void algorithm(const AlgorithmSegment &a, int row)
    {
        if (m_keepScans && a.kind() == AlgorithmKind::Corridor) {
            MavlinkItem i;
            i.segment = std::make_shared<const AlgorithmSegment>(a);
            m_out.items.push_back(i);
            return;
        }
        const SegmentPlanOutcome o = planAlgorithmSegment(a, AlgorithmCatalog::builtIn(), {m_cameras, m_speed, std::nullopt});
        if (!o.ok()) {
            m_out.notices << QCoreApplication::translate("MavlinkExport", "%1 was left out: %2").arg(segmentLabel(row, Segment(a)),
                                                                       o.errors.empty() ? QCoreApplication::translate("MavlinkExport", "it cannot be planned") : o.errors.front());
            return;
        }
        for (const PlannedPoint &p : o.plan->points) {
            speed(p.speed);
            MavlinkItem nav;
            nav.command = p.kind == PlannedPoint::Kind::Takeoff ? mav::NavTakeoff : p.kind == PlannedPoint::Kind::Landing ? mav::NavLand : mav::NavWaypoint;
            nav.frame = p.frame == HeightFrame::Amsl ? mav::Global : mav::GlobalRelativeAlt;
            nav.latitude = p.position.latitude;
            nav.longitude = p.position.longitude;
            nav.altitude = p.height;
            m_out.items.push_back(nav);
            for (const CameraCommand &c : p.camera) {
                if (c.kind == CameraCommand::Kind::StartSeries)
                    m_out.items.push_back(command(mav::DoSetCamTriggDist, c.value, 0, 1, 0));
                else if (c.kind == CameraCommand::Kind::StopSeries)
                    m_out.items.push_back(command(mav::DoSetCamTriggDist, 0, 0, 0, 0));
            }
        }
        m_once.insert(QCoreApplication::translate("MavlinkExport", "Segments without a MAVLink equivalent (circle, perimeter...) were written as the waypoints Sortie plans for them."));
    }

    void scan(const AreaScan &s, int row)
    {
        if (m_keepScans) {
            speed(s.parameters.speed);
            MavlinkItem i;
            i.scan = std::make_shared<const AreaScan>(s);
            m_out.items.push_back(i);
            return;
        }
        AreaScanOutcome scratch;
        const AreaScanOutcome &o = scanOutcome(s, m_cache, scratch);
        if (!o.ok()) {
            m_out.notices << QCoreApplication::translate("MavlinkExport", "Area scan %1 was left out: %2").arg(row + 1).arg(o.message);
            return;
        }
        speed(s.parameters.speed);
        const int frame = frameOf(s.parameters.altitudeType);
        auto point = [&](const GeoPoint &g) {
            MavlinkItem i;
            i.command = mav::NavWaypoint;
            i.frame = frame;
            i.latitude = g.latitude;
            i.longitude = g.longitude;
            i.altitude = o.plan->altitude;
            m_out.items.push_back(i);
        };
        const bool turnarounds = s.parameters.turnaroundMeters > 0;
        // The path holds, per transect: [turnaround], start, end, [turnaround]. Photos on the transect only.
        size_t k = 0;
        for (size_t n = 0; n < o.plan->transects.size(); ++n) {
            if (turnarounds) point(o.plan->path[k++]);
            point(o.plan->path[k++]);
            m_out.items.push_back(command(mav::DoSetCamTriggDist, o.plan->triggerDistance, 0, 1, 0));
            point(o.plan->path[k++]);
            m_out.items.push_back(command(mav::DoSetCamTriggDist, 0, 0, 0, 0));
            if (turnarounds) point(o.plan->path[k++]);
        }
        m_out.notices << QCoreApplication::translate("MavlinkExport", "Area scan %1 was written as %2 waypoints with distance triggering.").arg(row + 1).arg(o.plan->path.size());
    }

    double m_speed;
    std::vector<ProfileCamera> m_cameras;  // the route's profile's: a segment's camera may name one
    ScanPlanCache *m_cache;
    bool m_keepScans;
    MavlinkExport m_out;
    QSet<QString> m_once;
};
}

MavlinkExport routeToMavlink(const Route &route, double startSpeed, ScanPlanCache *cache, bool keepScans)
{
    return Exporter(startSpeed, route.settings.profile.cameras, cache, keepScans).run(route);
}

} // namespace sortie::mission::formats
