#include "SimRouteProcessor.h"

#include "Messages.pb.h"
#include "SimFlownPoints.h"
#include "SimVehicleProfiles.h"

#include "AlgorithmCatalog.h"
#include "Geodesy.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>

#include <QCryptographicHash>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kDefaultSpeed = 5.0;

std::optional<std::string> parameter(const pb::SegmentDefinition &segment, const char *name)
{
    for (const auto &p : segment.parametervalues())
        if (p.name() == name)
            return p.value();
    return std::nullopt;
}

pb::WaypointTurnType turnType(const std::string &name)
{
    if (name == "STRAIGHT") return pb::WTT_STRAIGHT;
    if (name == "SPLINE") return pb::WTT_SPLINE;
    if (name == "BANK_TURN") return pb::WTT_BANK_TURN;
    return pb::WTT_STOP_AND_TURN;
}

void message(pb::ProcessedSegment *segment, pb::MessageSeverity severity, const QString &text)
{
    auto *m = segment->mutable_messageset()->add_messages();
    m->set_severity(severity);
    m->set_defaulttext(text.toStdString());
}

void invalid(pb::ProcessedSegment *segment, int point, const QString &text)
{
    segment->set_status(pb::RPS_INVALID);
    segment->set_wrongpointnumber(point);
    message(segment, pb::MS_ERROR, text);
}

QString metres(double v)
{
    return QString::number(v, 'f', 1);
}

// Any other definition becomes the Action member of the same name ("setServoDefinition" -> setServo,
// "poiDefinition" -> poiChange), its fields copied by name, as a UgCS server passes servos, lidar, hop,
// drop and camera actions through. False when there is no such member or a field set in the
// definition has no counterpart of the same type there (a POI above the ground, say).
bool performedAsDefined(const pb::ActionDefinition &d, pb::Action *action)
{
    using google::protobuf::FieldDescriptor;
    const auto *refl = d.GetReflection();
    std::vector<const FieldDescriptor *> set;
    refl->ListFields(d, &set);
    for (const FieldDescriptor *member : set) {
        if (member->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE || member->name() == "segmentDefinition")
            continue;
        std::string name = member->name();
        if (name.size() > 10 && name.ends_with("Definition"))
            name.resize(name.size() - 10);
        name[0] = char(std::tolower(static_cast<unsigned char>(name[0])));
        const auto *descriptor = pb::Action::descriptor();
        const FieldDescriptor *target = descriptor->FindFieldByName(name);
        if (!target)
            target = descriptor->FindFieldByName(name + "Change");
        if (!target || target->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE)
            return false;
        const auto &from = refl->GetMessage(d, member);
        auto *to = action->GetReflection()->MutableMessage(action, target);
        std::vector<const FieldDescriptor *> fields;
        from.GetReflection()->ListFields(from, &fields);
        for (const FieldDescriptor *f : fields) {
            if (f->name() == "id" || f->name() == "version")
                continue;
            const FieldDescriptor *t = to->GetDescriptor()->FindFieldByName(f->name());
            if (!t || t->type() != f->type() || t->is_repeated() || f->is_repeated()
                || (f->enum_type() && f->enum_type() != t->enum_type()))
                return false;
            const auto *fr = from.GetReflection();
            const auto *tr = to->GetReflection();
            switch (f->cpp_type()) {
            case FieldDescriptor::CPPTYPE_DOUBLE: tr->SetDouble(to, t, fr->GetDouble(from, f)); break;
            case FieldDescriptor::CPPTYPE_FLOAT: tr->SetFloat(to, t, fr->GetFloat(from, f)); break;
            case FieldDescriptor::CPPTYPE_INT32: tr->SetInt32(to, t, fr->GetInt32(from, f)); break;
            case FieldDescriptor::CPPTYPE_INT64: tr->SetInt64(to, t, fr->GetInt64(from, f)); break;
            case FieldDescriptor::CPPTYPE_UINT32: tr->SetUInt32(to, t, fr->GetUInt32(from, f)); break;
            case FieldDescriptor::CPPTYPE_UINT64: tr->SetUInt64(to, t, fr->GetUInt64(from, f)); break;
            case FieldDescriptor::CPPTYPE_BOOL: tr->SetBool(to, t, fr->GetBool(from, f)); break;
            case FieldDescriptor::CPPTYPE_ENUM: tr->SetEnum(to, t, fr->GetEnum(from, f)); break;
            case FieldDescriptor::CPPTYPE_STRING: tr->SetString(to, t, fr->GetString(from, f)); break;
            default: return false;
            }
        }
        return true;
    }
    return false;
}

