// Planning a route for WPML: its points, heights in the written mode, turns, headings and action groups.
#include "WpmlPlan.h"

#include "AreaScanPlanner.h"
#include "FlightPath.h"
#include "Geodesy.h"
#include "Egm96Geoid.h"
#include "ScanPlanCache.h"
#include "WpmlGeoidAccess.h"

#include <algorithm>
#include <cmath>

namespace sortie::mission::formats::wpml {
namespace {

QString rowText(int segment)
{
    return segment < 0 ? QStringLiteral("the climb point") : QStringLiteral("row %1").arg(segment + 1);
}

double normalizeHeading(double deg)  // into [-180, 180], as rotateYaw wants it
{
    double h = std::fmod(deg, 360.0);
    if (h > 180.0) h -= 360.0;
    if (h < -180.0) h += 360.0;
    return h;
}

// Converts Sortie altitudes into the written height mode, or says why it cannot.
class HeightConverter
{
public:
    HeightConverter(const WpmlExportOptions &o, const Route &route, GeoidAccess *geoid)
        : m_options(o), m_takeoff(takeoffAltitude(o, route)), m_geoid(geoid)
    {
    }

    // {executeHeight, templateHeight}
    Result<std::pair<double, double>> convert(const GeoPoint &p, double altitude, AltitudeType type, const QString &where)
    {
        const auto ground = [&]() -> std::optional<double> {
            return m_options.groundElevationAmsl ? m_options.groundElevationAmsl(p) : std::nullopt;
        };
        switch (m_options.heightMode) {
        case WpmlHeightMode::RelativeToTakeoff:
            if (type == AltitudeType::Amsl) {
                if (!m_takeoff)
                    return refuse(QStringLiteral("%1 is AMSL: writing it relative to take-off needs the take-off's AMSL altitude (set the route's home)").arg(where));
                return std::pair{altitude - *m_takeoff, altitude - *m_takeoff};
            }
            if (const auto g = ground(); g && m_takeoff)
                return std::pair{*g + altitude - *m_takeoff, *g + altitude - *m_takeoff};
            if (!m_aglNoticed) {
                m_aglNoticed = true;
                m_notices << QStringLiteral("AGL altitudes written relative to take-off: equal only over level ground");
            }
            return std::pair{altitude, altitude};
        case WpmlHeightMode::Egm96: {
            double amsl = altitude;
            if (type == AltitudeType::Agl) {
                const auto g = ground();
                if (!g)
                    return refuse(QStringLiteral("%1 is AGL: writing AMSL heights needs the terrain elevation there").arg(where));
                amsl = *g + altitude;
            }
            if (!m_takeoff)
                return refuse(QStringLiteral("AMSL heights: the executable wayline flies relative to take-off and needs the take-off's AMSL altitude (set the route's home)"));
            return std::pair{amsl - *m_takeoff, amsl};
        }
        case WpmlHeightMode::Wgs84: {
            double amsl = altitude;
            if (type == AltitudeType::Agl) {
                const auto g = ground();
                if (!g)
                    return refuse(QStringLiteral("%1 is AGL: writing WGS-84 heights needs the terrain elevation there").arg(where));
                amsl = *g + altitude;
            }
            const auto h = ellipsoidal(p, amsl, where);
            if (!h)
                return h.error();
            return std::pair{*h, amsl};
        }
        case WpmlHeightMode::AboveGroundLevel:
            if (type == AltitudeType::Amsl) {
                const auto g = ground();
                if (!g)
                    return refuse(QStringLiteral("%1 is AMSL: following the terrain needs its elevation there").arg(where));
                return std::pair{altitude - *g, altitude - *g};
            }
            return std::pair{altitude, altitude};
        }
        return refuse(QStringLiteral("unknown height mode"));
    }

    // An AMSL height as WGS-84 ellipsoidal, through the EGM96 geoid.
    Result<double> ellipsoidal(const GeoPoint &p, double amsl, const QString &where)
    {
        const Result<const datum::Egm96Geoid *> geoid = m_geoid->get(QStringLiteral("DJI WPML: WGS-84 heights"));
        if (!geoid)
            return geoid.error();
        const auto h = (*geoid)->ellipsoidalFromAmsl(p.latitude, p.longitude, amsl);
        if (!h)
            return refuse(QStringLiteral("%1: no EGM96 geoid height there").arg(where));
        return *h;
    }

