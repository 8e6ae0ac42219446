#include "HciSegmentMapper.h"

#include "Domain.pb.h"
#include "CameraProto.h"
#include "HciActionMapper.h"
#include "HciOrigin.h"
#include "HciRouteMapper.h"
#include "HciText.h"
#include "SegmentParameters.h"

#include <algorithm>
#include <numbers>
#include <QCoreApplication>

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

void eraseParam(pb::SegmentDefinition &s, const char *name)
{
    auto *params = s.mutable_parametervalues();
    for (int i = params->size() - 1; i >= 0; --i)
        if (params->Get(i).name() == name)
            params->DeleteSubrange(i, 1);
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

// The route profile's camera payload, if it has one with a full sensor description (UgCS gives
// the optics in SI metres: cameraFromPayload converts).
std::optional<Camera> profileCamera(const pb::VehicleProfile *profile)
{
    if (!profile)
        return std::nullopt;
    for (const auto &link : profile->payloadprofiles())
        if (auto camera = cameraFromPayload(link.payloadprofile()))
            return camera;
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
        return MissionError{QCoreApplication::translate("HciSegmentMapper", "the waypoint has no figure point"), {}, 0, 0, {}};
    const pb::FigurePoint &p = s.figure().points(0);
    w.position = {p.latitude() / kDeg, p.longitude() / kDeg};
    if (!w.position.isValid())
        return MissionError{QCoreApplication::translate("HciSegmentMapper", "the waypoint's position is out of range"), {}, 0, 0, {}};
    w.altitudeType = altitudeTypeOf(s, &p);
    w.altitude = w.altitudeType == AltitudeType::Amsl ? p.wgs84altitude() : p.aglaltitude();
    w.speed = ctx.defaultSpeed;
    Segment segment = w;
    for (const char *name : {"speed", "wpTurnType", "acceptanceRadius"})  // the rest stays in the origin
        if (const pb::ParameterValue *v = findParam(s, name); v && !v->value().empty())
            setParameterValue(segment, QString::fromLatin1(name), QString::fromStdString(v->value()));
    w = std::get<Waypoint>(std::move(segment));
    for (const auto &d : s.actiondefinitions())
        w.actions.push_back(actionFromHci(d));
    return w;
}

// Polygons travel closed (the first point repeated last); Sortie keeps them open.
std::vector<GeoPoint> openPolygon(const pb::Figure &figure)
{
    std::vector<GeoPoint> polygon;
    for (const auto &p : figure.points())
        polygon.push_back({p.latitude() / kDeg, p.longitude() / kDeg});
    if (polygon.size() > 3 && polygon.front() == polygon.back())
        polygon.pop_back();
    return polygon;
}

AreaScan scanFromHci(const pb::SegmentDefinition &s, const HciSegmentContext &ctx, QStringList *notices)
{
    AreaScan scan;
    scan.polygon = openPolygon(s.figure());
    Segment segment = AreaScan{};
    setParameterValue(segment, QStringLiteral("speed"), ctx.defaultSpeed);
    // The pass spacing is the camera's (overlapSide) when both are given: sideDistance is what
    // Sortie writes beside it for a server that only reads that.
    const bool byOverlap = findParam(s, "overlapSide") != nullptr;
    bool customCamera = false;
    for (const auto &v : s.parametervalues()) {
        const QString name = QString::fromStdString(v.name());
        if (v.value().empty() || (byOverlap && name == QLatin1String("sideDistance")))
            continue;  // "" is "not set"
        QString error;
        const QString key = name == QLatin1String("cameraName") ? QStringLiteral("camera") : name;  // before 0.2
        if (!parameterNames(segment).contains(key))
            continue;  // kept in the origin, written back as it came
        if (!setParameterValue(segment, key, QString::fromStdString(v.value()), &error)) {
            if (notices)
                *notices << QCoreApplication::translate("HciSegmentMapper", "An area scan's %1: %2 It keeps Sortie's default.").arg(name, error);
            continue;
        }
        customCamera |= key.startsWith(QLatin1String("camera"))
            && (key != QLatin1String("camera") || builtInCamera(QString::fromStdString(v.value())));
    }
    scan.parameters = std::get<AreaScan>(segment).parameters;
    AreaScanParameters &p = scan.parameters;
    if (!findParam(s, "altitudeType"))
        p.altitudeType = altitudeTypeOf(s, nullptr);
    if (!customCamera) {
        if (const auto c = profileCamera(ctx.profile)) {
            p.camera = *c;
        } else if (p.sideDistanceMeters <= 0 && notices) {
            *notices << QCoreApplication::translate("HciSegmentMapper", "An area scan came without a camera; Sortie's default camera (%1) was assumed.").arg(p.camera.name);
        }
    }
    syncDerivedFields(p);
    return scan;
}

// Merge by position: an action of the same kind at the same index keeps its definition's ids.
void actionsToHci(const std::vector<WaypointAction> &actions, const std::vector<WaypointAction> *before, pb::SegmentDefinition &s)
{
    const google::protobuf::RepeatedPtrField<pb::ActionDefinition> old = s.actiondefinitions();
    s.clear_actiondefinitions();
    for (size_t i = 0; i < actions.size(); ++i) {
        pb::ActionDefinition def;
        if (before && i < before->size() && int(i) < old.size() && actionKindName((*before)[i]) == actionKindName(actions[i]))
            def = old[int(i)];
        actionToHci(actions[i], def);
        *s.add_actiondefinitions() = std::move(def);
    }
}

// Any other algorithm, as the server described it: figure and parameter text, nothing parsed
// that is not needed, so an algorithm Sortie does not know comes back exactly as it went.
AlgorithmSegment algorithmSegmentFromHci(const pb::SegmentDefinition &s)
{
    AlgorithmSegment a;
    a.algorithm = QString::fromStdString(s.algorithmclassname());
    a.figure = FigureType(int(s.figure().type()));
    for (const pb::FigurePoint &p : s.figure().points()) {
        const AltitudeType type = p.altitudetype() == pb::AT_WGS84 ? AltitudeType::Amsl : AltitudeType::Agl;
        a.points.push_back({{p.latitude() / kDeg, p.longitude() / kDeg}, type == AltitudeType::Amsl ? p.wgs84altitude() : p.aglaltitude(), type});
    }
    if (a.figure == FigureType::Polygon && a.points.size() > 3 && a.points.front().position == a.points.back().position)
        a.points.pop_back();  // sent closed
    for (const auto &fp : s.figure().parameters())
        a.figureParameters.push_back(fp.value());
    for (const auto &v : s.parametervalues())
        a.parameters.push_back({QString::fromStdString(v.name()), QString::fromStdString(v.value())});
    for (const auto &d : s.actiondefinitions())
        a.actions.push_back(actionFromHci(d));
    return a;
}

// Unchanged since read, bit for bit: a NaN the server sent (a segment kept because it did not read
// as its kind) is the same NaN, so an unedited segment goes back exactly as it came.
bool samePoints(const std::vector<FigurePoint> &a, const std::vector<FigurePoint> &b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const FigurePoint &x, const FigurePoint &y) {
        return !differs(x.position.latitude, y.position.latitude) && !differs(x.position.longitude, y.position.longitude)
            && !differs(x.altitude, y.altitude) && x.altitudeType == y.altitudeType;
    });
}