// Actions a segment's definitions become, with the time they take.
void addActions(const pb::SegmentDefinition &definition, pb::ProcessedSegment *segment, double *time)
{
    for (const auto &d : definition.actiondefinitions()) {
        pb::Action a;
        a.set_origin(pb::OO_USER);
        if (d.has_waitdefinition()) {
            auto *w = a.mutable_wait();
            w->set_interval(d.waitdefinition().interval());
            w->set_waitforoperator(d.waitdefinition().waitforoperator());
            a.set_estimatedtime(d.waitdefinition().interval());
            *time += d.waitdefinition().interval();
        } else if (d.has_headingdefinition()) {
            const auto &h = d.headingdefinition();
            auto *c = a.mutable_headingchange();
            c->set_heading(h.heading());
            c->set_relativetonextwaypoint(h.relativetonextwaypoint());
            c->set_relativetonorth(h.relativetonorth());
        } else if (d.has_cameraseriesbydistancedefinition()) {
            const auto &c = d.cameraseriesbydistancedefinition();
            auto *s = a.mutable_cameraseriesbydistance();
            s->set_interval(c.interval());
            s->set_shotsnumber(c.shotsnumber());
            s->set_startdelay(c.startdelay());
            s->set_autocalc(c.autocalc());
        } else if (d.has_cameraseriesbytimedefinition()) {
            const auto &c = d.cameraseriesbytimedefinition();
            auto *s = a.mutable_cameraseriesbytime();
            s->set_interval(c.interval());
            s->set_shotsnumber(c.shotsnumber());
            s->set_startdelay(c.startdelay());
            s->set_autocalc(c.autocalc());
        } else if (!performedAsDefined(d, &a)) {
            const std::string text = "The simulator keeps this action in the route but does not perform it";
            bool said = false;
            for (const auto &m : segment->messageset().messages())
                said = said || m.defaulttext() == text;
            if (!said)
                message(segment, pb::MS_INFORMATION, QString::fromStdString(text));
            continue;
        }
        *segment->add_segmentactions() = std::move(a);
    }
}

// The figure in degrees, each point's altitude in its own frame (the first point's frame counts).
mission::SegmentFigure figureOf(const pb::SegmentDefinition &definition)
{
    mission::SegmentFigure f;
    const auto &figure = definition.figure();
    f.type = mission::FigureType(int(figure.type()));
    for (int i = 0; i < figure.points_size(); ++i) {
        const auto &p = figure.points(i);
        const bool agl = p.altitudetype() == pb::AT_AGL;
        if (i == 0)
            f.pointFrame = agl ? mission::HeightFrame::Agl : mission::HeightFrame::Amsl;
        f.points.push_back({p.latitude() * kDeg, p.longitude() * kDeg});
        f.pointAltitudes.push_back(agl ? p.aglaltitude() : p.wgs84altitude());
    }
    for (const auto &parameter : figure.parameters())
        f.parameters.push_back(parameter.value());
    return f;
}

mission::ParameterValues valuesOf(const pb::SegmentDefinition &definition)
{
    mission::ParameterValues values;
    values.reserve(definition.parametervalues_size());
    for (const auto &p : definition.parametervalues())
        values.push_back({QString::fromStdString(p.name()), QString::fromStdString(p.value())});
    return values;
}

QString segmentName(int index, const mission::AlgorithmDefinition *algorithm, const std::string &className)
{
    const QString tool = algorithm ? algorithm->displayName : QString::fromStdString(className).section(QLatin1Char('.'), -1);
    return QStringLiteral("Segment %1 (%2)").arg(index + 1).arg(tool);
}

double altitudeAgl(const mission::PlannedPoint &p, double ground)
{
    return p.frame == mission::HeightFrame::Agl ? p.height : p.height - ground;
}

