#include "SimRouteZones.h"

#include "Messages.pb.h"
#include "SimLog.h"
#include "SimObjectStore.h"
#include "SimTerrain.h"
#include "SimZones.h"

#include "AirspaceCheck.h"
#include "AirspaceRule.h"
#include "ElevationService.h"
#include "NfzConversion.h"
#include "TerrainProfile.h"

#include <numbers>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The processed route's flown points, each in the row of its segment.
terrain::ProfileRoute flownPoints(const pb::ProcessedRoute &processed)
{
    terrain::ProfileRoute path;
    for (int s = 0; s < processed.segments_size(); ++s) {
        for (const pb::Action &a : processed.segments(s).segmentactions()) {
            terrain::ProfileWaypoint p;
            p.reference = terrain::HeightReference::Amsl;
            p.row = s;
            if (a.has_waypoint()) {
                p.position = {a.waypoint().latitude() * kDeg, a.waypoint().longitude() * kDeg};
                p.altitude = a.waypoint().wgs84altitude();
            } else if (a.has_takeoff()) {
                p.position = {a.takeoff().latitude() * kDeg, a.takeoff().longitude() * kDeg};
                p.altitude = a.takeoff().wgs84altitude();
                p.role = mission::WaypointRole::Takeoff;
            } else if (a.has_landing()) {
                p.position = {a.landing().latitude() * kDeg, a.landing().longitude() * kDeg};
                p.altitude = a.landing().wgs84altitude();
                p.role = mission::WaypointRole::Land;
            } else {
                continue;
            }
            p.label = QStringLiteral("Point %1").arg(path.waypoints.size() + 1);
            path.waypoints.push_back(std::move(p));
        }
    }
    return path;
}

} // namespace

void SimRouteZones::apply(pb::ProcessedRoute &processed, const pb::Route &route, const SimObjectStore &store, const SimTerrain &terrain)
{
    if (!route.checkaerodromenfz() && !route.checkcustomnfz())
        return;
    std::vector<airspace::Zone> zones;
    for (const auto *w : store.list(SimZones::kType)) {
        const pb::NoFlightZone &nfz = w->noflightzone();
        if (nfz.type() == pb::NT_AERODROME ? !route.checkaerodromenfz() : !route.checkcustomnfz())
            continue;
        QString why;
        if (auto zone = airspace::NfzConversion::toZone(nfz, &why))
            zones.push_back(std::move(*zone));
        else
            qCWarning(lcSim).noquote() << "route processing skips NoFlightZone" << nfz.id() << why;
    }
    const terrain::ProfileRoute path = flownPoints(processed);
    if (zones.empty() || path.waypoints.empty())
        return;
    terrain::ElevationService ground;
    ground.setSources({&terrain.source()});
    const terrain::TerrainProfile profile = terrain::computeProfile(path, ground);
    const airspace::AirspaceReport report = airspace::checkAirspace(airspace::flownPath(path, &profile), zones, 0.0);
    for (const airspace::AirspaceViolation &v : report.violations) {
        const airspace::Zone &zone = zones[size_t(v.zone)];
        const int s = v.row >= 0 && v.row < processed.segments_size() ? v.row : processed.segments_size() - 1;
        pb::ProcessedSegment *segment = processed.mutable_segments(s);
        segment->set_status(pb::RPS_INVALID);
        auto *m = segment->mutable_messageset()->add_messages();
        m->set_severity(pb::MS_ERROR);
        m->set_defaulttext(QStringLiteral("Segment %1: the route crosses the %2 no-fly zone '%3': %4")
                               .arg(s + 1)
                               .arg(zone.source == airspace::ZoneSource::ServerAerodrome ? QStringLiteral("aerodrome") : QStringLiteral("custom"),
                                    zone.name, airspace::violationMessage(v, zone))
                               .toStdString());
    }
}

} // namespace sortie::sim