void algorithmSegmentToHci(const AlgorithmSegment &a, const AlgorithmSegment *before, pb::SegmentDefinition &s)
{
    const bool fresh = !before;
    if (fresh || before->algorithm != a.algorithm)
        s.set_algorithmclassname(a.algorithm.toStdString());
    if (fresh || before->figure != a.figure)
        s.mutable_figure()->set_type(pb::FigureType(int(a.figure)));
    if (fresh || !samePoints(before->points, a.points)) {
        const bool closed = a.figure == FigureType::Polygon && !a.points.empty();
        const size_t n = a.points.size() + (closed ? 1 : 0);
        auto *points = s.mutable_figure()->mutable_points();
        while (points->size() > int(n))
            points->RemoveLast();
        for (size_t i = 0; i < n; ++i) {
            const FigurePoint &f = a.points[i % a.points.size()];
            const bool exists = int(i) < points->size();
            pb::FigurePoint *p = exists ? points->Mutable(int(i)) : s.mutable_figure()->add_points();
            if (!exists || differs(p->latitude() / kDeg, f.position.latitude))
                p->set_latitude(f.position.latitude * kDeg);
            if (!exists || differs(p->longitude() / kDeg, f.position.longitude))
                p->set_longitude(f.position.longitude * kDeg);
            const pb::AltitudeType type = f.altitudeType == AltitudeType::Amsl ? pb::AT_WGS84 : pb::AT_AGL;
            if (!exists || !p->has_altitudetype() || p->altitudetype() != type)
                p->set_altitudetype(type);
            const double current = type == pb::AT_WGS84 ? p->wgs84altitude() : p->aglaltitude();
            if (!exists || differs(current, f.altitude))
                type == pb::AT_WGS84 ? p->set_wgs84altitude(f.altitude) : p->set_aglaltitude(f.altitude);
        }
    }
    if (fresh || before->figureParameters != a.figureParameters) {
        auto *params = s.mutable_figure()->mutable_parameters();
        while (params->size() > int(a.figureParameters.size()))
            params->RemoveLast();
        for (size_t i = 0; i < a.figureParameters.size(); ++i) {
            pb::FigureParameter *p = int(i) < params->size() ? params->Mutable(int(i)) : s.mutable_figure()->add_parameters();
            if (differs(p->value(), a.figureParameters[i]) || !p->has_value())
                p->set_value(a.figureParameters[i]);
        }
    }
    if (fresh || before->parameters != a.parameters) {
        if (before)
            for (const ParameterValue &v : before->parameters)
                if (!a.value(v.name))
                    eraseParam(s, v.name.toStdString().c_str());
        for (const ParameterValue &v : a.parameters) {
            const QString *old = before ? before->value(v.name) : nullptr;
            if (!old || *old != v.value)
                setParam(s, v.name.toStdString().c_str(), v.value.toStdString());
        }
    }
    if (fresh || before->actions != a.actions)
        actionsToHci(a.actions, before ? &before->actions : nullptr, s);
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
    if (fresh || before->actions != w.actions)
        actionsToHci(w.actions, before ? &before->actions : nullptr, s);
}

