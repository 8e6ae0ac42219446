#include "HciSegmentMapper.h"

#include "Domain.pb.h"
#include "HciActionMapper.h"
#include "HciRouteMapper.h"
#include "HciText.h"

#include <numbers>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

const char *turnName(TurnType t)
{
    switch (t) {
    case TurnType::StopAndTurn: return "STOP_AND_TURN";
    case TurnType::Straight: return "STRAIGHT";
    case TurnType::Spline: return "SPLINE";
    case TurnType::BankTurn: return "BANK_TURN";
    }
    return "STOP_AND_TURN";
}

const pb::ParameterValue *findParam(const pb::SegmentDefinition &s, const char *name)
{
    for (const auto &p : s.parametervalues())
        if (p.name() == name)
            return &p;
    return nullptr;
}

std::optional<double> numberParam(const pb::SegmentDefinition &s, const char *name)
{
    const pb::ParameterValue *p = findParam(s, name);
    return p ? parseHciDouble(p->value()) : std::nullopt;
}

void setParam(pb::SegmentDefinition &s, const char *name, const std::string &value)
{
    for (auto &p : *s.mutable_parametervalues()) {
        if (p.name() == name) {
            if (p.value() != value)
                p.set_value(value);
            return;
        }
    }
    auto *p = s.add_parametervalues();
    p->set_name(name);
    p->set_value(value);
}

void setNumber(pb::SegmentDefinition &s, const char *name, double v) { setParam(s, name, javaDoubleString(v)); }

AltitudeType altitudeTypeOf(const pb::SegmentDefinition &s, const pb::FigurePoint *point)
{
    if (point && point->has_altitudetype())
        return point->altitudetype() == pb::AT_WGS84 ? AltitudeType::Amsl : AltitudeType::Agl;
    if (const pb::ParameterValue *p = findParam(s, "altitudeType"))
        return p->value() == "AMSL" || p->value() == "WGS84" ? AltitudeType::Amsl : AltitudeType::Agl;
    return AltitudeType::Agl;
}

// The route profile's camera payload, if it has one with a full sensor description.
std::optional<Camera> profileCamera(const pb::VehicleProfile *profile)
{
    if (!profile)
        return std::nullopt;
    for (const auto &link : profile->payloadprofiles()) {
        const pb::PayloadProfile &pp = link.payloadprofile();
        if (pp.payloadtype() != pb::PT_CAMERA)
            continue;
        Camera c;
        c.name = QString::fromStdString(pp.name());
        int found = 0;
        for (const auto &param : pp.parameters()) {
            switch (param.type()) {
            case pb::PPT_TRUE_FOCAL_LENGTH: c.focalLengthMm = param.value(); ++found; break;
            case pb::PPT_SENSOR_WIDTH: c.sensorWidthMm = param.value(); ++found; break;
            case pb::PPT_SENSOR_HEIGHT: c.sensorHeightMm = param.value(); ++found; break;
            case pb::PPT_SENSOR_HORIZONTAL_PIXELS: c.imageWidthPx = int(param.value()); ++found; break;
            case pb::PPT_SENSOR_VERTICAL_PIXELS: c.imageHeightPx = int(param.value()); ++found; break;
            default: break;
            }
        }
        if (found == 5)
            return c;
    }
    return std::nullopt;
}

Result<Waypoint> waypointFromHci(const pb::SegmentDefinition &s, const HciSegmentContext &ctx)
{
    Waypoint w;
    const std::string &algorithm = s.algorithmclassname();
    const pb::FigureType ft = s.figure().type();
    w.role = (algorithm == kTakeoffAlgorithm || ft == pb::FT_TAKEOFF_POINT) ? WaypointRole::Takeoff
           : (algorithm == kLandingAlgorithm || ft == pb::FT_LANDING_POINT) ? WaypointRole::Land : WaypointRole::Pass;
    if (s.figure().points_size() < 1)
        return MissionError{QStringLiteral("the waypoint has no figure point"), {}, 0, 0, {}};
    const pb::FigurePoint &p = s.figure().points(0);
    w.position = {p.latitude() / kDeg, p.longitude() / kDeg};
    if (!w.position.isValid())
        return MissionError{QStringLiteral("the waypoint's position is out of range"), {}, 0, 0, {}};
    w.altitudeType = altitudeTypeOf(s, &p);
    w.altitude = w.altitudeType == AltitudeType::Amsl ? p.wgs84altitude() : p.aglaltitude();
    w.speed = numberParam(s, "speed").value_or(ctx.defaultSpeed);
    if (const pb::ParameterValue *t = findParam(s, "wpTurnType")) {
        for (TurnType tt : {TurnType::StopAndTurn, TurnType::Straight, TurnType::Spline, TurnType::BankTurn})
            if (t->value() == turnName(tt))
                w.turnType = tt;
    }
    w.acceptanceRadius = numberParam(s, "acceptanceRadius").value_or(0.0);
    for (const auto &d : s.actiondefinitions())
        w.actions.push_back(actionFromHci(d));
    return w;
}

