#include "SimRouteTerrain.h"

#include "AlgorithmCatalog.h"
#include "Messages.pb.h"
#include "PathSampling.h"
#include "SimFlownPoints.h"
#include "SimTerrain.h"
#include "TerrainFollow.h"

#include <QString>

#include <cmath>
#include <optional>
#include <vector>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::optional<double> safeDistanceOf(const pb::VehicleProfile &profile)
{
    for (const auto &p : profile.parameters())
        if (p.type() == pb::VPT_SAFE_DISTANCE_TO_TERRAIN && p.value() >= 0)
            return p.value();
    return std::nullopt;
}

void fail(pb::ProcessedSegment *segment, const QString &text)
{
    segment->set_status(pb::RPS_INVALID);
    auto *m = segment->mutable_messageset()->add_messages();
    m->set_severity(pb::MS_ERROR);
    m->set_defaulttext(text.toStdString());
}

QString metres(double v)
{
    return QString::number(v, 'f', 1);
}

struct Point
{
    double latitude, longitude, amsl;
    int segment;
    int number;   // 1-based among the route's flown points
    bool placed;  // false: its height above sea level is unknown (AGL over no data)
};

// The tolerance within which a segment's AGL waypoints follow the terrain: an algorithm with a
// `tolerance` parameter (UgCS's area tools); unset, the default. nullopt: it does not follow.
std::optional<double> followTolerance(const pb::SegmentDefinition &definition)
{
    const mission::AlgorithmDefinition *algorithm =
        mission::AlgorithmCatalog::builtIn().byClassName(QString::fromStdString(definition.algorithmclassname()));
    if (!algorithm || !algorithm->parameter(u"tolerance"))
        return std::nullopt;
    for (const auto &p : definition.parametervalues())
        if (p.name() == "tolerance") {
            bool ok = false;
            const double value = QString::fromStdString(p.value()).toDouble(&ok);
            if (ok && value >= 0)
                return value;
        }
    return terrain::kDefaultFollowTolerance;
}

bool isAglWaypoint(const pb::Action &a)
{
    return a.has_waypoint() && a.waypoint().altitudeframe() == pb::AF_AGL;
}

// Adds waypoints between consecutive AGL waypoints of the segment where a straight climb would
// stray more than `tolerance` from the ground (probed every `step` metres). Each added point is a
// copy of the waypoint it leads to (same turn, radius), its height above the ground interpolated,
// still processed over flat ground (the placement below puts it on the real ground). A leg with
// no data under it is left straight: its waypoints' own checks speak for it.
void followTerrain(pb::ProcessedSegment &segment, const SimTerrain &terrain, double tolerance, double step)
{
    google::protobuf::RepeatedPtrField<pb::Action> out;
    const pb::Action *previous = nullptr;
    for (const pb::Action &action : segment.segmentactions()) {
        if (isAglWaypoint(action) && previous) {
            const pb::Waypoint &a = previous->waypoint(), &b = action.waypoint();
            const terrain::SampledPath path = terrain::samplePath(
                {{a.latitude() * kDeg, a.longitude() * kDeg}, {b.latitude() * kDeg, b.longitude() * kDeg}}, step);
            std::vector<double> distance, ground;
            bool complete = true;
            for (const terrain::PathSamplePoint &p : path.points) {
                const std::optional<double> g = terrain.groundAt(p.position.latitude, p.position.longitude);
                complete = complete && g.has_value();
                distance.push_back(p.distance);
                ground.push_back(g.value_or(0.0));
            }
            if (complete && path.points.size() > 2) {
                std::vector<bool> keep(path.points.size(), false);
                terrain::markFollowPoints(distance, ground, tolerance, 0, path.points.size() - 1, keep);
                const double aglA = a.wgs84altitude() - a.elevation(), aglB = b.wgs84altitude() - b.elevation();
                const double length = distance.back();
                for (size_t i = 1; i + 1 < keep.size(); ++i) {
                    if (!keep[i])
                        continue;
                    pb::Action added;
                    added.set_origin(pb::OO_SYSTEM);
                    pb::Waypoint *w = added.mutable_waypoint();
                    *w = b;
                    w->set_latitude(path.points[i].position.latitude / kDeg);
                    w->set_longitude(path.points[i].position.longitude / kDeg);
                    const double f = length > 0 ? distance[i] / length : 0.0;
                    w->set_wgs84altitude(b.elevation() + aglA + f * (aglB - aglA));
                    *out.Add() = std::move(added);
                }
            }
        }
        if (action.has_waypoint() || action.has_takeoff() || action.has_landing())
            previous = isAglWaypoint(action) ? &action : nullptr;
        *out.Add() = action;
    }
    segment.mutable_segmentactions()->Swap(&out);
}

} // namespace

