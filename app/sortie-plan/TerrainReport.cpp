#include "TerrainReport.h"

#include "MavlinkMission.h"
#include "MissionFiles.h"
#include "WplFormat.h"
#include "ScanPlanCache.h"

#include <QFile>

#include <QList>

#include <cmath>

namespace sortie::plan {

using mission::formats::Json;
using namespace sortie::terrain;
namespace mav = mission::formats::mav;

namespace {
Json number(double v)
{
    return std::isfinite(v) ? Json(std::round(v * 1000.0) / 1000.0) : Json(nullptr);
}

Json coordinate(double v)
{
    return Json(std::round(v * 1e8) / 1e8);
}
} // namespace

Json terrainJson(const ProfileRoute &route, const TerrainProfile &profile, bool withSamples)
{
    Json t = Json::object();
    t["safeDistance"] = route.safeDistance;
    Json sources = Json::array();
    for (const QString &s : profile.sourcesTried)
        sources.push_back(s.toStdString());
    t["sources"] = sources;
    t["length"] = number(profile.path.length());
    t["step"] = profile.path.step;
    if (profile.minClearance) {
        t["minClearance"] = number(profile.minClearance->clearance);
        t["minClearanceAt"] = {{"leg", profile.minClearance->leg + 1},
                               {"distance", number(profile.minClearance->distance)},
                               {"distanceAlongLeg", number(profile.minClearance->distanceAlongLeg)}};
    } else {
        t["minClearance"] = nullptr;
        t["minClearanceAt"] = nullptr;
    }
    Json noData = Json::array();
    for (const NoDataStretch &s : profile.noData)
        noData.push_back({{"fromDistance", number(s.fromDistance)}, {"toDistance", number(s.toDistance)}, {"leg", s.leg + 1}});
    t["noData"] = noData;
    Json low = Json::array();
    for (const LowStretch &s : profile.lowStretches)
        low.push_back({{"fromDistance", number(s.fromDistance)}, {"toDistance", number(s.toDistance)}, {"leg", s.leg + 1},
                       {"clearance", number(s.lowest.clearance)}, {"distance", number(s.lowest.distance)}});
    t["tooLow"] = low;
    Json waypoints = Json::array();
    for (size_t i = 0; i < profile.waypoints.size(); ++i) {
        const WaypointTerrain &w = profile.waypoints[i];
        waypoints.push_back({{"waypoint", i + 1},
                             {"ground", w.ground.hasValue() ? number(w.ground.ground) : Json(nullptr)},
                             {"altitudeAmsl", number(w.altitudeAmsl)},
                             {"altitudeAgl", number(w.altitudeAgl)},
                             {"distance", number(profile.path.vertexDistance[i])}});
    }
    t["waypoints"] = waypoints;
    // The take-off climbs and landing descents, straight up and down at their points (FlownLegs.h).
    Json verticals = Json::array();
    for (const VerticalMove &v : profile.verticals)
        verticals.push_back({{"leg", v.leg + 1}, {"waypoint", v.waypoint + 1}, {"distance", number(v.distance)},
                             {"fromAmsl", number(v.fromAmsl)}, {"toAmsl", number(v.toAmsl)}});
    t["verticals"] = verticals;
    if (withSamples) {
        Json samples = Json::array();
        for (size_t i = 0; i < profile.size(); ++i) {
            const PathSamplePoint &p = profile.path.points[i];
            const GroundSample &g = profile.ground[i];
            samples.push_back({{"distance", number(p.distance)},
                               {"leg", p.leg + 1},
                               {"latitude", coordinate(p.position.latitude)},
                               {"longitude", coordinate(p.position.longitude)},
                               {"ground", g.hasValue() ? number(g.ground) : Json(nullptr)},
                               {"altitudeAmsl", number(profile.altitudeAmsl[i])},
                               {"clearance", g.hasValue() ? number(profile.clearance(i)) : Json(nullptr)}});
        }
        t["samples"] = samples;
    }
    return t;
}

std::optional<ProfileRoute> wplProfileRoute(const QByteArray &data, QString *error)
{
    const auto read = mission::formats::readWplItems(data);
    if (!read) {
        if (error)
            *error = QStringLiteral("line %1: %2").arg(read.error().line).arg(read.error().message);
        return std::nullopt;
    }
    ProfileRoute route;
    if (read.value().home)
        route.home = read.value().home->position;
    for (const mission::formats::MavlinkItem &item : read.value().items) {
        switch (item.command) {
        case mav::NavWaypoint: case mav::NavLoiterUnlimited: case mav::NavLoiterTurns: case mav::NavLoiterTime:
        case mav::NavLand: case mav::NavTakeoff: case mav::NavLoiterToAltitude: case mav::NavSplineWaypoint:
        case mav::NavVtolTakeoff: case mav::NavVtolLand:
            break;
        default:
            continue;  // not a place the vehicle flies to
        }
        ProfileWaypoint w;
        switch (item.frame) {
        case mav::Global: case mav::GlobalInt: w.reference = HeightReference::Amsl; break;
        case mav::GlobalRelativeAlt: case mav::GlobalRelativeAltInt: w.reference = HeightReference::AboveHome; break;
        case mav::GlobalTerrainAlt: case mav::GlobalTerrainAltInt: w.reference = HeightReference::AboveTerrain; break;
        default:
            if (error)
                *error = QStringLiteral("line %1: altitude frame %2 has no height reference the profile knows (0, 3 or 10)").arg(item.line).arg(item.frame);
            return std::nullopt;
        }
        w.position = {item.latitude, item.longitude};
        if (item.latitude == 0.0 && item.longitude == 0.0) {  // "here": home for a take-off, the previous point otherwise
            if (item.command == mav::NavTakeoff || item.command == mav::NavVtolTakeoff || route.waypoints.empty()) {
                if (!route.home) {
                    if (error)
                        *error = QStringLiteral("line %1: a take-off at 0,0 needs the home item").arg(item.line);
                    return std::nullopt;
                }
                w.position = *route.home;
            } else {
                w.position = route.waypoints.back().position;
            }
        }
        w.altitude = item.altitude;
        if (item.command == mav::NavTakeoff || item.command == mav::NavVtolTakeoff)
            w.role = mission::WaypointRole::Takeoff;
        else if (item.command == mav::NavLand || item.command == mav::NavVtolLand)
            w.role = mission::WaypointRole::Land;
        w.row = int(route.waypoints.size());
        w.label = QStringLiteral("Waypoint %1").arg(route.waypoints.size() + 1);
        route.waypoints.push_back(std::move(w));
    }
    return route;
}

std::optional<std::vector<ProfileRoute>> profileRoutes(const QString &file, const mission::Mission &mission, QString *error)
{
    std::vector<ProfileRoute> routes;
    if (mission::formats::formatForPath(file) == mission::formats::FileFormat::Wpl) {
        QFile f(file);
        if (!f.open(QIODevice::ReadOnly)) {
            *error = f.errorString();
            return std::nullopt;
        }
        std::optional<ProfileRoute> r = wplProfileRoute(f.readAll(), error);
        if (!r)
            return std::nullopt;
        if (!mission.routes.empty()) {
            r->name = mission.routes.front().settings.name;
            r->safeDistance = mission.routes.front().settings.profile.safeTerrainDistance;
        }
        routes.push_back(std::move(*r));
        return routes;
    }
    mission::ScanPlanCache cache;
    for (const mission::Route &r : mission.routes)
        routes.push_back(profileRouteOf(r, &cache));
    return routes;
}

} // namespace sortie::plan