// The metres between passes the scan flies: its own sideDistance or the camera's footprint less
// the side overlap.
double passSpacing(const AreaScanParameters &p)
{
    return p.sideDistanceMeters > 0 ? p.sideDistanceMeters : footprintAcrossMeters(p) * (1 - p.sideOverlapPercent / 100.0);
}

void scanToHci(const AreaScan &a, const AreaScan *before, pb::SegmentDefinition &s)
{
    const bool fresh = !before;
    if (fresh) {
        s.set_algorithmclassname(kAreaScanAlgorithm);
        s.mutable_figure()->set_type(pb::FT_POLYGON);
    }
    if (fresh || before->polygon != a.polygon) {
        // Closed on the wire: n corners, then the first again.
        auto *points = s.mutable_figure()->mutable_points();
        const size_t n = a.polygon.size() + 1;
        while (points->size() > int(n))
            points->RemoveLast();
        for (size_t i = 0; i < n; ++i) {
            const GeoPoint &g = a.polygon[i % a.polygon.size()];
            const bool exists = int(i) < points->size();
            pb::FigurePoint *p = exists ? points->Mutable(int(i)) : s.mutable_figure()->add_points();
            if (!exists || differs(p->latitude() / kDeg, g.latitude))
                p->set_latitude(g.latitude * kDeg);
            if (!exists || differs(p->longitude() / kDeg, g.longitude))
                p->set_longitude(g.longitude * kDeg);
            if (!exists) {  // area tools carry 0 m AGL on their corners; the height is a parameter
                p->set_aglaltitude(0);
                p->set_altitudetype(pb::AT_AGL);
            }
        }
    }
    const AreaScanParameters &p = a.parameters;
    const AreaScanParameters *b = before ? &before->parameters : nullptr;
    if (!b || differs(scanAltitude(*b), scanAltitude(p))) setNumber(s, "height", scanAltitude(p));
    if (!b || b->altitudeType != p.altitudeType) setParam(s, "altitudeType", p.altitudeType == AltitudeType::Amsl ? "AMSL" : "AGL");
    if (!b || differs(passSpacing(*b), passSpacing(p))) setNumber(s, "sideDistance", passSpacing(p));
    if (p.sideDistanceMeters > 0) {
        if (!b || b->sideDistanceMeters <= 0)
            eraseParam(s, "overlapSide");
    } else if (!b || differs(b->sideOverlapPercent, p.sideOverlapPercent) || b->sideDistanceMeters > 0) {
        setNumber(s, "overlapSide", p.sideOverlapPercent);
    }
    if (!b || differs(b->frontOverlapPercent, p.frontOverlapPercent)) setNumber(s, "overlapForward", p.frontOverlapPercent);
    if (!b || differs(b->directionDeg, p.directionDeg)) setNumber(s, "directionAngle", p.directionDeg);
    if (!b || differs(b->turnaroundMeters, p.turnaroundMeters)) setNumber(s, "overshoot", p.turnaroundMeters);
    if (!b || differs(b->speed, p.speed)) setNumber(s, "speed", p.speed);
    if (!b || b->toleranceMeters.has_value() != p.toleranceMeters.has_value()
        || (p.toleranceMeters && differs(*b->toleranceMeters, *p.toleranceMeters))) {
        if (p.toleranceMeters)
            setNumber(s, "tolerance", *p.toleranceMeters);
        else
            eraseParam(s, "tolerance");
    }
    if (!b || b->heightMode != p.heightMode || differs(b->groundSampleDistanceCm, p.groundSampleDistanceCm)) {
        if (p.heightMode == ScanHeightMode::GroundSampleDistance)
            setNumber(s, "groundSampleDistance", p.groundSampleDistanceCm);
        else
            eraseParam(s, "groundSampleDistance");
    }
    if (!b || !(b->camera == p.camera)) {
        eraseParam(s, "cameraName");
        setParam(s, "camera", p.camera.name.toStdString());
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
    const ServerOrigin origin = hciOrigin(s);
    if (algorithm == kAreaScanAlgorithm && s.figure().type() == pb::FT_POLYGON && s.figure().points_size() >= 3) {
        AreaScan scan = scanFromHci(s, ctx, notices);
        scan.origin = origin;
        return Segment(std::move(scan));
    }
    if (algorithm == kWaypointAlgorithm || algorithm == kTakeoffAlgorithm || algorithm == kLandingAlgorithm) {
        if (Result<Waypoint> w = waypointFromHci(s, ctx)) {
            Waypoint out = std::move(w).value();
            out.origin = origin;
            return Segment(std::move(out));
        } else if (notices) {
            *notices << QCoreApplication::translate("HciSegmentMapper", "A %1 segment could not be read as one (%2); it is kept as the server sent it.")
                            .arg(QString::fromStdString(algorithm).section(QLatin1Char('.'), -1), w.error().message);
        }
    } else if (algorithm == kAreaScanAlgorithm && notices) {
        *notices << QCoreApplication::translate("HciSegmentMapper", "An area scan without a polygon of three corners is kept as the server sent it.");
    }
    // Any other algorithm (or one that does not read as its kind) is kept as the server described it.
    AlgorithmSegment other = algorithmSegmentFromHci(s);
    other.origin = origin;
    return Segment(std::move(other));
}

pb::SegmentDefinition segmentToHci(const Segment &segment, const HciSegmentContext &ctx)
{
    const pb::SegmentDefinition *origin = hciSegment(originOf(segment));
    pb::SegmentDefinition out;
    std::optional<Segment> before;
    if (origin) {
        out = *origin;
        Result<Segment> decoded = segmentFromHci(*origin, ctx, nullptr);
        if (decoded && decoded.value().index() == segment.index())
            before = std::move(decoded).value();
        else
            out.Clear();  // the kind changed: nothing of the old one applies
    }
    if (const Waypoint *w = asWaypoint(segment))
        waypointToHci(*w, before ? &std::get<Waypoint>(*before) : nullptr, out);
    else if (const AreaScan *scan = asAreaScan(segment))
        scanToHci(*scan, before ? &std::get<AreaScan>(*before) : nullptr, out);
    else
        algorithmSegmentToHci(std::get<AlgorithmSegment>(segment), before ? &std::get<AlgorithmSegment>(*before) : nullptr, out);
    return out;
}

} // namespace sortie::mission