// The route's and the profile's limits over the planned points: each rule reports its first offender.
void checkLimits(const pb::Route &route, const SimRouteLimits &limits, double ground, const mission::SegmentPlan &plan,
                 const QString &name, pb::ProcessedSegment *segment)
{
    auto first = [&](auto test) -> const mission::PlannedPoint * {
        for (const auto &p : plan.points)
            if (test(p))
                return &p;
        return nullptr;
    };
    auto airborne = [](const mission::PlannedPoint &p) { return p.kind == mission::PlannedPoint::Kind::Waypoint; };
    const QString prefix = name + QStringLiteral(": ");
    if (route.has_maxaltitude())
        if (const auto *p = first([&](const auto &q) { return altitudeAgl(q, ground) > route.maxaltitude(); }))
            invalid(segment, 0, prefix + QStringLiteral("Altitude %1 m is above the route's maximum altitude of %2 m")
                                    .arg(metres(altitudeAgl(*p, ground)), metres(route.maxaltitude())));
    if (limits.maxAltitudeAgl > 0)
        if (const auto *p = first([&](const auto &q) { return altitudeAgl(q, ground) > limits.maxAltitudeAgl; }))
            invalid(segment, 0, prefix + QStringLiteral("Altitude %1 m AGL is above the vehicle profile's limit of %2 m")
                                    .arg(metres(altitudeAgl(*p, ground)), metres(limits.maxAltitudeAgl)));
    if (const auto *p = first([&](const auto &q) { return altitudeAgl(q, ground) < 0; }))
        invalid(segment, 0, prefix + QStringLiteral("Altitude %1 m is below the ground").arg(metres(altitudeAgl(*p, ground))));
    if (route.has_maxspeed() && route.maxspeed() > 0)
        if (const auto *p = first([&](const auto &q) { return q.speed > route.maxspeed(); }))
            invalid(segment, 0, prefix + QStringLiteral("Speed %1 m/s is above the route's maximum speed of %2 m/s")
                                    .arg(metres(p->speed), metres(route.maxspeed())));
    if (limits.maxSpeed > 0)
        if (const auto *p = first([&](const auto &q) { return q.speed > limits.maxSpeed; }))
            invalid(segment, 0, prefix + QStringLiteral("Speed %1 m/s is above the vehicle profile's limit of %2 m/s")
                                    .arg(metres(p->speed), metres(limits.maxSpeed)));
    if (route.has_safealtitude())
        if (const auto *p = first([&](const auto &q) {
                const double agl = altitudeAgl(q, ground);
                return airborne(q) && agl >= 0 && agl < route.safealtitude();
            }))
            message(segment, pb::MS_WARNING, prefix + QStringLiteral("Altitude %1 m is below the route's safe altitude of %2 m")
                                                 .arg(metres(altitudeAgl(*p, ground)), metres(route.safealtitude())));
}

pb::Action systemAction()
{
    pb::Action a;
    a.set_origin(pb::OO_SYSTEM);
    return a;
}

void addCameraActions(const mission::PlannedPoint &p, pb::ProcessedSegment *segment)
{
    for (const mission::CameraCommand &c : p.camera) {
        pb::Action a = systemAction();
        switch (c.kind) {
        case mission::CameraCommand::Kind::FaceDown:
            a.mutable_cameracontrol()->set_tilt(std::numbers::pi / 2);  // UgCS: tilt 90° faces down
            a.mutable_cameracontrol()->set_roll(0);
            a.mutable_cameracontrol()->set_yaw(0);
            break;
        case mission::CameraCommand::Kind::FaceHeading: {
            a.mutable_headingchange()->set_heading(c.value / kDeg);
            a.mutable_headingchange()->set_relativetonorth(true);
            a.mutable_headingchange()->set_relativetonextwaypoint(false);
            *segment->add_segmentactions() = std::move(a);
            a = systemAction();
            a.mutable_cameracontrol()->set_tilt(0);
            break;
        }
        case mission::CameraCommand::Kind::StartSeries:
        case mission::CameraCommand::Kind::StopSeries:
            a.mutable_cameraseriesbydistance()->set_interval(c.value);
            a.mutable_cameraseriesbydistance()->set_shotsnumber(0);
            a.mutable_cameraseriesbydistance()->set_startdelay(0);
            a.mutable_cameraseriesbydistance()->set_autocalc(false);
            break;
        }
        *segment->add_segmentactions() = std::move(a);
    }
}

} // namespace

SimRouteLimits SimRouteLimits::of(const pb::VehicleProfile &profile)
{
    SimRouteLimits limits;
    for (const auto &p : profile.parameters()) {
        switch (p.type()) {
        case pb::VPT_MAX_HORIZONTAL_SPEED: limits.maxSpeed = p.value(); break;
        case pb::VPT_MAX_ALTITUDE_AGL: limits.maxAltitudeAgl = p.value(); break;
        case pb::VPT_MAX_CLIMB_RATE: if (p.value() > 0) limits.climbRate = p.value(); break;
        case pb::VPT_WAYPOINT_ACCEPTANCE_RADIUS: if (p.value() > 0) limits.acceptanceRadius = p.value(); break;
        default: break;
        }
    }
    limits.cameras = profileCameras(profile);
    return limits;
}

