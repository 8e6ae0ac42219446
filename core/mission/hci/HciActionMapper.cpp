#include "HciActionMapper.h"

#include "Domain.pb.h"
#include "HciText.h"

#include <cmath>
#include <numbers>
#include <optional>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

constexpr double kDeg = std::numbers::pi / 180.0;

// An angle the server holds in radians, in degrees as the operator typed them: 60° goes out as
// 1.0471975511965976 rad and would come back as 59.99999999999999°, which reads as an edit.
double degreesOf(double radians)
{
    return std::round(radians / kDeg * 1e9) / 1e9;
}

// Set a field only when the decoded value differs: keeps the server's bytes when nothing changed.
}

WaypointAction actionFromHci(const pb::ActionDefinition &d)
{
    if (d.has_waitdefinition())
        return WaitAction{d.waitdefinition().interval(), d.waitdefinition().waitforoperator()};
    if (d.has_headingdefinition())
        return HeadingAction{degreesOf(d.headingdefinition().heading()), d.headingdefinition().relativetonextwaypoint()};
    if (d.has_poidefinition()) {
        const auto &p = d.poidefinition();
        const bool amsl = p.has_altitudetype() && p.altitudetype() == pb::AT_WGS84;
        return PoiAction{{p.latitude() / kDeg, p.longitude() / kDeg}, amsl ? p.wgs84altitude() : p.aglaltitude(),
                         amsl ? AltitudeType::Amsl : AltitudeType::Agl};
    }
    if (d.has_cameratriggerdefinition())
        return CameraTriggerAction{TriggerState(int(d.cameratriggerdefinition().state()))};
    if (d.has_cameraseriesbytimedefinition()) {
        const auto &c = d.cameraseriesbytimedefinition();
        return CameraSeriesByTimeAction{c.interval(), c.shotsnumber(), c.startdelay()};
    }
    if (d.has_cameraseriesbydistancedefinition()) {
        const auto &c = d.cameraseriesbydistancedefinition();
        return CameraSeriesByDistanceAction{c.interval(), c.shotsnumber(), c.startdelay()};
    }
    if (d.has_panoramadefinition()) {
        const auto &p = d.panoramadefinition();
        return PanoramaAction{degreesOf(p.angle()), degreesOf(p.stepangle()), p.stepdelay(),
                              p.rotationdirection() == pb::RD_COUNTERCLOCKWISE ? RotationDirection::CounterClockwise : RotationDirection::Clockwise,
                              degreesOf(p.rotationspeed()), p.panoramamode() == pb::PM_VIDEO ? PanoramaMode::Video : PanoramaMode::Photo};
    }
    if (d.has_cameracontroldefinition()) {
        const auto &c = d.cameracontroldefinition();
        CameraControlAction a;
        if (c.has_tilt()) a.tiltDeg = degreesOf(c.tilt());
        if (c.has_roll()) a.rollDeg = degreesOf(c.roll());
        if (c.has_yaw()) a.yawDeg = degreesOf(c.yaw());
        if (c.has_zoomlevel()) a.zoomLevel = c.zoomlevel();
        return a;
    }
    // Anything else (servos, VTOL transitions, lidar, hop, drop) stays in the server's terms.
    return ServerAction{QByteArray::fromStdString(d.SerializeAsString())};
}

