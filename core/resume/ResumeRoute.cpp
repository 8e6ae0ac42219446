#include "ResumeRoute.h"

#include "Geodesy.h"
#include "LocalTangentPlane.h"
#include "SegmentWaypoints.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace sortie::resume {

using namespace sortie::mission;

namespace {

// Closer than this to a point of the path is at it (the point's actions belong to the resume).
constexpr double kAtPointMetres = 0.5;

MissionError failure(const QString &message)
{
    MissionError e;
    e.message = message;
    return e;
}

struct FlownPoint
{
    Waypoint waypoint;
    int row = -1;
};

// Every segment as the waypoints it flies, each with its row.
Result<std::vector<FlownPoint>> flownPoints(const Route &route, ScanPlanCache *cache)
{
    std::vector<FlownPoint> points;
    std::optional<GeoPoint> from;
    for (size_t row = 0; row < route.segments.size(); ++row) {
        auto waypoints = segmentWaypoints(route, row, from, cache);
        if (!waypoints)
            return failure(QCoreApplication::translate("ResumeRoute", "%1 cannot be resumed here: %2").arg(segmentLabel(int(row), route.segments[row]), waypoints.error().message));
        for (const Waypoint &w : *waypoints)
            points.push_back({w, int(row)});
        if (!waypoints->empty())
            from = waypoints->back().position;
    }
    return points;
}

// A place on the path: `along` metres on the leg from point `leg` to `leg + 1` (on the only point
// of a one-point path, leg 0 and 0 m).
struct Place
{
    size_t leg = 0;
    double along = 0.0;
};

double legLength(const std::vector<FlownPoint> &path, size_t leg)
{
    return leg + 1 < path.size() ? geodesicDistance(path[leg].waypoint.position, path[leg + 1].waypoint.position) : 0.0;
}

// The point the place is at, or -1 when it lies between two.
int pointAt(const std::vector<FlownPoint> &path, const Place &place)
{
    if (place.along <= kAtPointMetres)
        return int(place.leg);
    if (place.along >= legLength(path, place.leg) - kAtPointMetres)
        return int(place.leg) + 1;
    return -1;
}

GeoPoint positionOf(const std::vector<FlownPoint> &path, const Place &place)
{
    const GeoPoint &a = path[place.leg].waypoint.position;
    if (place.leg + 1 >= path.size() || place.along <= 0)
        return a;
    const auto inverse = geodesicInverse(a, path[place.leg + 1].waypoint.position);
    if (!inverse || inverse->distance <= 0)
        return a;
    return geodesicDirect(a, inverse->azimuth1Deg, std::min(place.along, inverse->distance)).point;
}

// The place on the path nearest to `p`, and how far `p` is from it. Of places as near (within a
// centimetre), the last: a path that passes a place twice has flown it the second time by then.
Place nearestPlace(const std::vector<FlownPoint> &path, const GeoPoint &p, double *distance)
{
    const LocalTangentPlane plane(p);
    const PlanePoint first = plane.project(path.front().waypoint.position);
    Place best;
    *distance = std::hypot(first.x, first.y);
    for (size_t i = 0; i + 1 < path.size(); ++i) {
        const PlanePoint a = plane.project(path[i].waypoint.position), b = plane.project(path[i + 1].waypoint.position);
        const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
        const double t = length2 > 0 ? std::clamp(-(a.x * dx + a.y * dy) / length2, 0.0, 1.0) : 0.0;
        const double d = std::hypot(a.x + t * dx, a.y + t * dy);
        if (d <= *distance + 0.01) {
            *distance = std::min(*distance, d);
            best = {i, t * legLength(path, i)};
        }
    }
    return best;
}

// The last point of the path the reached waypoints come to, matched in order; -1 when none does.
int lastReachedPoint(const std::vector<FlownPoint> &path, const std::vector<GeoPoint> &reached, double tolerance)
{
    int matched = -1;
    for (const GeoPoint &p : reached) {
        if (!p.isValid())
            continue;
        for (size_t j = size_t(matched + 1); j < path.size(); ++j) {
            if (geodesicDistance(path[j].waypoint.position, p) <= tolerance) {
                matched = int(j);
                break;
            }
        }
    }
    return matched;
}

// `metres` further along the path; nullopt beyond its end.
std::optional<Place> advance(const std::vector<FlownPoint> &path, Place place, double metres)
{
    while (true) {
        const double length = legLength(path, place.leg);
        if (place.along + metres <= length + 1e-9) {
            place.along += metres;
            return place;
        }
        metres -= length - place.along;
        if (place.leg + 2 >= path.size())
            return std::nullopt;
        ++place.leg;
        place.along = 0.0;
    }
}

double metresTo(const std::vector<FlownPoint> &path, const Place &place)
{
    double sum = place.along;
    for (size_t i = 0; i < place.leg; ++i)
        sum += legLength(path, i);
    return sum;
}

// What the camera and the vehicle's pointing are doing at a place, from the actions run before it.
struct CameraState
{
    std::optional<CameraSeriesByDistanceAction> byDistance;
    std::optional<CameraSeriesByTimeAction> byTime;
    CameraControlAction gimbal;
    std::optional<WaypointAction> pointing; // the last heading or point of interest
    bool recording = false;