AreaScan scanFromHci(const pb::SegmentDefinition &s, const HciSegmentContext &ctx, QStringList *notices)
{
    AreaScan scan;
    for (const auto &p : s.figure().points())
        scan.polygon.push_back({p.latitude() / kDeg, p.longitude() / kDeg});
    AreaScanParameters &p = scan.parameters;
    p.altitude = numberParam(s, "height").value_or(p.altitude);
    p.altitudeType = altitudeTypeOf(s, nullptr);
    p.sideOverlapPercent = numberParam(s, "sideOverlap").value_or(p.sideOverlapPercent);
    p.frontOverlapPercent = numberParam(s, "forwardOverlap").value_or(p.frontOverlapPercent);
    p.directionDeg = numberParam(s, "directionAngle").value_or(p.directionDeg);
    p.turnaroundMeters = numberParam(s, "overshoot").value_or(p.turnaroundMeters);
    p.speed = numberParam(s, "speed").value_or(ctx.defaultSpeed);
    if (const auto gsd = numberParam(s, "groundSampleDistance")) {
        p.heightMode = ScanHeightMode::GroundSampleDistance;
        p.groundSampleDistanceCm = *gsd;
    }
    const auto sw = numberParam(s, "cameraSensorWidth"), sh = numberParam(s, "cameraSensorHeight"),
               f = numberParam(s, "cameraFocalLength"), iw = numberParam(s, "cameraImageWidth"), ih = numberParam(s, "cameraImageHeight");
    if (sw && sh && f && iw && ih) {
        const pb::ParameterValue *name = findParam(s, "cameraName");
        p.camera = {name ? QString::fromStdString(name->value()) : QString(), *sw, *sh, *f, int(*iw), int(*ih)};
    } else if (const auto c = profileCamera(ctx.profile)) {
        p.camera = *c;
    } else if (notices) {
        *notices << QStringLiteral("An area scan came without a camera; Sortie's default camera (%1) was assumed.").arg(p.camera.name);
    }
    syncDerivedFields(p);
    return scan;
}

void waypointToHci(const Waypoint &w, const Waypoint *before, pb::SegmentDefinition &s)
{
    const bool fresh = !before;
    if (fresh || before->role != w.role) {
        s.set_algorithmclassname(w.role == WaypointRole::Takeoff ? kTakeoffAlgorithm
                                 : w.role == WaypointRole::Land ? kLandingAlgorithm : kWaypointAlgorithm);
        s.mutable_figure()->set_type(w.role == WaypointRole::Takeoff ? pb::FT_TAKEOFF_POINT
                                     : w.role == WaypointRole::Land ? pb::FT_LANDING_POINT : pb::FT_POINT);
    }
    pb::FigurePoint *p = s.mutable_figure()->points_size() > 0 ? s.mutable_figure()->mutable_points(0) : s.mutable_figure()->add_points();
    if (fresh || differs(before->position.latitude, w.position.latitude))
        p->set_latitude(w.position.latitude * kDeg);
    if (fresh || differs(before->position.longitude, w.position.longitude))
        p->set_longitude(w.position.longitude * kDeg);
    const bool typeChanged = fresh || before->altitudeType != w.altitudeType;
    if (typeChanged) {
        p->set_altitudetype(w.altitudeType == AltitudeType::Amsl ? pb::AT_WGS84 : pb::AT_AGL);
    }
    if (typeChanged || differs(before->altitude, w.altitude)) {
        if (w.altitudeType == AltitudeType::Amsl)
            p->set_wgs84altitude(w.altitude);
        else
            p->set_aglaltitude(w.altitude);
    }
    if (fresh || differs(before->speed, w.speed))
        setNumber(s, "speed", w.speed);
    if (fresh || before->turnType != w.turnType)
        setParam(s, "wpTurnType", turnName(w.turnType));
    if (fresh) {
        setParam(s, "avoidObstacles", "true");
        setParam(s, "avoidTerrain", "true");
    }
    if (typeChanged)
        setParam(s, "altitudeType", w.altitudeType == AltitudeType::Amsl ? "AMSL" : "AGL");
    if ((fresh && w.acceptanceRadius != 0) || (!fresh && differs(before->acceptanceRadius, w.acceptanceRadius)))
        setNumber(s, "acceptanceRadius", w.acceptanceRadius);
    if (fresh || before->actions != w.actions) {
        // Merge by position: an action of the same kind at the same index keeps its definition's ids.
        const google::protobuf::RepeatedPtrField<pb::ActionDefinition> old = s.actiondefinitions();
        s.clear_actiondefinitions();
        for (size_t i = 0; i < w.actions.size(); ++i) {
            pb::ActionDefinition def;
            if (before && i < before->actions.size() && int(i) < old.size()
                && actionKindName(before->actions[i]) == actionKindName(w.actions[i]))
                def = old[int(i)];
            actionToHci(w.actions[i], def);
            *s.add_actiondefinitions() = std::move(def);
        }
    }
}

