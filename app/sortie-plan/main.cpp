// sortie-plan: convert mission files between formats, print statistics and validation, and
// generate area scans, check routes against airspace, and find where routes flown together come too
// close, for scripts and batch work. See docs/missions.md, docs/airspace.md and docs/deconfliction.md.
#include "AirspaceCommand.h"
#include "ConflictsCommand.h"
#include "PlanCommands.h"
#include "ProfileCommand.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <cstdio>

namespace {
const char *const kUsage =
    "usage: sortie-plan <command> [options]\n"
    "\n"
    "  convert IN OUT [--route N] [--strict]\n"
    "       [--drone m300|m350|m30|m30t|m3e|m3t|m3m|m3d|m3td] [--payload P] [--height relative|amsl|agl|wgs84] [--takeoff-amsl M] [--security-height M]\n"
    "      Convert between .sortie, .plan (QGroundControl), .waypoints (QGC WPL 110), .kmz (DJI WPML) and\n"
    "      .kml (export only). The --drone.. options shape a .kmz for DJI Pilot 2. The route is written as\n"
    "      the file states it and its validation issues are listed; --strict refuses one with errors.\n"
    "  stats FILE [--dem PATH] [--vehicle PROFILE.json [--wind SPEED,FROM_DEG] [--turns coordinated|stop]]\n"
    "       [--zones ZONES_FILE ...] [--json]\n"
    "      Print each route's statistics and validation results (with --dem, the terrain rules too; with\n"
    "      --vehicle, time and energy per leg, batteries, battery changes and the point of no return;\n"
    "      with --zones, the airspace rules).\n"
    "      Exit 2 when a route has errors or cannot be flown on one battery with the reserve.\n"
    "  profile FILE --dem PATH [--step METERS] [--safe-distance METERS] [--json]\n"
    "      Ground, altitude and clearance along each route from a DEM (PATH: a GeoTIFF or any raster GDAL\n"
    "      reads, an SRTM .hgt tile, or a folder of them).\n"
    "      Exit 2 when a leg flies closer to the ground than the safe distance.\n"
    "  airspace FILE --zones ZONES_FILE [--zones ZONES_FILE ...] [--at ISO-8601-UTC]\n"
    "           [--authorisation IDENTIFIER=REFERENCE ...] [--dem PATH] [--buffer METERS] [--json]\n"
    "      Check every flown leg in 3D against no-fly zones and geofences (ZONES_FILE: .plan geofence,\n"
    "      .geojson/.json, .kml, or UAS geographical zones in ED-269 or ED-318, found by content). Exit 2\n"
    "      when a leg enters an exclusion zone or leaves the inclusion zones; a leg within the buffer\n"
    "      (default 20 m) of a zone is a warning. Geographical zones count when they apply during the\n"
    "      flight (from --at, default now, to its end by the time model): PROHIBITED is an error,\n"
    "      REQ_AUTHORISATION an error unless --authorisation records one (then a warning), CONDITIONAL\n"
    "      a warning with the zone's message, NO_RESTRICTION information.\n"
    "  conflicts ROUTE_FILE ROUTE_FILE [ROUTE_FILE ...] [--start SECONDS,SECONDS,...] [--speed M/S] [--separation H,V] [--json]\n"
    "      Fly the routes (one per file) on one clock, each from its --start (default 0), in straight legs at\n"
    "      their speeds (or --speed), and report where two come closer than H across and V in height\n"
    "      (default 20,15 m). Exit 2 when there is a conflict.\n"
    "  scan POLYGON.kml OUT [--altitude M | --gsd CM] [--front PCT] [--side PCT] [--angle DEG]\n"
    "       [--turnaround M] [--speed M/S] [--amsl] [--camera NAME,SENSOR_W_MM,SENSOR_H_MM,FOCAL_MM,IMAGE_W_PX,IMAGE_H_PX]\n"
    "       [--json] [--force]\n"
    "      Generate an area scan over a KML polygon and save it as a route.\n"
    "  resume FILE OUT --takeoff LAT,LON (--photo LAT,LON | --battery-change N --vehicle PROFILE.json\n"
    "         [--wind SPEED,FROM_DEG] [--turns coordinated|stop]) [--transit M] [--route N] [--force] [--json]\n"
    "      The rest of a route stopped half-way, as a route of its own: a take-off at --takeoff, the\n"
    "      flight over at the transit height, then the rest with the camera as it was there, from where\n"
    "      the next photo was due after the last one (--photo), or from the N-th battery change the\n"
    "      endurance model places with that profile. Saved through the validation gate (exit 2 when the\n"
    "      rest has errors, unless --force).\n"
    "\n"
    "scan --force writes a route even when it has validation errors.\n";
}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("sortie-plan"));
    // The tool reports for itself; the library's progress logging stays quiet unless asked for.
    QLoggingCategory::setFilterRules(QStringLiteral("sortie.*.info=false\nsortie.*.debug=false"));
    QTextStream out(stdout), err(stderr);
    QStringList args = app.arguments().mid(1);
    if (args.isEmpty() || args.first() == QLatin1String("--help") || args.first() == QLatin1String("-h")) {
        (args.isEmpty() ? err : out) << kUsage;
        return args.isEmpty() ? sortie::plan::Failure : sortie::plan::Ok;
    }
    const QString command = args.takeFirst();
    const sortie::plan::Streams io{out, err};
    if (command == QLatin1String("convert"))
        return sortie::plan::runConvert(args, io);
    if (command == QLatin1String("stats"))
        return sortie::plan::runStats(args, io);
    if (command == QLatin1String("profile"))
        return sortie::plan::runProfile(args, io);
    if (command == QLatin1String("airspace"))
        return sortie::plan::runAirspace(args, io);
    if (command == QLatin1String("conflicts"))
        return sortie::plan::runConflicts(args, io);
    if (command == QLatin1String("scan"))
        return sortie::plan::runScan(args, io);
    if (command == QLatin1String("resume"))
        return sortie::plan::runResume(args, io);
    err << "sortie-plan: unknown command \"" << command << "\"\n\n" << kUsage;
    return sortie::plan::Failure;
}
