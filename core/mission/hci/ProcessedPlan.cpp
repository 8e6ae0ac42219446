#include "ProcessedPlan.h"

#include "Domain.pb.h"
#include "HciOrigin.h"

#include <numbers>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

int rowOfUuid(const Route *route, const std::string &uuid)
{
    if (!route || uuid.empty())
        return -1;
    for (size_t i = 0; i < route->segments.size(); ++i) {
        const pb::SegmentDefinition *o = hciSegment(originOf(route->segments[i]));
        if (o && o->uuid() == uuid)
            return int(i);
    }
    return -1;
}

void addActions(const google::protobuf::RepeatedPtrField<pb::Action> &actions, bool connection, int segment,
                ProcessedPlan &plan, ProcessedSegment &seg, double &speed)
{
    for (const pb::Action &a : actions) {
        if (a.has_speedchange()) {
            const auto &sc = a.speedchange();
            if (sc.has_groundspeed()) speed = sc.groundspeed();
            else if (sc.has_speed()) speed = sc.speed();
            continue;
        }
        ProcessedWaypoint w;
        w.segment = segment;
        w.connection = connection;
        w.speed = speed;
        if (a.has_waypoint()) {
            const auto &p = a.waypoint();
            w.position = {p.latitude() / kDeg, p.longitude() / kDeg};
            w.altitudeAmsl = p.wgs84altitude();
            w.groundElevation = p.elevation();
            w.frame = AltitudeFrame(int(p.altitudeframe()));
            w.turnType = TurnType(int(p.turntype()));
            w.acceptanceRadius = p.acceptanceradius();
        } else if (a.has_takeoff() || a.has_landing()) {
            const bool takeoff = a.has_takeoff();
            const double lat = takeoff ? a.takeoff().latitude() : a.landing().latitude();
            const double lon = takeoff ? a.takeoff().longitude() : a.landing().longitude();
            w.position = {lat / kDeg, lon / kDeg};
            w.altitudeAmsl = takeoff ? a.takeoff().wgs84altitude() : a.landing().wgs84altitude();
            w.groundElevation = takeoff ? a.takeoff().elevation() : a.landing().elevation();
            w.role = takeoff ? WaypointRole::Takeoff : WaypointRole::Land;
        } else {
            ++seg.actionCount;
            continue;
        }
        plan.waypoints.push_back(w);
        ++seg.waypointCount;
    }
}
}

bool ProcessedPlan::flyable() const
{
    for (const auto &s : segments)
        if (s.status != ProcessingStatus::Processed)
            return false;
    return !segments.empty();
}

ProcessedPlan processedPlanFromHci(const pb::ProcessedRoute &processed, const Route *route)
{
    ProcessedPlan plan;
    double speed = 0.0;
    for (int i = 0; i < processed.segments_size(); ++i) {
        const pb::ProcessedSegment &s = processed.segments(i);
        ProcessedSegment seg;
        seg.uuid = QString::fromStdString(s.uuid());
        seg.routeRow = rowOfUuid(route, s.uuid());
        seg.status = ProcessingStatus(int(s.status()));
        seg.estimatedDistance = s.estimateddistance();
        seg.estimatedTime = s.estimatedtime();
        for (const auto &m : s.messageset().messages())
            seg.messages.push_back({m.severity() == pb::MS_ERROR, QString::fromStdString(m.defaulttext())});
        seg.firstWaypoint = int(plan.waypoints.size());
        // The connection from the previous segment is flown first, then the segment itself.
        addActions(s.connectionactions(), true, i, plan, seg, speed);
        addActions(s.segmentactions(), false, i, plan, seg, speed);
        plan.estimatedTime += seg.estimatedTime;
        plan.segments.push_back(std::move(seg));
    }
    plan.estimatedDistance = processed.has_estimateddistance() ? processed.estimateddistance() : 0.0;
    if (!processed.has_estimateddistance())
        for (const auto &s : plan.segments)
            plan.estimatedDistance += s.estimatedDistance;
    return plan;
}

} // namespace sortie::mission
