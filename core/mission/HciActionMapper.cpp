#include "HciActionMapper.h"

#include "Domain.pb.h"

#include <numbers>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

constexpr double kDeg = std::numbers::pi / 180.0;

// Set a field only when the decoded value differs: keeps the server's bytes when nothing changed.
#define SORTIE_MERGE(msg, field, value) \
    do { if (!(msg).has_##field() || (msg).field() != (value)) (msg).set_##field(value); } while (0)
}

WaypointAction actionFromHci(const pb::ActionDefinition &d)
{
    if (d.has_waitdefinition())
        return WaitAction{d.waitdefinition().interval(), d.waitdefinition().waitforoperator()};
    if (d.has_headingdefinition())
        return HeadingAction{d.headingdefinition().heading() / kDeg, d.headingdefinition().relativetonextwaypoint()};
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
        return PanoramaAction{p.angle() / kDeg, p.stepangle() / kDeg, p.stepdelay(),
                              p.rotationdirection() == pb::RD_COUNTERCLOCKWISE ? RotationDirection::CounterClockwise : RotationDirection::Clockwise,
                              p.rotationspeed() / kDeg, p.panoramamode() == pb::PM_VIDEO ? PanoramaMode::Video : PanoramaMode::Photo};
    }
    // Anything else (camera control, servos, VTOL transitions, lidar, hop, drop) is kept verbatim.
    QString name = QStringLiteral("Action");
    const auto *refl = d.GetReflection();
    std::vector<const google::protobuf::FieldDescriptor *> fields;
    refl->ListFields(d, &fields);
    for (const auto *f : fields) {
        if (f->type() == google::protobuf::FieldDescriptor::TYPE_MESSAGE && f->name() != "segmentDefinition") {
            name = QString::fromStdString(f->message_type()->name());
            name.remove(QStringLiteral("Definition"));
            break;
        }
    }
    return OpaqueAction{name, std::make_shared<const pb::ActionDefinition>(d)};
}

void actionToHci(const WaypointAction &action, pb::ActionDefinition &def)
{
    std::visit(Overloaded{
        [&](const WaitAction &a) {
            auto *w = def.mutable_waitdefinition();
            SORTIE_MERGE(*w, interval, a.seconds);
            SORTIE_MERGE(*w, waitforoperator, a.waitForOperator);
        },
        [&](const HeadingAction &a) {
            auto *h = def.mutable_headingdefinition();
            if (h->heading() / kDeg != a.headingDeg || !h->has_heading())
                h->set_heading(a.headingDeg * kDeg);
            SORTIE_MERGE(*h, relativetonextwaypoint, a.relativeToNextWaypoint);
        },
        [&](const PoiAction &a) {
            auto *p = def.mutable_poidefinition();
            SORTIE_MERGE(*p, mode, pb::PM_LOCATION);
            if (!p->has_latitude() || p->latitude() / kDeg != a.position.latitude)
                p->set_latitude(a.position.latitude * kDeg);
            if (!p->has_longitude() || p->longitude() / kDeg != a.position.longitude)
                p->set_longitude(a.position.longitude * kDeg);
            const pb::AltitudeType t = a.altitudeType == AltitudeType::Amsl ? pb::AT_WGS84 : pb::AT_AGL;
            SORTIE_MERGE(*p, altitudetype, t);
            if (a.altitudeType == AltitudeType::Amsl)
                SORTIE_MERGE(*p, wgs84altitude, a.altitude);
            else
                SORTIE_MERGE(*p, aglaltitude, a.altitude);
        },
        [&](const CameraTriggerAction &a) {
            SORTIE_MERGE(*def.mutable_cameratriggerdefinition(), state, pb::TriggerState(int(a.state)));
        },
        [&](const CameraSeriesByTimeAction &a) {
            auto *c = def.mutable_cameraseriesbytimedefinition();
            SORTIE_MERGE(*c, interval, a.intervalSeconds);
            SORTIE_MERGE(*c, shotsnumber, a.shots);
            SORTIE_MERGE(*c, startdelay, a.startDelaySeconds);
            if (!c->has_autocalc()) c->set_autocalc(false);
        },
        [&](const CameraSeriesByDistanceAction &a) {
            auto *c = def.mutable_cameraseriesbydistancedefinition();
            SORTIE_MERGE(*c, interval, a.intervalMeters);
            SORTIE_MERGE(*c, shotsnumber, a.shots);
            SORTIE_MERGE(*c, startdelay, a.startDelaySeconds);
            if (!c->has_autocalc()) c->set_autocalc(false);
        },
        [&](const PanoramaAction &a) {
            auto *p = def.mutable_panoramadefinition();
            if (!p->has_angle() || p->angle() / kDeg != a.angleDeg) p->set_angle(a.angleDeg * kDeg);
            if (!p->has_stepangle() || p->stepangle() / kDeg != a.stepAngleDeg) p->set_stepangle(a.stepAngleDeg * kDeg);
            SORTIE_MERGE(*p, stepdelay, a.stepDelaySeconds);
            SORTIE_MERGE(*p, rotationdirection, a.direction == RotationDirection::Clockwise ? pb::RD_CLOCKWISE : pb::RD_COUNTERCLOCKWISE);
            if (!p->has_rotationspeed() || p->rotationspeed() / kDeg != a.rotationSpeedDegPerSecond)
                p->set_rotationspeed(a.rotationSpeedDegPerSecond * kDeg);
            SORTIE_MERGE(*p, panoramamode, a.mode == PanoramaMode::Video ? pb::PM_VIDEO : pb::PM_PHOTO);
        },
        [&](const OpaqueAction &a) {
            if (a.definition)
                def = *a.definition;
        },
    }, action);
}

} // namespace sortie::mission