    void apply(const WaypointAction &action)
    {
        if (const auto *d = std::get_if<CameraSeriesByDistanceAction>(&action)) {
            byTime.reset();
            byDistance.reset();
            if (d->intervalMeters > 0)
                byDistance = *d;
        } else if (const auto *t = std::get_if<CameraSeriesByTimeAction>(&action)) {
            byTime.reset();
            byDistance.reset();
            if (t->intervalSeconds > 0)
                byTime = *t;
        } else if (const auto *c = std::get_if<CameraControlAction>(&action)) {
            if (c->tiltDeg) gimbal.tiltDeg = c->tiltDeg;
            if (c->rollDeg) gimbal.rollDeg = c->rollDeg;
            if (c->yawDeg) gimbal.yawDeg = c->yawDeg;
            if (c->zoomLevel) gimbal.zoomLevel = c->zoomLevel;
        } else if (std::holds_alternative<HeadingAction>(action) || std::holds_alternative<PoiAction>(action)) {
            pointing = action;
        } else if (const auto *trigger = std::get_if<CameraTriggerAction>(&action)) {
            if (trigger->state == TriggerState::StartRecording)
                recording = true;
            else if (trigger->state == TriggerState::StopRecording)
                recording = false;
            else if (trigger->state == TriggerState::ToggleRecording)
                recording = !recording;
        }
    }

    // The actions that put a new mission's camera where this one's was.
    std::vector<WaypointAction> restore() const
    {
        std::vector<WaypointAction> out;
        if (gimbal != CameraControlAction{})
            out.emplace_back(gimbal);
        if (pointing)
            out.push_back(*pointing);
        if (recording)
            out.emplace_back(CameraTriggerAction{TriggerState::StartRecording});
        if (byDistance)
            out.emplace_back(*byDistance);
        if (byTime)
            out.emplace_back(*byTime);
        return out;
    }
};

// The camera state once the points before `end` (not including it) have run their actions.
CameraState stateBefore(const std::vector<FlownPoint> &path, size_t end)
{
    CameraState state;
    for (size_t i = 0; i < end && i < path.size(); ++i)
        for (const WaypointAction &a : path[i].waypoint.actions)
            state.apply(a);
    return state;
}

// The state at a place: after the actions of every point reached by then, the place's own included.
CameraState stateAt(const std::vector<FlownPoint> &path, const Place &place)
{
    const int at = pointAt(path, place);
    return stateBefore(path, at >= 0 ? size_t(at) + 1 : place.leg + 1);
}

QString metres(double m)
{
    return QString::number(m, 'f', 0);
}

} // namespace

