#include "MissionItems.h"

#include "AlgorithmCatalog.h"
#include "AlgorithmSegment.h"
#include "AreaScan.h"
#include "ElevationService.h"
#include "Route.h"
#include "RouteValidator.h"
#include "ScanPlanCache.h"
#include "SegmentPlanning.h"
#include "TerrainFollow.h"

#include <cmath>
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

MissionAction seriesByDistance(double interval)
{
    return {QStringLiteral("camera_by_distance"), {{QStringLiteral("interval"), interval}, {QStringLiteral("shots"), 0}, {QStringLiteral("delay"), 0.0}}};
}

// The camera commands of a planned point, as sortie-sim's ProcessRoute turns them into actions.
std::vector<MissionAction> cameraActions(const PlannedPoint &p)
{
    std::vector<MissionAction> out;
    for (const CameraCommand &c : p.camera) {
        switch (c.kind) {
        case CameraCommand::Kind::FaceDown:
            out.push_back({QStringLiteral("gimbal"), {{QStringLiteral("tilt"), 90 * kRad}, {QStringLiteral("roll"), 0.0}, {QStringLiteral("yaw"), 0.0}}});
            break;
        case CameraCommand::Kind::FaceHeading:
            out.push_back({QStringLiteral("heading"), {{QStringLiteral("heading"), c.value * kRad}, {QStringLiteral("relativeToNext"), false}}});
            out.push_back({QStringLiteral("gimbal"), {{QStringLiteral("tilt"), 0.0}}});
            break;
        case CameraCommand::Kind::StartSeries:
        case CameraCommand::Kind::StopSeries:
            out.push_back(seriesByDistance(c.value));
            break;
        }
    }
    return out;
}

// A point to fly, its height still in the route's terms.
struct RoutePoint
{
    GeoPoint position;
    double height = 0.0;
    AltitudeType type = AltitudeType::Agl;
    double speed = 0.0;
    double acceptanceRadius = 0.0;
    std::vector<MissionAction> actions;
};

// Puts the route's points into the mission, each height made relative to the vehicle's home.
class MissionBuilder
{
public:
    MissionBuilder(const Route &route, const VciHeights &heights) : m_route(route), m_heights(heights) {}

    std::optional<GeoPoint> lastPosition() const
    {
        return m_lastPosition;
    }

    // Adds one segment's points; an AGL area tool (followTolerance set) follows the ground.
    std::optional<MissionError> add(int row, const std::vector<RoutePoint> &points, std::optional<double> followTolerance)
    {
        if (points.empty())
            return std::nullopt;
        m_lastPosition = points.back().position;
        if (followTolerance && canFollow(points) && follow(points, *followTolerance))
            return std::nullopt;
        for (const RoutePoint &p : points) {
            const std::optional<double> altitude = aboveHome(p);
            if (!altitude)
                return at(row, QStringLiteral("an AMSL altitude needs the vehicle's home altitude, which it has not reported; "
                                              "wait for its telemetry or use AGL"));
            m_mission.items.push_back({p.position.latitude * kRad, p.position.longitude * kRad, *altitude, p.speed, p.acceptanceRadius, p.actions});
        }
        return std::nullopt;
    }

    VciMission finish()
    {
        if (m_levelGround > 0) {
            const QString why = !m_heights.homeAmsl ? QStringLiteral("the vehicle has not reported its home")
                              : !m_heights.elevation || m_heights.elevation->sourceCount() == 0
                                  ? QStringLiteral("no terrain source is set")
                                  : QStringLiteral("no ground is known under them (tried: %1)").arg(m_heights.elevation->triedText());
            m_mission.notices << QStringLiteral("%1 point(s) fly their height above the ground as a height above home, right only over "
                                                "level ground: %2")
                                     .arg(m_levelGround)
                                     .arg(why);
        }
        return std::move(m_mission);
    }

    MissionError at(int row, const QString &why) const
    {
        return missionError(QStringLiteral("%1: %2").arg(segmentLabel(m_route, row), why));
    }

private:
    // The ground under a point, nullopt where unknown (noting a source still asking).
    std::optional<double> ground(const GeoPoint &p)
    {
        if (!m_heights.elevation)
            return std::nullopt;
        const terrain::GroundSample g = m_heights.elevation->sample(p);
        if (g.status == terrain::SampleStatus::Pending)
            m_mission.waitingFor = m_heights.elevation->triedText();
        return g.hasValue() ? std::optional<double>(g.ground) : std::nullopt;
    }

