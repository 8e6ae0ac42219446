#include "MissionItems.h"

#include "AreaScan.h"
#include "Route.h"
#include "RouteValidator.h"
#include "ScanPlanCache.h"

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

MissionError at(const Route &route, int row, const QString &why)
{
    return missionError(QStringLiteral("%1: %2").arg(segmentLabel(route, row), why));
}

} // namespace

Result<std::vector<MissionItem>> missionItemsFor(const Route &route, ScanPlanCache *cache)
{
    std::vector<MissionItem> items;
    for (size_t row = 0; row < route.segments.size(); ++row) {
        const Segment &segment = route.segments[row];
        if (const Waypoint *w = asWaypoint(segment)) {
            if (w->altitudeType != AltitudeType::Agl)
                return at(route, int(row), QStringLiteral("an AMSL altitude cannot be flown by a VCI vehicle, which flies above home; use AGL"));
            MissionItem item{w->position.latitude * kRad, w->position.longitude * kRad, w->altitude, w->speed, w->acceptanceRadius, {}};
            for (const WaypointAction &a : w->actions) {
                auto action = vciAction(a);
                if (!action)
                    return at(route, int(row), action.error().message);
                item.actions.push_back(*action);
            }
            if (w->role == WaypointRole::Land)
                item.actions.push_back({QStringLiteral("land"), {}});
            items.push_back(std::move(item));
            continue;
        }
        const AreaScan &scan = std::get<AreaScan>(segment);
        if (scan.parameters.altitudeType != AltitudeType::Agl)
            return at(route, int(row), QStringLiteral("an AMSL altitude cannot be flown by a VCI vehicle, which flies above home; use AGL"));
        AreaScanOutcome scratch;
        const AreaScanOutcome &outcome = scanOutcome(scan, cache, scratch);
        if (!outcome.ok() || outcome.plan->path.empty())
            return at(route, int(row), outcome.message.isEmpty() ? QStringLiteral("cannot be planned") : outcome.message);
        const AreaScanPlan &plan = *outcome.plan;
        const size_t first = items.size();
        for (const GeoPoint &p : plan.path)
            items.push_back({p.latitude * kRad, p.longitude * kRad, plan.altitude, scan.parameters.speed, 0, {}});
        items[first].actions.push_back({QStringLiteral("camera_by_distance"), {{QStringLiteral("interval"), plan.triggerDistance},
                                                                              {QStringLiteral("shots"), 0},
                                                                              {QStringLiteral("delay"), 0.0}}});
        items.back().actions.push_back({QStringLiteral("camera_by_distance"), {{QStringLiteral("interval"), 0.0},
                                                                              {QStringLiteral("shots"), 0},
                                                                              {QStringLiteral("delay"), 0.0}}});
    }
    if (items.empty())
        return missionError(QStringLiteral("the route has no waypoints to fly"));
    return items;
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