pb::ProcessedRoute SimRouteProcessor::process(const pb::Route &route, const SimRouteLimits &limits, double ground)
{
    pb::ProcessedRoute out;
    out.mutable_route()->set_id(route.id());
    out.mutable_route()->set_version(route.version());
    if (route.has_name())
        out.mutable_route()->set_name(route.name());
    out.set_uuid(route.uuid());
    out.set_modificationuuid(route.modificationuuid());

    const mission::AlgorithmCatalog &catalog = mission::AlgorithmCatalog::builtIn();
    const double climb = limits.climbRate > 0 ? limits.climbRate : 3;
    double total = 0;
    double minLat = 1e9, maxLat = -1e9, minLon = 1e9, maxLon = -1e9;
    std::optional<mission::GeoPoint> previous;
    double previousAgl = 0;
    double speed = route.initialspeed() > 0 ? route.initialspeed() : kDefaultSpeed;
    double cruise = speed;  // the last segment's own speed (not its overshoot legs'): the next one's default

    for (int index = 0; index < route.segments_size(); ++index) {
        const pb::SegmentDefinition &definition = route.segments(index);
        auto *segment = out.add_segments();
        segment->set_uuid(definition.uuid());
        segment->set_modificationuuid(definition.modificationuuid());
        segment->set_status(pb::RPS_PROCESSED);

        const mission::AlgorithmDefinition *algorithm = catalog.byClassName(QString::fromStdString(definition.algorithmclassname()));
        const QString name = segmentName(index, algorithm, definition.algorithmclassname());
        if (!algorithm) {
            invalid(segment, 0, QStringLiteral("%1: the simulator has no algorithm '%2'")
                                    .arg(name, QString::fromStdString(definition.algorithmclassname())));
            continue;
        }
        segment->set_algorithmcode(algorithm->code.toStdString());

        mission::PlanContext context;
        context.cameras = limits.cameras;
        context.defaultSpeed = cruise;
        context.previousPosition = previous;
        const mission::SegmentPlanOutcome outcome = mission::planSegment(*algorithm, figureOf(definition), valuesOf(definition), context);
        if (!outcome.ok()) {
            for (const QString &error : outcome.errors)
                invalid(segment, std::max(0, outcome.wrongPoint), name + QStringLiteral(": ") + error);
            continue;
        }
        mission::SegmentPlan plan = *outcome.plan;
        // Terrain post-processing (AGL conversion, clearance) belongs here: it edits `plan`'s points
        // before they are checked and written.
        checkLimits(route, limits, ground, plan, name, segment);
        for (const QString &w : plan.warnings)
            message(segment, pb::MS_WARNING, name + QStringLiteral(": ") + w);
        for (const QString &n : plan.notes)
            message(segment, pb::MS_INFORMATION, name + QStringLiteral(": ") + n);
        if (segment->status() == pb::RPS_INVALID)
            continue;

        const pb::WaypointTurnType turn = turnType(parameter(definition, "wpTurnType").value_or("STOP_AND_TURN"));
        double distance = 0, time = 0;
        for (size_t i = 0; i < plan.points.size(); ++i) {
            const mission::PlannedPoint &p = plan.points[i];
            const double agl = altitudeAgl(p, ground);
            const double leg = previous ? mission::geodesicDistance(*previous, p.position) : 0.0;
            const double legTime = leg / p.speed + std::abs(agl - previousAgl) / climb;
            if (i == 0 || p.speed != speed) {
                pb::Action change;
                change.set_origin(i == 0 ? pb::OO_USER : pb::OO_SYSTEM);
                change.mutable_speedchange()->set_groundspeed(p.speed);
                change.mutable_speedchange()->set_rateofclimb(climb);
                change.set_estimatedtime(0);
                *segment->add_segmentactions() = std::move(change);
                speed = p.speed;
            }
            const double lat = p.position.latitude / kDeg, lon = p.position.longitude / kDeg;
            const double amsl = ground + agl;
            pb::Action action;
            action.set_origin(pb::OO_USER);
            action.set_estimatedtime(legTime);
            if (p.kind == mission::PlannedPoint::Kind::Takeoff) {
                auto *t = action.mutable_takeoff();
                t->set_latitude(lat);
                t->set_longitude(lon);
                t->set_wgs84altitude(amsl);
                t->set_elevation(ground);
                t->set_acceptanceradius(limits.acceptanceRadius);
                t->set_rateofclimb(climb);
            } else if (p.kind == mission::PlannedPoint::Kind::Landing) {
                auto *l = action.mutable_landing();
                l->set_latitude(lat);
                l->set_longitude(lon);
                l->set_wgs84altitude(amsl);
                l->set_elevation(ground);
                l->set_acceptanceradius(limits.acceptanceRadius);
                l->set_rateofdescent(climb);
            } else {
                auto *w = action.mutable_waypoint();
                w->set_latitude(lat);
                w->set_longitude(lon);
                w->set_wgs84altitude(amsl);
                w->set_elevation(ground);
                w->set_acceptanceradius(limits.acceptanceRadius);
                w->set_turntype(turn);
                w->set_altitudeframe(p.frame == mission::HeightFrame::Agl ? pb::AF_AGL : pb::AF_WGS84);
            }
            *segment->add_segmentactions() = std::move(action);
            addCameraActions(p, segment);
            if (p.userActions)
                addActions(definition, segment, &time);
            if (!p.overshoot)
                cruise = p.speed;
            distance += leg;
            time += legTime;
            previous = p.position;
            previousAgl = agl;
            minLat = std::min(minLat, p.position.latitude), maxLat = std::max(maxLat, p.position.latitude);
            minLon = std::min(minLon, p.position.longitude), maxLon = std::max(maxLon, p.position.longitude);
        }
        segment->set_estimateddistance(distance);
        segment->set_estimatedtime(time);
        total += distance;
    }
    out.set_estimateddistance(total);
    out.set_diameter(previous ? sphericalDistance(minLat, minLon, maxLat, maxLon) : 0.0);
    return out;
}