    // The point's height above home; nullopt for an AMSL height without the home's altitude.
    std::optional<double> aboveHome(const RoutePoint &p)
    {
        if (p.type == AltitudeType::Amsl) {
            if (!m_heights.homeAmsl)
                return std::nullopt;
            return p.height - *m_heights.homeAmsl;
        }
        if (m_heights.homeAmsl)
            if (const std::optional<double> g = ground(p.position))
                return *g + p.height - *m_heights.homeAmsl;
        ++m_levelGround;
        return p.height;
    }

    bool canFollow(const std::vector<RoutePoint> &points) const
    {
        if (!m_heights.elevation || !m_heights.homeAmsl)
            return false;
        for (const RoutePoint &p : points)
            if (p.type != AltitudeType::Agl)
                return false;
        return true;
    }

    // The points with those terrain following adds between them (flying the leg's speed, no
    // actions); false, leaving the mission as it was, where the ground is not known everywhere.
    bool follow(const std::vector<RoutePoint> &points, double tolerance)
    {
        std::vector<terrain::FollowVertex> pass;
        pass.reserve(points.size());
        for (const RoutePoint &p : points)
            pass.push_back({p.position, p.height});
        terrain::FollowOptions options;
        options.tolerance = tolerance;
        options.probeStep = kFollowProbeStep;
        const terrain::FollowResult followed = terrain::followTerrain(pass, options, *m_heights.elevation);
        if (followed.status == terrain::SampleStatus::Pending)
            m_mission.waitingFor = m_heights.elevation->triedText();
        if (!followed.ok())
            return false;
        size_t next = 0;  // the vertex the next leg arrives at
        for (const terrain::FollowPoint &f : followed.points) {
            const RoutePoint &leg = points[f.vertex >= 0 ? size_t(f.vertex) : std::min(next, points.size() - 1)];
            MissionItem item{f.position.latitude * kRad, f.position.longitude * kRad, f.altitudeAmsl - *m_heights.homeAmsl, leg.speed, 0, {}};
            if (f.vertex >= 0) {
                item.acceptanceRadius = leg.acceptanceRadius;
                item.actions = leg.actions;
                next = size_t(f.vertex) + 1;
            }
            m_mission.items.push_back(std::move(item));
        }
        return true;
    }

    // Probes every 10 m, as sortie-sim's processing does (SimRouteTerrain::kStep).
    static constexpr double kFollowProbeStep = 10.0;

    const Route &m_route;
    const VciHeights &m_heights;
    VciMission m_mission;
    std::optional<GeoPoint> m_lastPosition;
    int m_levelGround = 0;
};

// A waypoint as it is.
Result<std::vector<RoutePoint>> waypointPoints(const Waypoint &w)
{
    RoutePoint p{w.position, w.altitude, w.altitudeType, w.speed, w.acceptanceRadius, {}};
    for (const WaypointAction &a : w.actions) {
        auto action = vciAction(a);
        if (!action)
            return action.error();
        p.actions.push_back(*action);
    }
    if (w.role == WaypointRole::Land)
        p.actions.push_back({QStringLiteral("land"), {}});
    return std::vector<RoutePoint>{std::move(p)};
}

// Sortie's own area scan: its passes, the camera on from the first point to the last.
Result<std::vector<RoutePoint>> scanPoints(const AreaScan &scan, ScanPlanCache *cache)
{
    AreaScanOutcome scratch;
    const AreaScanOutcome &outcome = scanOutcome(scan, cache, scratch);
    if (!outcome.ok() || outcome.plan->path.empty())
        return missionError(outcome.message.isEmpty() ? QStringLiteral("cannot be planned") : outcome.message);
    const AreaScanPlan &plan = *outcome.plan;
    std::vector<RoutePoint> points;
    points.reserve(plan.path.size());
    for (const GeoPoint &p : plan.path)
        points.push_back({p, plan.altitude, scan.parameters.altitudeType, scan.parameters.speed, 0, {}});
    points.front().actions.push_back(seriesByDistance(plan.triggerDistance));
    points.back().actions.push_back(seriesByDistance(0.0));
    return points;
}

