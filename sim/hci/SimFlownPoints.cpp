#include "SimFlownPoints.h"

#include "Messages.pb.h"

#include <utility>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::vector<SimFlownPoint> read(const pb::ProcessedRoute &route)
{
    std::vector<SimFlownPoint> points;
    double speed = 0;
    for (int s = 0; s < route.segments_size(); ++s) {
        for (const pb::Action &action : route.segments(s).segmentactions()) {
            if (action.has_speedchange() && action.speedchange().groundspeed() > 0)
                speed = action.speedchange().groundspeed();
            SimFlownPoint p;
            const auto fill = [&](const auto &w, bool agl, mission::WaypointRole role) {
                p.latitude = w.latitude() * kDeg;
                p.longitude = w.longitude() * kDeg;
                p.amsl = w.wgs84altitude();
                if (w.has_elevation())
                    p.ground = w.elevation();
                p.agl = agl;
                p.role = role;
            };
            if (action.has_waypoint())
                fill(action.waypoint(), action.waypoint().altitudeframe() == pb::AF_AGL, mission::WaypointRole::Pass);
            else if (action.has_takeoff())
                fill(action.takeoff(), true, mission::WaypointRole::Takeoff);
            else if (action.has_landing())
                fill(action.landing(), true, mission::WaypointRole::Land);
            else
                continue;
            p.segment = s;
            p.speed = speed;
            points.push_back(p);
        }
    }
    return points;
}

} // namespace

std::vector<SimFlownPoint> simFlownPoints(pb::ProcessedRoute &route)
{
    std::vector<SimFlownPoint> points = read(std::as_const(route));
    size_t k = 0;
    for (int s = 0; s < route.segments_size(); ++s)
        for (pb::Action &action : *route.mutable_segments(s)->mutable_segmentactions())
            if (action.has_waypoint() || action.has_takeoff() || action.has_landing())
                points[k++].action = &action;
    return points;
}

std::vector<SimFlownPoint> simFlownPoints(const pb::ProcessedRoute &route)
{
    return read(route);
}

std::vector<mission::LegShape> simFlownLegs(const std::vector<SimFlownPoint> &points)
{
    std::vector<mission::VerticalPoint> vertical;
    vertical.reserve(points.size());
    for (const SimFlownPoint &p : points)
        vertical.push_back({p.role, p.role == mission::WaypointRole::Land || (p.agl && !(p.heightAboveGround() > 0.0))});
    return mission::flownLegs(vertical);
}

double amslOver(const std::vector<SimFlownPoint> &points, size_t whose, size_t at)
{
    const SimFlownPoint &w = points[whose], &a = points[at];
    if (whose == at || !w.agl || !w.ground || !a.ground)
        return w.amsl;
    return *a.ground + w.heightAboveGround();
}

} // namespace sortie::sim
