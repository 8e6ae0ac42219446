#include "RouteStatistics.h"

#include "AlgorithmCatalog.h"

#include "FlightPath.h"
#include "FlownLegs.h"
#include "Geodesy.h"
#include "RouteTiming.h"
#include "ScanPlanCache.h"
#include "SegmentPlanning.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sortie::mission {

GeoBox boundingBoxOf(const std::vector<GeoPoint> &points)
{
    GeoBox box;
    if (points.empty())
        return box;
    box.empty = false;
    box.south = box.north = points.front().latitude;
    double west = points.front().longitude, east = west;
    for (const GeoPoint &p : points) {
        box.south = std::min(box.south, p.latitude);
        box.north = std::max(box.north, p.latitude);
        west = std::min(west, p.longitude);
        east = std::max(east, p.longitude);
    }
    box.west = west;
    box.east = east;
    if (east - west <= 180.0)
        return box;
    // Wide in longitude: the box is the complement of the largest gap between longitudes, which
    // may be the one across the antimeridian.
    std::vector<double> lons;
    lons.reserve(points.size());
    for (const GeoPoint &p : points)
        lons.push_back(p.longitude);
    std::sort(lons.begin(), lons.end());
    double gap = lons.front() + 360.0 - lons.back();
    box.west = lons.front();
    box.east = lons.back();
    for (size_t i = 1; i < lons.size(); ++i) {
        if (lons[i] - lons[i - 1] > gap) {
            gap = lons[i] - lons[i - 1];
            box.west = lons[i];
            box.east = lons[i - 1];
        }
    }
    return box;
}

namespace {
// The photos the waypoints' camera actions take along the path: a single shot, or a series by
// distance or by time that starts with a photo where it is set and goes on (for its number of
// shots, or until another series or a stop) over the legs that follow.
class CameraActionPhotos
{
public:
    void arrive(const std::vector<WaypointAction> &actions)
    {
        for (const WaypointAction &a : actions) {
            if (const auto *shot = std::get_if<CameraTriggerAction>(&a); shot && shot->state == TriggerState::SingleShot)
                ++m_photos;
            else if (const auto *d = std::get_if<CameraSeriesByDistanceAction>(&a))
                start(Series::Distance, d->intervalMeters, d->shots);
            else if (const auto *t = std::get_if<CameraSeriesByTimeAction>(&a))
                start(Series::Time, t->intervalSeconds, t->shots);
        }
    }
    // `seconds` is asked for only while a series by time runs.
    template<typename Seconds>
    void fly(double meters, Seconds seconds)
    {
        if (m_series == Series::None)
            return;
        m_since += m_series == Series::Distance ? meters : seconds();
        while (m_since >= m_interval && m_left != 0) {
            ++m_photos;
            m_since -= m_interval;
            --m_left;  // below 0: no limit
        }
    }
    int photos() const { return m_photos; }

private:
    enum class Series { None, Distance, Time };
    void start(Series series, double interval, int shots)
    {
        m_series = interval > 0 ? series : Series::None;  // an interval of 0 stops the series
        m_interval = interval;
        m_since = 0;
        if (m_series == Series::None)
            return;
        ++m_photos;
        m_left = shots > 0 ? shots - 1 : -1;
    }
    Series m_series = Series::None;
    double m_interval = 0, m_since = 0;
    int m_left = -1;
    int m_photos = 0;
};
} // namespace

RouteStatistics computeStatistics(const Route &route, ScanPlanCache *cache)
{
    RouteStatistics st;
    for (const Segment &s : route.segments) {
        if (isWaypoint(s)) {
            ++st.waypointCount;
        } else if (const AreaScan *scan = asAreaScan(s)) {
            ++st.areaScanCount;
            AreaScanOutcome scratch;
            const AreaScanOutcome &o = scanOutcome(*scan, cache, scratch);
            if (o.ok())
                st.photoCount += o.plan->photoCount;
        } else if (const SegmentPlanOutcome o = planAlgorithmSegment(std::get<AlgorithmSegment>(s), AlgorithmCatalog::builtIn(),
                                                                                 planContextOf(route.settings)); o.ok()) {
            st.areaScanCount += o.plan->passes > 0;
            st.photoCount += o.plan->photos;
        }
    }
    const std::vector<PathPoint> path = flightPath(route, cache);
    st.pathPointCount = int(path.size());
    // The time comes from the one time model (core/mission/timing); a route it cannot time (a leg
    // with no speed at all) has no flight time rather than a wrong one.
    const Result<RouteTimeline> timeline = timePath(route, path, timingOf(route.settings));
    st.flightTimeSeconds = timeline ? timeline->totalSeconds() : std::numeric_limits<double>::quiet_NaN();
    const auto legSeconds = [&](size_t leg) {
        return timeline && leg < timeline->legs().size() ? timeline->legs()[leg].moveSeconds : 0.0;
    };

    std::vector<GeoPoint> positions;
    positions.reserve(path.size() + 1);
    CameraActionPhotos cameraActions;
    for (size_t i = 0; i < path.size(); ++i) {
        const PathPoint &p = path[i];
        positions.push_back(p.position);
        const auto arriveAtWaypoint = [&] {
            if (p.segment >= 0 && p.segment < int(route.segments.size()))
                if (const Waypoint *w = asWaypoint(route.segments[size_t(p.segment)]))
                    cameraActions.arrive(w->actions);
        };
        if (i == 0) {
            arriveAtWaypoint();
            continue;
        }
        const PathPoint &q = path[i - 1];
        // The timeline measured the leg already (leg i runs from point i-1 to point i).
        const double d = timeline ? timeline->legs()[i - 1].distance : geodesicDistance(q.position, p.position);
        st.lengthMeters += d;
        cameraActions.fly(d, [&] { return legSeconds(i - 1); });
        arriveAtWaypoint();
    }
    // Climb and descent as the legs are flown: straight up at a take-off, across, straight down at
    // a landing (FlownLegs.h); heights in different frames are not compared.
    const auto aboveGround = [](const PathPoint &p) { return p.altitudeType == AltitudeType::Agl ? std::max(0.0, p.altitude) : 0.0; };
    for (const LegShape &leg : flownLegs(path)) {
        const PathPoint &depart = path[leg.departHeight], &arrive = path[leg.arriveHeight];
        if (leg.climbAtStart)
            st.climbMeters += aboveGround(depart);
        if (leg.moves() && arrive.altitudeType == depart.altitudeType) {
            const double dh = arrive.altitude - depart.altitude;
            (dh > 0 ? st.climbMeters : st.descentMeters) += std::abs(dh);
        }
        if (leg.climbAtEnd)
            st.climbMeters += aboveGround(path[leg.to]);
        if (leg.descentAtEnd)
            st.descentMeters += aboveGround(arrive);
    }
    st.photoCount += cameraActions.photos();
    const RouteSettings &rs = route.settings;
    if (rs.endAction == EndAction::ReturnHome && rs.home && !path.empty()) {
        const PathPoint &last = path.back();
        st.lengthMeters += geodesicDistance(last.position, rs.home->position);
        if (last.altitudeType == AltitudeType::Agl)
            st.descentMeters += std::max(0.0, last.altitude);
        positions.push_back(rs.home->position);
    }
    st.boundingBox = boundingBoxOf(positions);
    return st;
}

} // namespace sortie::mission