void scanToHci(const AreaScan &a, const AreaScan *before, pb::SegmentDefinition &s)
{
    const bool fresh = !before;
    if (fresh) {
        s.set_algorithmclassname(kAreaScanAlgorithm);
        s.mutable_figure()->set_type(pb::FT_POLYGON);
    }
    if (fresh || before->polygon != a.polygon) {
        auto *points = s.mutable_figure()->mutable_points();
        while (points->size() > int(a.polygon.size()))
            points->RemoveLast();
        for (size_t i = 0; i < a.polygon.size(); ++i) {
            pb::FigurePoint *p = int(i) < points->size() ? points->Mutable(int(i)) : s.mutable_figure()->add_points();
            if (fresh || i >= before->polygon.size() || differs(before->polygon[i].latitude, a.polygon[i].latitude))
                p->set_latitude(a.polygon[i].latitude * kDeg);
            if (fresh || i >= before->polygon.size() || differs(before->polygon[i].longitude, a.polygon[i].longitude))
                p->set_longitude(a.polygon[i].longitude * kDeg);
        }
    }
    const AreaScanParameters &p = a.parameters;
    const AreaScanParameters *b = before ? &before->parameters : nullptr;
    if (!b || differs(scanAltitude(*b), scanAltitude(p))) setNumber(s, "height", scanAltitude(p));
    if (!b || b->altitudeType != p.altitudeType) setParam(s, "altitudeType", p.altitudeType == AltitudeType::Amsl ? "AMSL" : "AGL");
    if (!b || differs(b->sideOverlapPercent, p.sideOverlapPercent)) setNumber(s, "sideOverlap", p.sideOverlapPercent);
    if (!b || differs(b->frontOverlapPercent, p.frontOverlapPercent)) setNumber(s, "forwardOverlap", p.frontOverlapPercent);
    if (!b || differs(b->directionDeg, p.directionDeg)) setNumber(s, "directionAngle", p.directionDeg);
    if (!b || differs(b->turnaroundMeters, p.turnaroundMeters)) setNumber(s, "overshoot", p.turnaroundMeters);
    if (!b || differs(b->speed, p.speed)) setNumber(s, "speed", p.speed);
    if (!b || b->heightMode != p.heightMode || differs(b->groundSampleDistanceCm, p.groundSampleDistanceCm)) {
        if (p.heightMode == ScanHeightMode::GroundSampleDistance) {
            setNumber(s, "groundSampleDistance", p.groundSampleDistanceCm);
        } else {
            auto *params = s.mutable_parametervalues();
            for (int i = params->size() - 1; i >= 0; --i)
                if (params->Get(i).name() == "groundSampleDistance")
                    params->DeleteSubrange(i, 1);
        }
    }
    if (!b || !(b->camera == p.camera)) {
        setParam(s, "cameraName", p.camera.name.toStdString());
        setNumber(s, "cameraSensorWidth", p.camera.sensorWidthMm);
        setNumber(s, "cameraSensorHeight", p.camera.sensorHeightMm);
        setNumber(s, "cameraFocalLength", p.camera.focalLengthMm);
        setNumber(s, "cameraImageWidth", p.camera.imageWidthPx);
        setNumber(s, "cameraImageHeight", p.camera.imageHeightPx);
    }
}
}

Result<Segment> segmentFromHci(const pb::SegmentDefinition &s, const HciSegmentContext &ctx, QStringList *notices)
{
    const std::string &algorithm = s.algorithmclassname();
    if (algorithm == kAreaScanAlgorithm) {
        if (s.figure().type() != pb::FT_POLYGON)
            return MissionError{QStringLiteral("an area scan whose figure is not a polygon"), {}, 0, 0, {}};
        AreaScan scan = scanFromHci(s, ctx, notices);
        scan.origin.message = std::make_shared<const pb::SegmentDefinition>(s);
        return Segment(std::move(scan));
    }
    if (algorithm == kWaypointAlgorithm || algorithm == kTakeoffAlgorithm || algorithm == kLandingAlgorithm) {
        Result<Waypoint> w = waypointFromHci(s, ctx);
        if (!w)
            return w.error();
        Waypoint out = std::move(w).value();
        out.origin.message = std::make_shared<const pb::SegmentDefinition>(s);
        return Segment(std::move(out));
    }
    return MissionError{QStringLiteral("a segment of algorithm \"%1\", which Sortie cannot edit").arg(QString::fromStdString(algorithm)),
                        {}, 0, 0, {}};
}

pb::SegmentDefinition segmentToHci(const Segment &segment, const HciSegmentContext &ctx)
{
    const SegmentOrigin &origin = isWaypoint(segment) ? std::get<Waypoint>(segment).origin : std::get<AreaScan>(segment).origin;
    pb::SegmentDefinition out;
    std::optional<Segment> before;
    if (origin.message) {
        out = *origin.message;
        Result<Segment> decoded = segmentFromHci(*origin.message, ctx, nullptr);
        if (decoded && decoded.value().index() == segment.index())
            before = std::move(decoded).value();
        else
            out.Clear();  // the kind changed: nothing of the old one applies
    }
    if (const Waypoint *w = asWaypoint(segment))
        waypointToHci(*w, before ? &std::get<Waypoint>(*before) : nullptr, out);
    else
        scanToHci(std::get<AreaScan>(segment), before ? &std::get<AreaScan>(*before) : nullptr, out);
    return out;
}

} // namespace sortie::mission
