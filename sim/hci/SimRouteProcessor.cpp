#include "SimRouteProcessor.h"

#include "Messages.pb.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>

#include <QCryptographicHash>

#include <cmath>
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
        } else {
            message(segment, pb::MS_INFORMATION, QStringLiteral("The simulator keeps this action in the route but does not perform it"));
            continue;
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

    double total = 0;
    double minLat = 1e9, maxLat = -1e9, minLon = 1e9, maxLon = -1e9;
    std::optional<std::pair<double, double>> previous; // lat, lon in degrees
    double previousAgl = 0;
    const double climb = limits.climbRate > 0 ? limits.climbRate : 3;

    for (const auto &definition : route.segments()) {
        auto *segment = out.add_segments();
        segment->set_uuid(definition.uuid());
        segment->set_modificationuuid(definition.modificationuuid());
        segment->set_status(pb::RPS_PROCESSED);
        segment->set_algorithmcode("Waypoint");

        if (definition.algorithmclassname() != kWaypointAlgorithm) {
            invalid(segment, 0, QStringLiteral("The simulator processes waypoint segments only, not '%1'")
                                    .arg(QString::fromStdString(definition.algorithmclassname())));
            continue;
        }
        if (definition.figure().points_size() == 0) {
            invalid(segment, 0, QStringLiteral("The segment has no point"));
            continue;
        }
        const auto &point = definition.figure().points(0);
        const double lat = point.latitude() * kDeg, lon = point.longitude() * kDeg;
        if (std::abs(lat) > 90 || std::abs(lon) > 180 || !std::isfinite(lat) || !std::isfinite(lon)) {
            invalid(segment, 0, QStringLiteral("The point is not on the globe (latitude and longitude are in radians)"));
            continue;
        }
        const bool agl = point.altitudetype() == pb::AT_AGL;
        const double altitudeAgl = agl ? point.aglaltitude() : point.wgs84altitude() - ground;
        const double altitudeAmsl = ground + altitudeAgl;

        double speed = route.initialspeed() > 0 ? route.initialspeed() : kDefaultSpeed;
        if (const auto text = parameter(definition, "speed"); text && !text->empty()) {
            bool ok = false;
            speed = QString::fromStdString(*text).toDouble(&ok);
            if (!ok || speed <= 0) {
                invalid(segment, 0, QStringLiteral("The speed '%1' is not a positive number of m/s").arg(QString::fromStdString(*text)));
                continue;
            }
        }

        if (route.has_maxaltitude() && altitudeAgl > route.maxaltitude())
            invalid(segment, 0, QStringLiteral("Altitude %1 m is above the route's maximum altitude of %2 m")
                                    .arg(metres(altitudeAgl), metres(route.maxaltitude())));
        if (limits.maxAltitudeAgl > 0 && altitudeAgl > limits.maxAltitudeAgl)
            invalid(segment, 0, QStringLiteral("Altitude %1 m AGL is above the vehicle profile's limit of %2 m")
                                    .arg(metres(altitudeAgl), metres(limits.maxAltitudeAgl)));
        if (altitudeAgl < 0)
            invalid(segment, 0, QStringLiteral("Altitude %1 m is below the ground").arg(metres(altitudeAgl)));
        if (route.has_maxspeed() && route.maxspeed() > 0 && speed > route.maxspeed())
            invalid(segment, 0, QStringLiteral("Speed %1 m/s is above the route's maximum speed of %2 m/s")
                                    .arg(metres(speed), metres(route.maxspeed())));
        if (limits.maxSpeed > 0 && speed > limits.maxSpeed)
            invalid(segment, 0, QStringLiteral("Speed %1 m/s is above the vehicle profile's limit of %2 m/s")
                                    .arg(metres(speed), metres(limits.maxSpeed)));
        if (route.has_safealtitude() && altitudeAgl >= 0 && altitudeAgl < route.safealtitude())
            message(segment, pb::MS_WARNING, QStringLiteral("Altitude %1 m is below the route's safe altitude of %2 m")
                                                 .arg(metres(altitudeAgl), metres(route.safealtitude())));
        if (segment->status() == pb::RPS_INVALID)
            continue;

        const double distance = previous ? sphericalDistance(previous->first, previous->second, lat, lon) : 0.0;
        double time = distance / speed + std::abs(altitudeAgl - previousAgl) / climb;

        pb::Action change;
        change.set_origin(pb::OO_USER);
        change.mutable_speedchange()->set_groundspeed(speed);
        change.mutable_speedchange()->set_rateofclimb(climb);
        change.set_estimatedtime(0);
        *segment->add_segmentactions() = std::move(change);

        pb::Action waypoint;
        waypoint.set_origin(pb::OO_USER);
        auto *w = waypoint.mutable_waypoint();
        w->set_latitude(point.latitude());
        w->set_longitude(point.longitude());
        w->set_wgs84altitude(altitudeAmsl);
        w->set_elevation(ground);
        w->set_acceptanceradius(limits.acceptanceRadius);
        w->set_turntype(turnType(parameter(definition, "wpTurnType").value_or("STOP_AND_TURN")));
        w->set_altitudeframe(agl ? pb::AF_AGL : pb::AF_WGS84);
        waypoint.set_estimatedtime(time);
        *segment->add_segmentactions() = std::move(waypoint);
        addActions(definition, segment, &time);

        segment->set_estimateddistance(distance);
        segment->set_estimatedtime(time);
        total += distance;
        previous = {lat, lon};
        previousAgl = altitudeAgl;
        minLat = std::min(minLat, lat), maxLat = std::max(maxLat, lat);
        minLon = std::min(minLon, lon), maxLon = std::max(maxLon, lon);
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
    std::vector<FlightModel::Waypoint> plan;
    double speed = 0;
    for (int i = 0; i < route.segments_size(); ++i) {
        const auto &segment = route.segments(i);
        if (segment.status() != pb::RPS_PROCESSED) {
            *error = QStringLiteral("Segment %1 of the route was not processed successfully; fix it and process the route again").arg(i + 1);
            return {};
        }
        for (const auto &action : segment.segmentactions()) {
            if (action.has_speedchange() && action.speedchange().groundspeed() > 0)
                speed = action.speedchange().groundspeed();
            if (!action.has_waypoint())
                continue;
            const auto &w = action.waypoint();
            plan.push_back({w.latitude() * kDeg, w.longitude() * kDeg, w.wgs84altitude() - homeGround, speed});
        }
    }
    if (plan.empty())
        *error = QStringLiteral("The route has no waypoint to fly");
    return plan;
}

} // namespace sortie::sim