Result<ResumePlan> resumeRoute(const Route &flown, const ResumeRequest &request, ScanPlanCache *cache)
{
    if (!request.takeoff.isValid())
        return failure(QCoreApplication::translate("ResumeRoute", "the take-off point is not known"));
    auto expanded = flownPoints(flown, cache);
    if (!expanded)
        return expanded.error();
    const std::vector<FlownPoint> &path = *expanded;
    if (path.empty())
        return failure(QCoreApplication::translate("ResumeRoute", "the route has nothing to fly"));

    ResumePlan plan;
    Place place;
    if (request.from == ResumeRequest::From::LastWaypoint) {
        const int reached = lastReachedPoint(path, request.reached, request.waypointTolerance);
        if (reached < 0)
            return failure(QCoreApplication::translate("ResumeRoute", "none of the waypoints the vehicle reached is on this route's path: not this route's flight"));
        place = {size_t(reached), 0.0};
        plan.offPath = geodesicDistance(path[size_t(reached)].waypoint.position, request.reached.back());
        if (request.reached.back().isValid() && plan.offPath > request.waypointTolerance)
            plan.notes << QCoreApplication::translate("ResumeRoute", "The last waypoint the vehicle reached is not one of the route's own: the rest starts at the route's point before it.");
    } else if (request.from == ResumeRequest::From::Place) {
        const auto at = request.placeDistance >= 0 ? advance(path, {}, request.placeDistance) : std::nullopt;
        if (!at || !request.place.isValid())
            return failure(QCoreApplication::translate("ResumeRoute", "the place to resume from is not on the route's path"));
        place = *at;
        plan.offPath = geodesicDistance(positionOf(path, place), request.place);
        if (plan.offPath > request.waypointTolerance)
            return failure(QCoreApplication::translate("ResumeRoute", "the place to resume from is %1 m from where the route's path is that far along").arg(metres(plan.offPath)));
    } else {
        if (!request.lastPhoto.isValid())
            return failure(QCoreApplication::translate("ResumeRoute", "where the last photo was taken is not known"));
        place = nearestPlace(path, request.lastPhoto, &plan.offPath);
        if (plan.offPath > request.tolerance)
            return failure(QCoreApplication::translate("ResumeRoute", "the last photo was taken %1 m from the route's path, more than the %2 m a flight of it strays: not this route's flight")
                               .arg(metres(plan.offPath), metres(request.tolerance)));
    }

    if (request.from == ResumeRequest::From::LastPhoto) {
        // The next photo is due one interval on: resume there, so the series takes it and none twice.
        const CameraState atPhoto = stateAt(path, place);
        double interval = 0.0;
        if (atPhoto.byDistance) {
            interval = atPhoto.byDistance->intervalMeters;
        } else if (atPhoto.byTime) {
            const size_t next = std::min(place.leg + 1, path.size() - 1);
            interval = atPhoto.byTime->intervalSeconds * path[next].waypoint.speed;
            plan.notes << QCoreApplication::translate("ResumeRoute", "The photos were taken every %1 s: the next one is taken as due %2 m on at the leg's speed.")
                              .arg(atPhoto.byTime->intervalSeconds)
                              .arg(metres(interval));
        } else {
            plan.notes << QCoreApplication::translate("ResumeRoute", "No photo series was running at the last photo: the rest starts where it was taken.");
        }
        const auto next = advance(path, place, interval);
        if (!next)
            return failure(QCoreApplication::translate("ResumeRoute", "the last photo was the route's last: nothing is left to fly"));
        place = *next;
    }

    const int at = pointAt(path, place);
    if (at == int(path.size()) - 1)
        return failure(QCoreApplication::translate("ResumeRoute", "the route was flown to its last point: nothing is left to fly"));

    // The resume point: the path's point the place is at (with its own actions after the camera's
    // restored state), or a new one on the leg.
    Waypoint resume;
    size_t firstAfter = 0;
    if (at >= 0) {
        resume = path[size_t(at)].waypoint;
        // The new mission took off already; and a landing there (a planned battery change) is the
        // one that ended the last flight: flown through, the rest goes on.
        resume.role = WaypointRole::Pass;
        std::vector<WaypointAction> actions = stateBefore(path, size_t(at)).restore();
        actions.insert(actions.end(), resume.actions.begin(), resume.actions.end());
        resume.actions = std::move(actions);
        resume.origin = {};
        plan.resumedRow = path[size_t(at)].row;
        firstAfter = size_t(at) + 1;
    } else {
        const Waypoint &from = path[place.leg].waypoint, &to = path[place.leg + 1].waypoint;
        const double t = place.along / std::max(legLength(path, place.leg), 1e-9);
        resume.position = positionOf(path, place);
        resume.altitudeType = to.altitudeType;
        resume.altitude = from.altitudeType == to.altitudeType ? std::lerp(from.altitude, to.altitude, t) : to.altitude;
        resume.speed = to.speed;
        resume.turnType = to.turnType;
        resume.acceptanceRadius = to.acceptanceRadius;
        resume.actions = stateBefore(path, place.leg + 1).restore();
        plan.resumedRow = path[place.leg + 1].row;
        firstAfter = place.leg + 1;
    }
    plan.resumeAt = resume.position;
    plan.flownMetres = metresTo(path, place);
    plan.remainingMetres = metresTo(path, {path.size() - 1, 0.0}) - plan.flownMetres;

    // Take-off where the vehicle stands and the flight over to the resume point at the transit height.
    const RouteSettings &settings = flown.settings;
    const double transit = request.transitAltitude.value_or(resume.altitudeType == AltitudeType::Agl ? std::max(resume.altitude, settings.safeAltitude)
                                                                                                    : resume.altitude);
    Route route;
    route.settings = settings;
    route.settings.name = QCoreApplication::translate("ResumeRoute", "%1 (resumed)").arg(settings.name.isEmpty() ? QCoreApplication::translate("ResumeRoute", "Route") : settings.name);
    route.fence = flown.fence;
    Waypoint takeoff;
    takeoff.position = request.takeoff;
    takeoff.altitude = transit;
    takeoff.altitudeType = resume.altitudeType;
    takeoff.speed = settings.initialSpeed;
    takeoff.role = WaypointRole::Takeoff;
    route.segments.emplace_back(takeoff);
    if (std::abs(transit - resume.altitude) > kAtPointMetres && geodesicDistance(request.takeoff, resume.position) > kAtPointMetres) {
        Waypoint over = takeoff;
        over.position = resume.position;
        over.role = WaypointRole::Pass;
        route.segments.emplace_back(over);
    }
    route.segments.emplace_back(resume);
    // The rest of the resume point's segment as its waypoints, then the later segments as they are.
    for (size_t i = firstAfter; i < path.size() && path[i].row == plan.resumedRow; ++i)
        route.segments.emplace_back(path[i].waypoint);
    route.segments.insert(route.segments.end(), flown.segments.begin() + plan.resumedRow + 1, flown.segments.end());

    const CameraState restored = stateBefore(path, at >= 0 ? size_t(at) : place.leg + 1);
    plan.notes.prepend(QCoreApplication::translate("ResumeRoute", "Resumes %1, %2 m into the flight (%3 m left), after a take-off and a flight over at %4 m.")
                           .arg(segmentLabel(plan.resumedRow, flown.segments[size_t(plan.resumedRow)]), metres(plan.flownMetres),
                                metres(plan.remainingMetres), metres(transit)));
    if (restored.byDistance)
        plan.notes << QCoreApplication::translate("ResumeRoute", "The photo series every %1 m starts again at the resume point.").arg(restored.byDistance->intervalMeters);
    if (restored.byTime)
        plan.notes << QCoreApplication::translate("ResumeRoute", "The photo series every %1 s starts again at the resume point.").arg(restored.byTime->intervalSeconds);
    if (restored.gimbal.tiltDeg)
        plan.notes << QCoreApplication::translate("ResumeRoute", "The gimbal is tilted to %1° there, as it was.").arg(*restored.gimbal.tiltDeg);
    plan.route = std::move(route);
    return plan;
}

} // namespace sortie::resume