std::string SimRouteProcessor::hash(const pb::Route &route)
{
    std::string bytes;
    google::protobuf::io::StringOutputStream stream(&bytes);
    google::protobuf::io::CodedOutputStream coded(&stream);
    coded.SetSerializationDeterministic(true);
    route.SerializeToCodedStream(&coded);
    coded.Trim();
    return QCryptographicHash::hash(QByteArray::fromStdString(bytes), QCryptographicHash::Md5).toHex().toStdString();
}

std::vector<FlightModel::Waypoint> SimRouteProcessor::flightPlan(const pb::ProcessedRoute &route, double homeGround, QString *error)
{
    for (int i = 0; i < route.segments_size(); ++i) {
        if (route.segments(i).status() != pb::RPS_PROCESSED) {
            *error = QStringLiteral("Segment %1 of the route was not processed successfully; fix it and process the route again").arg(i + 1);
            return {};
        }
    }
    // Flown as the terrain pass checked it (mission::flownLegs): over a take-off, straight up to the
    // height the first leg leaves at; across; over a landing at the height the leg left at, where
    // the vehicle lands (straight down).
    const std::vector<SimFlownPoint> points = simFlownPoints(route);
    std::vector<FlightModel::Waypoint> plan;
    const auto add = [&](size_t at, size_t whose, bool land) {
        const SimFlownPoint &p = points[at];
        const double altitude = amslOver(points, whose, at) - homeGround;
        if (!plan.empty()) {
            const FlightModel::Waypoint &last = plan.back();
            if (last.latitude == p.latitude && last.longitude == p.longitude && last.altitudeAgl == altitude && !last.landHere) {
                plan.back().landHere = land;
                return;
            }
        }
        FlightModel::Waypoint w{p.latitude, p.longitude, altitude, p.speed};
        w.landHere = land;
        plan.push_back(w);
    };
    for (const mission::LegShape &leg : simFlownLegs(points)) {
        add(leg.from, leg.departHeight, false);
        const bool last = leg.to + 1 == points.size();
        if (leg.moves() || leg.descentAtEnd)
            add(leg.to, leg.arriveHeight, leg.descentAtEnd && last);
        if (leg.descentAtEnd && !last) {  // down to the ground, and the route goes on from there
            plan.push_back(plan.back());
            plan.back().altitudeAgl = points[leg.to].ground.value_or(points[leg.to].amsl) - homeGround;
        }
    }
    if (plan.empty())
        *error = QStringLiteral("The route has no waypoint to fly");
    return plan;
}

} // namespace sortie::sim