void actionToHci(const WaypointAction &action, pb::ActionDefinition &def)
{
    if (const auto *o = std::get_if<ServerAction>(&action)) {
        if (!o->definition.isEmpty())
            def.ParseFromArray(o->definition.constData(), int(o->definition.size()));
        return;
    }
    // Compare with what def already says (decoded: an absent field reads as its meaning, not
    // its protobuf default) and write only the differences; a new definition gets every field.
    std::optional<WaypointAction> decoded;
    if (def.ByteSizeLong() > 0)
        decoded = actionFromHci(def);
    if (decoded && decoded->index() != action.index()) {
        def.Clear();  // another kind of action: nothing of the old one applies
        decoded.reset();
    }
    const bool fresh = !decoded;
    std::visit(Overloaded{
        [&](const WaitAction &a) {
            const WaitAction *b = fresh ? nullptr : &std::get<WaitAction>(*decoded);
            auto *w = def.mutable_waitdefinition();
            if (!b || differs(b->seconds, a.seconds)) w->set_interval(a.seconds);
            if (!b || b->waitForOperator != a.waitForOperator) w->set_waitforoperator(a.waitForOperator);
        },
        [&](const HeadingAction &a) {
            const HeadingAction *b = fresh ? nullptr : &std::get<HeadingAction>(*decoded);
            auto *h = def.mutable_headingdefinition();
            if (!b || differs(b->headingDeg, a.headingDeg)) h->set_heading(a.headingDeg * kDeg);
            if (!b || b->relativeToNextWaypoint != a.relativeToNextWaypoint) h->set_relativetonextwaypoint(a.relativeToNextWaypoint);
        },
        [&](const PoiAction &a) {
            const PoiAction *b = fresh ? nullptr : &std::get<PoiAction>(*decoded);
            auto *p = def.mutable_poidefinition();
            if (!b) p->set_mode(pb::PM_LOCATION);
            if (!b || differs(b->position.latitude, a.position.latitude)) p->set_latitude(a.position.latitude * kDeg);
            if (!b || differs(b->position.longitude, a.position.longitude)) p->set_longitude(a.position.longitude * kDeg);
            const bool typeChanged = !b || b->altitudeType != a.altitudeType;
            if (typeChanged) p->set_altitudetype(a.altitudeType == AltitudeType::Amsl ? pb::AT_WGS84 : pb::AT_AGL);
            if (typeChanged || differs(b->altitude, a.altitude)) {
                if (a.altitudeType == AltitudeType::Amsl) p->set_wgs84altitude(a.altitude);
                else p->set_aglaltitude(a.altitude);
            }
        },
        [&](const CameraTriggerAction &a) {
            const CameraTriggerAction *b = fresh ? nullptr : &std::get<CameraTriggerAction>(*decoded);
            auto *c = def.mutable_cameratriggerdefinition();
            if (!b || b->state != a.state) c->set_state(pb::TriggerState(int(a.state)));
        },
        [&](const CameraSeriesByTimeAction &a) {
            const CameraSeriesByTimeAction *b = fresh ? nullptr : &std::get<CameraSeriesByTimeAction>(*decoded);
            auto *c = def.mutable_cameraseriesbytimedefinition();
            if (!b || differs(b->intervalSeconds, a.intervalSeconds)) c->set_interval(a.intervalSeconds);
            if (!b || b->shots != a.shots) c->set_shotsnumber(a.shots);
            if (!b || differs(b->startDelaySeconds, a.startDelaySeconds)) c->set_startdelay(a.startDelaySeconds);
            if (!b) c->set_autocalc(false);
        },
        [&](const CameraSeriesByDistanceAction &a) {
            const CameraSeriesByDistanceAction *b = fresh ? nullptr : &std::get<CameraSeriesByDistanceAction>(*decoded);
            auto *c = def.mutable_cameraseriesbydistancedefinition();
            if (!b || differs(b->intervalMeters, a.intervalMeters)) c->set_interval(a.intervalMeters);
            if (!b || b->shots != a.shots) c->set_shotsnumber(a.shots);
            if (!b || differs(b->startDelaySeconds, a.startDelaySeconds)) c->set_startdelay(a.startDelaySeconds);
            if (!b) c->set_autocalc(false);
        },
        [&](const PanoramaAction &a) {
            const PanoramaAction *b = fresh ? nullptr : &std::get<PanoramaAction>(*decoded);
            auto *p = def.mutable_panoramadefinition();
            if (!b || differs(b->angleDeg, a.angleDeg)) p->set_angle(a.angleDeg * kDeg);
            if (!b || differs(b->stepAngleDeg, a.stepAngleDeg)) p->set_stepangle(a.stepAngleDeg * kDeg);
            if (!b || differs(b->stepDelaySeconds, a.stepDelaySeconds)) p->set_stepdelay(a.stepDelaySeconds);
            if (!b || b->direction != a.direction)
                p->set_rotationdirection(a.direction == RotationDirection::Clockwise ? pb::RD_CLOCKWISE : pb::RD_COUNTERCLOCKWISE);
            if (!b || differs(b->rotationSpeedDegPerSecond, a.rotationSpeedDegPerSecond)) p->set_rotationspeed(a.rotationSpeedDegPerSecond * kDeg);
            if (!b || b->mode != a.mode) p->set_panoramamode(a.mode == PanoramaMode::Video ? pb::PM_VIDEO : pb::PM_PHOTO);
        },
        [&](const CameraControlAction &a) {
            const CameraControlAction *b = fresh ? nullptr : &std::get<CameraControlAction>(*decoded);
            auto *c = def.mutable_cameracontroldefinition();
            // An angle not set is absent on the wire: the camera keeps it.
            const auto angle = [&](const std::optional<double> &now, const std::optional<double> *before, auto set, auto clear) {
                if (before && now.has_value() == before->has_value() && (!now || !differs(**before, *now)))
                    return;
                if (now) (c->*set)(*now * kDeg);
                else (c->*clear)();
            };
            angle(a.tiltDeg, b ? &b->tiltDeg : nullptr, &pb::CameraControlDefinition::set_tilt, &pb::CameraControlDefinition::clear_tilt);
            angle(a.rollDeg, b ? &b->rollDeg : nullptr, &pb::CameraControlDefinition::set_roll, &pb::CameraControlDefinition::clear_roll);
            angle(a.yawDeg, b ? &b->yawDeg : nullptr, &pb::CameraControlDefinition::set_yaw, &pb::CameraControlDefinition::clear_yaw);
            if (!b || b->zoomLevel != a.zoomLevel) {
                if (a.zoomLevel) c->set_zoomlevel(*a.zoomLevel);
                else c->clear_zoomlevel();
            }
        },
        [&](const ServerAction &) {},
    }, action);
}

} // namespace sortie::mission