// Any other UgCS tool, planned as sortie-sim's ProcessRoute plans it: camera commands and the
// segment's own actions where the plan runs them, a landing's "land".
Result<std::vector<RoutePoint>> algorithmPoints(const AlgorithmSegment &segment, const Route &route, std::optional<GeoPoint> from)
{
    std::vector<MissionAction> own;
    for (const WaypointAction &a : segment.actions) {
        auto action = vciAction(a);
        if (!action)
            return action.error();
        own.push_back(*action);
    }
    if (!AlgorithmCatalog::builtIn().byClassName(segment.algorithm))
        return missionError(QStringLiteral("only a UgCS server that knows %1 can plan it, and a VCI vehicle flies planned points only")
                                .arg(segment.algorithm));
    PlanContext context = planContextOf(route.settings);
    context.previousPosition = from;
    const SegmentPlanOutcome outcome = planAlgorithmSegment(segment, AlgorithmCatalog::builtIn(), context);
    if (!outcome.ok() || outcome.plan->points.empty()) {
        const QStringList errors(outcome.errors.begin(), outcome.errors.end());
        return missionError(errors.isEmpty() ? QStringLiteral("cannot be planned") : errors.join(QStringLiteral("; ")));
    }
    std::vector<RoutePoint> points;
    points.reserve(outcome.plan->points.size());
    for (const PlannedPoint &p : outcome.plan->points) {
        RoutePoint point{p.position, p.height, p.frame == HeightFrame::Amsl ? AltitudeType::Amsl : AltitudeType::Agl,
                         p.speed > 0 ? p.speed : route.settings.initialSpeed, 0, cameraActions(p)};
        if (p.userActions)
            point.actions.insert(point.actions.end(), own.begin(), own.end());
        if (p.kind == PlannedPoint::Kind::Landing)
            point.actions.push_back({QStringLiteral("land"), {}});
        points.push_back(std::move(point));
    }
    return points;
}

} // namespace

Result<VciMission> vciMissionFor(const Route &route, const VciHeights &heights, ScanPlanCache *cache)
{
    MissionBuilder builder(route, heights);
    for (size_t row = 0; row < route.segments.size(); ++row) {
        const Segment &segment = route.segments[row];
        Result<std::vector<RoutePoint>> points = missionError(QStringLiteral("cannot be planned"));
        if (const Waypoint *w = asWaypoint(segment))
            points = waypointPoints(*w);
        else if (const AreaScan *scan = std::get_if<AreaScan>(&segment))
            points = scanPoints(*scan, cache);
        else if (const AlgorithmSegment *a = asAlgorithmSegment(segment))
            points = algorithmPoints(*a, route, builder.lastPosition());
        if (!points)
            return builder.at(int(row), points.error().message);
        if (auto error = builder.add(int(row), *points, terrain::terrainFollowTolerance(segment)))
            return *error;
    }
    VciMission mission = builder.finish();
    if (mission.items.empty())
        return missionError(QStringLiteral("the route has no waypoints to fly"));
    return mission;
}

namespace {

bool sameAction(const MissionAction &a, const MissionAction &b)
{
    if (a.type != b.type || a.parameters.keys() != b.parameters.keys())
        return false;
    for (auto it = a.parameters.begin(); it != a.parameters.end(); ++it) {
        const QVariant &other = b.parameters.value(it.key());
        bool na = false, nb = false;
        const double x = it.value().toDouble(&na), y = other.toDouble(&nb);
        if (na && nb && it.value().typeId() != QMetaType::QString && other.typeId() != QMetaType::QString) {
            if (std::abs(x - y) > 1e-9 * std::max(1.0, std::abs(x)))
                return false;
        } else if (it.value().toString() != other.toString()) {
            return false;
        }
    }
    return true;
}

} // namespace

QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &back)
{
    if (sent.size() != back.size())
        return QStringLiteral("the vehicle holds %1 waypoint(s), %2 were sent").arg(back.size()).arg(sent.size());
    constexpr double kAngle = 1e-3 / 6378137.0; // a millimetre on the ground, in radians
    for (size_t i = 0; i < sent.size(); ++i) {
        const MissionItem &s = sent[i], &b = back[i];
        const QString where = QStringLiteral("waypoint %1: ").arg(i + 1);
        if (std::abs(s.latitude - b.latitude) > kAngle || std::abs(s.longitude - b.longitude) > kAngle)
            return where + QStringLiteral("the vehicle holds another position");
        if (std::abs(s.altitude - b.altitude) > 1e-3)
            return where + QStringLiteral("altitude %1 m, sent %2 m").arg(b.altitude).arg(s.altitude);
        if (s.speed > 0 && std::abs(s.speed - b.speed) > 1e-3)
            return where + QStringLiteral("speed %1 m/s, sent %2 m/s").arg(b.speed).arg(s.speed);
        if (s.acceptanceRadius > 0 && std::abs(s.acceptanceRadius - b.acceptanceRadius) > 1e-3)
            return where + QStringLiteral("acceptance radius %1 m, sent %2 m").arg(b.acceptanceRadius).arg(s.acceptanceRadius);
        if (s.actions.size() != b.actions.size())
            return where + QStringLiteral("%1 action(s), sent %2").arg(b.actions.size()).arg(s.actions.size());
        for (size_t a = 0; a < s.actions.size(); ++a) {
            if (!sameAction(s.actions[a], b.actions[a]))
                return where + QStringLiteral("action %1 (%2) differs").arg(a + 1).arg(s.actions[a].type);
        }
    }
    return {};
}

} // namespace sortie::vehicle