double SimRouteTerrain::safeDistance(const pb::VehicleProfile &routeProfile, const pb::VehicleProfile *stored)
{
    if (const auto d = safeDistanceOf(routeProfile))
        return *d;
    if (stored)
        if (const auto d = safeDistanceOf(*stored))
            return *d;
    return kDefaultSafeDistance;
}

void SimRouteTerrain::apply(pb::ProcessedRoute &route, const SimTerrain &terrain, double safeDistance)
{
    for (int s = 0; s < route.segments_size() && s < route.route().segments_size(); ++s)
        if (const std::optional<double> tolerance = followTolerance(route.route().segments(s)))
            followTerrain(*route.mutable_segments(s), terrain, *tolerance, kStep);

    std::vector<Point> points;
    for (int s = 0; s < route.segments_size(); ++s) {
        auto *segment = route.mutable_segments(s);
        for (auto &action : *segment->mutable_segmentactions()) {
            // Waypoints, take-offs and landings are flown points; each has the same four fields.
            auto place = [&](auto *w, bool agl, bool landing) {
                const double lat = w->latitude() * kDeg, lon = w->longitude() * kDeg;
                const int number = int(points.size()) + 1;
                const std::optional<double> ground = terrain.groundAt(lat, lon);
                if (agl || landing) {
                    const double height = landing ? 0.0 : w->wgs84altitude() - w->elevation();  // processed over flat ground
                    if (!ground) {
                        fail(segment, QStringLiteral("Waypoint %1 is %2 m above the ground, but the terrain (%3) has no data there: "
                                                     "its height above sea level is unknown")
                                          .arg(number).arg(metres(height), terrain.description()));
                        points.push_back({lat, lon, w->wgs84altitude(), s, number, false});
                        return;
                    }
                    w->set_wgs84altitude(*ground + height);
                }
                if (ground)
                    w->set_elevation(*ground);
                else
                    w->clear_elevation();
                points.push_back({lat, lon, w->wgs84altitude(), s, number, true});
            };
            if (action.has_waypoint())
                place(action.mutable_waypoint(), action.waypoint().altitudeframe() == pb::AF_AGL, false);
            else if (action.has_takeoff())
                place(action.mutable_takeoff(), true, false);
            else if (action.has_landing())
                place(action.mutable_landing(), false, true);
        }
    }
    // The legs as they are flown (mission::flownLegs): a take-off climbs straight up to the next
    // point's height first, and is given that height as the altitude it takes off to; a landing is
    // reached at the height the leg left at and descended to straight down. The vertical moves meet
    // the ground on purpose and are not judged; every leg across is.
    std::vector<SimFlownPoint> flown = simFlownPoints(route);
    if (flown.size() != points.size())
        return;
    const std::vector<mission::LegShape> legs = simFlownLegs(flown);
    for (const mission::LegShape &leg : legs)
        if (leg.climbAtStart && leg.departHeight != leg.from && flown[leg.from].action->has_takeoff())
            flown[leg.from].action->mutable_takeoff()->set_wgs84altitude(amslOver(flown, leg.departHeight, leg.from));
    for (const mission::LegShape &leg : legs) {
        const Point &a = points[leg.from], &b = points[leg.to];
        if (!leg.moves() || !a.placed || !b.placed || !points[leg.departHeight].placed)
            continue;  // an unknown height: its segment is refused already
        const double fromAmsl = amslOver(flown, leg.departHeight, leg.from), toAmsl = amslOver(flown, leg.arriveHeight, leg.to);
        const terrain::SampledPath path = terrain::samplePath({{a.latitude, a.longitude}, {b.latitude, b.longitude}}, kStep);
        const double length = path.length();
        double lowest = INFINITY, at = 0;
        for (const terrain::PathSamplePoint &p : path.points) {
            const std::optional<double> ground = terrain.groundAt(p.position.latitude, p.position.longitude);
            if (!ground)
                continue;
            const double f = length > 0 ? p.distance / length : 0.0;
            const double clearance = fromAmsl + f * (toAmsl - fromAmsl) - *ground;
            if (clearance < lowest) {
                lowest = clearance;
                at = p.distance;
            }
        }
        if (lowest < safeDistance)
            fail(route.mutable_segments(b.segment),
                 QStringLiteral("The leg from waypoint %1 to waypoint %2 passes %3 m %4 the ground %5 m along it, closer than the "
                                "safe distance to terrain of %6 m")
                     .arg(a.number).arg(b.number).arg(metres(std::abs(lowest)), lowest < 0 ? QStringLiteral("below") : QStringLiteral("above"),
                                                       metres(at), metres(safeDistance)));
    }
}

} // namespace sortie::sim
