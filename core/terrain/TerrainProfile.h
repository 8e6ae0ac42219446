#pragma once

#include "ElevationService.h"
#include "FlownLegs.h"
#include "PathSampling.h"
#include "Route.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::terrain {

// What a waypoint's altitude is measured from. A route's AGL is above the ground under the waypoint
// (UgCS's meaning); WPL's frame 3 is above the home point's ground.
enum class HeightReference { Amsl, AboveTerrain, AboveHome };

struct ProfileWaypoint
{
    GeoPoint position;
    double altitude = 0.0;
    HeightReference reference = HeightReference::Amsl;
    int row = -1;   // the route segment it belongs to (what selecting it selects), -1 if none
    QString label;  // "Waypoint 3", as the table names it
    // >= 0: the leg to the next point follows the terrain within this many metres (an AGL scan; the
    // processing adds points there, see terrainFollowTolerance); -1: a straight climb.
    double followTolerance = -1.0;
    mission::WaypointRole role = mission::WaypointRole::Pass;  // a take-off climbs from the ground here, a landing descends to it
};

// The flown path as the profile sees it: points with their heights, legs between them.
struct ProfileRoute
{
    QString name;
    std::vector<ProfileWaypoint> waypoints;
    std::optional<GeoPoint> home;  // for AboveHome; the first waypoint when absent
    double safeDistance = 10.0;    // metres of clearance the vehicle keeps from the ground
    // The height above the surface operators are held to: the EU open category's 120 m from the
    // closest point of the surface (Regulation 2019/947, UAS.OPEN.010), judged here against the
    // ground under the path.
    double surfaceHeightLimit = 120.0;
};

// The flown path of a route (area scans expanded); AGL is above the terrain under each point.
ProfileRoute profileRouteOf(const mission::Route &route, mission::ScanPlanCache *cache = nullptr);

struct WaypointTerrain
{
    GroundSample ground;
    double altitudeAmsl = std::numeric_limits<double>::quiet_NaN();  // NaN: unknown (AGL over no data)
    double altitudeAgl = std::numeric_limits<double>::quiet_NaN();
};

struct ClearancePoint
{
    int leg = 0;
    double distance = 0.0;          // from the route's start
    double distanceAlongLeg = 0.0;
    double clearance = 0.0;         // metres above the ground (negative: below it)
};

// A leg's ends as flown (FlownLegs.h): the height it leaves its first point at and reaches its last
// point at, AMSL (NaN: unknown). A take-off on the ground leaves at the next point's height, a
// landing on the ground is reached at the height the leg left at.
struct LegEnds
{
    double departAmsl = std::numeric_limits<double>::quiet_NaN();
    double arriveAmsl = std::numeric_limits<double>::quiet_NaN();
};

// A vertical move at a point: a take-off's climb from the ground, a landing's descent to it. The
// clearance rule does not judge it: that is where the vehicle is meant to touch the ground.
struct VerticalMove
{
    int leg = 0;            // 0-based, the leg it belongs to (take-off: the one leaving; landing: the one arriving)
    int waypoint = 0;       // where
    double distance = 0.0;  // from the route's start
    double fromAmsl = std::numeric_limits<double>::quiet_NaN();
    double toAmsl = std::numeric_limits<double>::quiet_NaN();
    bool climb = true;      // a take-off's climb; false: a landing's descent
};

// A stretch of one leg flown closer to the ground than the safe distance.
struct LowStretch
{
    int leg = 0;
    double fromDistance = 0.0, toDistance = 0.0;
    ClearancePoint lowest;
};

// Ground, altitude and clearance along the flown path, sampled every step metres. Sample i is at
// path.points[i]; the altitude goes linearly with distance between a leg's ends as flown (legEnds:
// a take-off has climbed, a landing not yet descended), or, on a leg that follows the terrain,
// between the points terrain following adds (markFollowPoints on the samples). The vertical climbs
// and descents are `verticals`, not samples.
struct TerrainProfile
{
    SampledPath path;
    std::vector<GroundSample> ground;
    std::vector<double> altitudeAmsl;  // NaN where the altitude is unknown
    std::vector<WaypointTerrain> waypoints;
    std::vector<mission::LegShape> legs;   // legShapesOf(route)
    std::vector<LegEnds> legEnds;          // per leg
    std::vector<VerticalMove> verticals;   // in route order
    std::vector<NoDataStretch> noData;  // per leg
    std::vector<LowStretch> lowStretches;
    std::optional<ClearancePoint> minClearance;
    GroundSample homeGround;
    bool pending = false;  // an asynchronous source is still answering: more may come
    QStringList sourcesTried;

    double clearance(size_t i) const { return altitudeAmsl[i] - ground[i].ground; }  // NaN when unknown
    size_t size() const { return path.points.size(); }
};

// How the route's points are joined (the one rule, FlownLegs.h): a take-off or landing is on the
// ground at 0 m or less above the terrain.
std::vector<mission::LegShape> legShapesOf(const ProfileRoute &route);

TerrainProfile computeProfile(const ProfileRoute &route, ElevationService &service, double step = 30.0);

// "Leg 3 (Waypoint 3 → Waypoint 4)"
QString legLabel(const ProfileRoute &route, int leg);

} // namespace sortie::terrain