    QStringList notices() const { return m_notices; }
    std::optional<double> takeoff() const { return m_takeoff; }

private:
    const WpmlExportOptions &m_options;
    std::optional<double> m_takeoff;
    GeoidAccess *m_geoid;
    bool m_aglNoticed = false;
    QStringList m_notices;
};

TurnMode turnModeOf(TurnType t, bool *straight)
{
    switch (t) {
    case TurnType::StopAndTurn: *straight = true; return TurnMode::StopStraight;
    case TurnType::Straight: *straight = true; return TurnMode::PassCurved;
    case TurnType::Spline: *straight = false; return TurnMode::PassCurved;
    case TurnType::BankTurn: *straight = false; return TurnMode::Coordinated;
    }
    *straight = true;
    return TurnMode::StopStraight;
}

double bearing(const GeoPoint &a, const GeoPoint &b)
{
    const auto inv = geodesicInverse(a, b);
    return inv ? inv->azimuth1Deg : 0.0;
}

// How many of the first waypoint's actions lead it as gimbal tilts only: the wayline's start actions.
size_t leadingGimbalTilts(const Waypoint &w)
{
    size_t n = 0;
    for (const WaypointAction &a : w.actions) {
        const auto *gimbal = std::get_if<CameraControlAction>(&a);
        if (!gimbal || !gimbal->tiltDeg || gimbal->rollDeg || gimbal->yawDeg || gimbal->zoomLevel)
            break;
        ++n;
    }
    return n;
}

} // namespace

std::optional<double> takeoffAltitude(const WpmlExportOptions &options, const Route &route)
{
    if (options.takeoffAltitudeAmsl)
        return options.takeoffAltitudeAmsl;
    if (route.settings.home)
        return route.settings.home->altitudeAmsl;
    return std::nullopt;
}

Result<Plan> planOf(const Route &route, const WpmlExportOptions &options, const DjiDroneModel &model,
                    const DjiPayload &payload, ScanPlanCache *cache, GeoidAccess *geoid)
{
    Plan plan;
    HeightConverter heights(options, route, geoid);
    // Scans that cannot be planned would fly their first vertex only: refuse them instead.
    for (size_t i = 0; i < route.segments.size(); ++i) {
        if (const AreaScan *scan = asAreaScan(route.segments[i])) {
            AreaScanOutcome scratch;
            const AreaScanOutcome &o = scanOutcome(*scan, cache, scratch);
            if (!o.ok())
                return refuse(QStringLiteral("the area scan at %1 cannot be planned: %2").arg(rowText(int(i)), o.message));
        }
    }
    const std::vector<PathPoint> path = flightPath(route, cache);
    if (options.climbOver && !path.empty()) {
        // Straight up over the take-off spot first (no segment of the route: row -1).
        Point climb;
        climb.position = *options.climbOver;
        climb.speed = path.front().speed;
        // Above the take-off spot by the security height, in every height mode (AMSL in an EGM96 template).
        climb.executeHeight = options.takeoffSecurityHeight;
        climb.templateHeight = climb.executeHeight;
        if (options.heightMode == WpmlHeightMode::Egm96 || options.heightMode == WpmlHeightMode::Wgs84) {
            if (!heights.takeoff())
                return refuse(QStringLiteral("AMSL heights: the climb point needs the take-off's AMSL altitude"));
            climb.templateHeight += *heights.takeoff();
        }
        if (options.heightMode == WpmlHeightMode::Wgs84) {
            const auto h = heights.ellipsoidal(climb.position, climb.templateHeight, QStringLiteral("the climb point"));
            if (!h)
                return h.error();
            climb.executeHeight = *h;
        }
        plan.points.push_back(climb);
    }
    const size_t total = plan.points.size() + path.size();
    if (int(total) < kWpmlMinWaypoints || total > size_t(kWpmlMaxWaypoints))
        return refuse(QStringLiteral("a wayline holds %1 to %2 waypoints; this route flies %3")
                          .arg(kWpmlMinWaypoints).arg(kWpmlMaxWaypoints).arg(total));

    for (size_t k = 0; k < path.size(); ++k) {
        const PathPoint &pp = path[k];
        Point p;
        p.position = pp.position;
        p.speed = pp.speed;
        p.segment = pp.segment;
        const auto h = heights.convert(pp.position, pp.altitude, pp.altitudeType, rowText(pp.segment));
        if (!h)
            return h.error();
        p.executeHeight = h->first;
        p.templateHeight = h->second;
        if (const Waypoint *w = asWaypoint(route.segments[size_t(pp.segment)])) {
            p.turn = turnModeOf(w->turnType, &p.straight);
            if (p.turn == TurnMode::Coordinated)
                p.damping = std::max(0.2, route.settings.cornerRadius > 0 ? route.settings.cornerRadius : w->acceptanceRadius);
        }
        plan.points.push_back(p);
    }
    // The first and last waypoints are where the aircraft starts and ends: it stops there.
    for (Point *p : {&plan.points.front(), &plan.points.back()}) {
        if (p->turn != TurnMode::StopStraight) {
            p->turn = TurnMode::StopStraight;
            p->straight = true;
        }
    }

    // Limits: speed, heights, distances.
    for (size_t k = 0; k < plan.points.size(); ++k) {
        const Point &p = plan.points[k];
        const QString where = rowText(p.segment);
        if (!(p.speed > 0.0) || p.speed > model.maxWaypointSpeed)
            return refuse(QStringLiteral("%1: speed %2 m/s is outside the %3's waypoint speed range (above 0, at most %4 m/s)")
                              .arg(where).arg(p.speed).arg(model.name).arg(model.maxWaypointSpeed));
        // WGS-84 heights are checked above the take-off where its altitude is known.
        const std::optional<double> above = options.heightMode != WpmlHeightMode::Wgs84 ? std::optional<double>(p.executeHeight)
                                            : heights.takeoff() ? std::optional<double>(p.templateHeight - *heights.takeoff())
                                                                : std::nullopt;
        if (above && *above > model.maxAltitudeLimit)
            return refuse(QStringLiteral("%1: %2 m above %3 is above the %4's %5 m altitude limit")
                              .arg(where).arg(*above)
                              .arg(options.heightMode == WpmlHeightMode::AboveGroundLevel ? QStringLiteral("ground") : QStringLiteral("take-off"))
                              .arg(model.name).arg(model.maxAltitudeLimit));
        if (options.heightMode == WpmlHeightMode::AboveGroundLevel && p.executeHeight < 0.0)
            return refuse(QStringLiteral("%1: %2 m is below the ground").arg(where).arg(p.executeHeight));
        if (k > 0) {
            const Point &prev = plan.points[k - 1];
            const double horizontal = geodesicDistance(prev.position, p.position);
            const double vertical = p.executeHeight - prev.executeHeight;
            const double d = std::sqrt(horizontal * horizontal + vertical * vertical);
            if (d < kWpmlMinLegMeters)
                return refuse(QStringLiteral("waypoints %1 and %2 (%3) are %4 m apart; DJI needs at least %5 m between adjacent waypoints")
                                  .arg(k).arg(k + 1).arg(where).arg(d, 0, 'f', 2).arg(kWpmlMinLegMeters));
            // A coordinated turn starts turning this far before its point: within half of each leg.
            if (p.turn == TurnMode::Coordinated)
                plan.points[k].damping = std::min(plan.points[k].damping, horizontal / 2.0);
            if (prev.turn == TurnMode::Coordinated)
                plan.points[k - 1].damping = std::min(plan.points[k - 1].damping, horizontal / 2.0);
        }
    }

    // Actions, in route order. A camera series runs until the next camera action.
    std::optional<Group> series;
    auto endSeries = [&](int at) {
        if (series) {
            series->end = std::max(series->start, at);
            plan.groups.push_back(*series);
            series.reset();
        }
    };
    auto at = [&](int k) -> Group & {
        if (plan.groups.empty() || plan.groups.back().start != k || plan.groups.back().trigger != TriggerType::ReachPoint) {
            Group g;
            g.start = g.end = k;
            plan.groups.push_back(g);
        }
        return plan.groups.back();
    };
    std::optional<std::array<double, 3>> poi;
    int lastSegment = -1;
    for (int k = 0; k < int(plan.points.size()); ++k) {
        Point &p = plan.points[size_t(k)];
        if (p.segment < 0)
            continue;  // the climb point: no actions
        const bool firstOfSegment = p.segment != lastSegment;
        lastSegment = p.segment;
        if (poi) {
            p.heading = HeadingMode::TowardPoi;
            p.poi = poi;
        }
        if (!firstOfSegment)
            continue;
        const Segment &segment = route.segments[size_t(p.segment)];
        const QString where = rowText(p.segment);
        if (const AreaScan *scan = asAreaScan(segment)) {
            // The scan's passes: camera straight down, a photo every forward-overlap distance.
            endSeries(k);
            at(k).actions.push_back({ActuatorFunc::GimbalRotate, -90.0});
            int last = k;
            while (last + 1 < int(plan.points.size()) && plan.points[size_t(last + 1)].segment == p.segment)
                ++last;
            Group g;
            g.start = k;
            g.end = last;
            g.trigger = TriggerType::MultipleDistance;
            g.interval = footprintAlongMeters(scan->parameters) * (1.0 - scan->parameters.frontOverlapPercent / 100.0);
            if (!(g.interval > 0.0))
                return refuse(QStringLiteral("the area scan at %1 has no photo distance (forward overlap %2 %)").arg(where).arg(scan->parameters.frontOverlapPercent));
            g.actions.push_back({ActuatorFunc::TakePhoto, 0.0});
            plan.groups.push_back(g);
            continue;
        }
        const Waypoint &w = std::get<Waypoint>(segment);
        if (w.role == WaypointRole::Takeoff) {
            if (k != 0)
                return refuse(QStringLiteral("%1 is a take-off in the middle of the route; DJI takes off before the first waypoint only").arg(where));
            plan.notices << QStringLiteral("the take-off at %1 is flown as the first waypoint: DJI Pilot 2 takes off to the take-off security height by itself").arg(where);
        }
        if (w.role == WaypointRole::Land) {
            if (k != int(plan.points.size()) - 1)
                return refuse(QStringLiteral("%1 lands in the middle of the route; a DJI route can only land at its end").arg(where));
            plan.finish = FinishAction::AutoLand;
        }
        const double arriving = k > 0 ? bearing(plan.points[size_t(k - 1)].position, p.position)
                                      : (plan.points.size() > 1 ? bearing(p.position, plan.points[1].position) : 0.0);
        // The first waypoint's leading gimbal tilts are set before the wayline, where the aircraft can.
        const size_t startActions = p.segment == 0 && model.startActions ? leadingGimbalTilts(w) : 0;
        for (size_t s = 0; s < startActions; ++s)
            plan.startActions.push_back({ActuatorFunc::GimbalRotate, -*std::get<CameraControlAction>(w.actions[s]).tiltDeg});
        for (size_t actionIndex = startActions; actionIndex < w.actions.size(); ++actionIndex) {
            const WaypointAction &a = w.actions[actionIndex];
            if (const auto *wait = std::get_if<WaitAction>(&a)) {
                if (wait->waitForOperator)
                    return refuse(QStringLiteral("%1: \"wait for the operator\" has no WPML action; use a timed wait").arg(where));
                if (wait->seconds > 0.0)
                    at(k).actions.push_back({ActuatorFunc::Hover, wait->seconds});
            } else if (const auto *heading = std::get_if<HeadingAction>(&a)) {
                double deg = heading->headingDeg;
                if (heading->relativeToNextWaypoint) {
                    if (k + 1 >= int(plan.points.size()))
                        return refuse(QStringLiteral("%1: a heading relative to the next waypoint at the last waypoint").arg(where));
                    deg += bearing(p.position, plan.points[size_t(k + 1)].position);
                }
                at(k).actions.push_back({ActuatorFunc::RotateYaw, normalizeHeading(deg)});
                poi.reset();
            } else if (const auto *target = std::get_if<PoiAction>(&a)) {
                const auto h = heights.convert(target->position, target->altitude, target->altitudeType, where + QStringLiteral("'s point of interest"));
                if (!h)
                    return h.error();
                poi = std::array<double, 3>{target->position.latitude, target->position.longitude, h->first};
                p.heading = HeadingMode::TowardPoi;
                p.poi = poi;
            } else if (const auto *trigger = std::get_if<CameraTriggerAction>(&a)) {
                endSeries(k);
                switch (trigger->state) {
                case TriggerState::SingleShot: at(k).actions.push_back({ActuatorFunc::TakePhoto, 0.0}); break;
                case TriggerState::StartRecording: at(k).actions.push_back({ActuatorFunc::StartRecord, 0.0}); break;
                case TriggerState::StopRecording: at(k).actions.push_back({ActuatorFunc::StopRecord, 0.0}); break;
                case TriggerState::ToggleRecording:
                    return refuse(QStringLiteral("%1: \"toggle recording\" has no WPML action; use start or stop recording").arg(where));
                }
            } else if (const auto *byTime = std::get_if<CameraSeriesByTimeAction>(&a)) {
                endSeries(k);
                if (byTime->shots > 0 || byTime->startDelaySeconds > 0.0)
                    return refuse(QStringLiteral("%1: a photo series with a shot count or a start delay has no WPML trigger; it runs until the next camera action").arg(where));
                if (!(byTime->intervalSeconds > 0.0))
                    return refuse(QStringLiteral("%1: a photo series needs an interval above 0 s").arg(where));
                series = Group{k, k, TriggerType::MultipleTiming, byTime->intervalSeconds, {{ActuatorFunc::TakePhoto, 0.0}}};
            } else if (const auto *byDistance = std::get_if<CameraSeriesByDistanceAction>(&a)) {
                endSeries(k);
                if (byDistance->intervalMeters <= 0.0)
                    continue;  // stops the running series, done above
                if (byDistance->shots > 0 || byDistance->startDelaySeconds > 0.0)
                    return refuse(QStringLiteral("%1: a photo series with a shot count or a start delay has no WPML trigger; it runs until the next camera action").arg(where));
                series = Group{k, k, TriggerType::MultipleDistance, byDistance->intervalMeters, {{ActuatorFunc::TakePhoto, 0.0}}};
            } else if (const auto *pano = std::get_if<PanoramaAction>(&a)) {
                // Turn by steps from the arriving heading, a photo (or the running video) at each.
                endSeries(k);
                if (!(pano->stepAngleDeg > 0.0) || !(pano->angleDeg > 0.0))
                    return refuse(QStringLiteral("%1: a panorama needs a positive angle and step").arg(where));
                const int steps = int(std::floor(pano->angleDeg / pano->stepAngleDeg + 1e-9));
                const double sign = pano->direction == RotationDirection::Clockwise ? 1.0 : -1.0;
                Group &g = at(k);
                if (pano->mode == PanoramaMode::Video)
                    g.actions.push_back({ActuatorFunc::StartRecord, 0.0});
                for (int s = 0; s <= steps; ++s) {
                    if (s > 0)
                        g.actions.push_back({ActuatorFunc::RotateYaw, normalizeHeading(arriving + sign * s * pano->stepAngleDeg)});
                    if (pano->mode == PanoramaMode::Photo)
                        g.actions.push_back({ActuatorFunc::TakePhoto, 0.0});
                    if (pano->stepDelaySeconds > 0.0)
                        g.actions.push_back({ActuatorFunc::Hover, pano->stepDelaySeconds});
                }
                if (pano->mode == PanoramaMode::Video)
                    g.actions.push_back({ActuatorFunc::StopRecord, 0.0});
            } else if (const auto *gimbal = std::get_if<CameraControlAction>(&a)) {
                // WPML pitches -90° looking down where UgCS tilts 90°.
                if (gimbal->rollDeg || gimbal->yawDeg || gimbal->zoomLevel)
                    return refuse(QStringLiteral("%1: only the gimbal's tilt has a WPML action here; roll, yaw and zoom do not").arg(where));
                if (gimbal->tiltDeg)
                    at(k).actions.push_back({ActuatorFunc::GimbalRotate, -*gimbal->tiltDeg});
            } else if (std::holds_alternative<ServerAction>(a)) {
                return refuse(QStringLiteral("%1: the server action \"%2\" has no WPML equivalent").arg(where, describeAction(a)));
            }
        }
    }
    endSeries(int(plan.points.size()) - 1);
    std::stable_sort(plan.groups.begin(), plan.groups.end(), [](const Group &a, const Group &b) { return a.start < b.start; });
    std::vector<Action> all = plan.startActions;
    for (const Group &g : plan.groups)
        all.insert(all.end(), g.actions.begin(), g.actions.end());
    for (const Action &a : all)
        if (a.func == ActuatorFunc::GimbalRotate && (a.value < payload.gimbalPitchMinDeg || a.value > payload.gimbalPitchMaxDeg))
            return refuse(QStringLiteral("gimbal pitch %1° is outside the %2's range (%3° to %4°)")
                              .arg(a.value).arg(payload.name).arg(payload.gimbalPitchMinDeg).arg(payload.gimbalPitchMaxDeg));
    if (plan.finish != FinishAction::AutoLand)
        plan.finish = route.settings.endAction == EndAction::ReturnHome ? FinishAction::GoHome : FinishAction::NoAction;
    plan.notices = heights.notices() + plan.notices;
    return plan;
}

} // namespace sortie::mission::formats::wpml
