#include "PlanCommands.h"

#include "AirspaceReport.h"
#include "AirspaceRule.h"
#include "AreaScanPlanner.h"
#include "DjiDroneModels.h"
#include "ElevationService.h"
#include "EnduranceReport.h"
#include "EnduranceRule.h"
#include "DemOpener.h"
#include "MissionFiles.h"
#include "ReportJson.h"
#include "ResumeRoute.h"
#include "RouteStatistics.h"
#include "RouteValidator.h"
#include "ScanPlanCache.h"
#include "TerrainReport.h"
#include "TerrainRule.h"

#include <QCommandLineParser>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <memory>

namespace sortie::plan {

using namespace sortie::mission;
using namespace sortie::mission::formats;

namespace {
bool parse(QCommandLineParser &p, const QStringList &args, int positional, Streams io)
{
    p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    if (!p.parse(QStringList{QStringLiteral("sortie-plan")} + args)) {
        io.err << "sortie-plan: " << p.errorText() << "\n";
        return false;
    }
    if (p.positionalArguments().size() != positional) {
        io.err << "sortie-plan: expected " << positional << " file argument(s), got " << p.positionalArguments().size() << "\n";
        return false;
    }
    return true;
}

void printNotices(const QStringList &notices, Streams io)
{
    for (const QString &n : notices)
        io.err << "note: " << n << "\n";
}

// The validation of each route a conversion writes, to stderr, one line per issue; returns the
// number of errors.
int printIssuesOfWritten(const Mission &mission, std::optional<int> route, Streams io)
{
    ScanPlanCache cache;
    int errors = 0;
    for (size_t ri = 0; ri < mission.routes.size(); ++ri) {
        if (route && *route != int(ri))
            continue;
        const ValidationReport report = validateRoute(mission.routes[ri], &cache);
        for (const ValidationIssue &i : report.issues)
            io.err << (i.severity == Severity::Error ? "error" : "warning") << ": route " << ri + 1 << " [" << i.rule << "] " << i.message << "\n";
        errors += int(report.errorCount());
    }
    return errors;
}

QString duration(double seconds)
{
    if (!std::isfinite(seconds))
        return QStringLiteral("unknown");  // a leg with no speed at all
    const qint64 s = qRound64(seconds);
    return QStringLiteral("%1:%2:%3").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

int saveWithGate(const Mission &mission, const QString &path, std::optional<int> route, bool force, Streams io,
                 const WpmlExportOptions &wpml = {})
{
    const Result<QStringList> saved = saveMission(mission, path, {route, force ? ValidationOverride::AcceptErrors : ValidationOverride::None, wpml});
    if (!saved) {
        io.err << "sortie-plan: " << saved.error().toString() << "\n";
        return saved.error().message.contains(QStringLiteral("validation error")) ? ValidationErrors : Failure;
    }
    printNotices(*saved, io);
    return Ok;
}
}

int runConvert(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("route"), QStringLiteral("Route to write (1-based); default: every route (.sortie, .kmz waylines), or the only one."), QStringLiteral("N")});
    p.addOption({QStringLiteral("strict"), QStringLiteral("Refuse to write a route with validation errors (exit 2).")});
    p.addOption({QStringLiteral("force"), QStringLiteral("Write even with validation errors: what convert does unless --strict (kept for scripts).")});
    p.addOption({QStringLiteral("drone"), QStringLiteral("DJI WPML (.kmz): the aircraft (%1; default: the route's profile, else m350).").arg(djiDroneKeys()), QStringLiteral("MODEL")});
    p.addOption({QStringLiteral("payload"), QStringLiteral("DJI WPML: the payload (e.g. h20t, p1; default: the aircraft's camera)."), QStringLiteral("PAYLOAD")});
    p.addOption({QStringLiteral("height"), QStringLiteral("DJI WPML heights: relative (to take-off), amsl (EGM96), agl (terrain following) or wgs84 (ellipsoidal)."), QStringLiteral("MODE"), QStringLiteral("relative")});
    p.addOption({QStringLiteral("takeoff-amsl"), QStringLiteral("DJI WPML: AMSL altitude of the take-off point (default: the route's home)."), QStringLiteral("M")});
    p.addOption({QStringLiteral("security-height"), QStringLiteral("DJI WPML: take-off security height, m."), QStringLiteral("M"), QStringLiteral("20")});
    if (!parse(p, args, 2, io))
        return Failure;
    const QString in = p.positionalArguments().at(0), out = p.positionalArguments().at(1);
    WpmlExportOptions wpml;
    wpml.drone = p.value(QStringLiteral("drone"));
    wpml.payload = p.value(QStringLiteral("payload"));
    if (!parseWpmlHeightMode(p.value(QStringLiteral("height")), &wpml.heightMode)) {
        io.err << "sortie-plan: --height is relative, amsl, agl or wgs84\n";
        return Failure;
    }
    bool numberOk = true;
    if (p.isSet(QStringLiteral("takeoff-amsl")))
        wpml.takeoffAltitudeAmsl = p.value(QStringLiteral("takeoff-amsl")).toDouble(&numberOk);
    if (numberOk)
        wpml.takeoffSecurityHeight = p.value(QStringLiteral("security-height")).toDouble(&numberOk);
    if (!numberOk) {
        io.err << "sortie-plan: --takeoff-amsl and --security-height need a number\n";
        return Failure;
    }
    const Result<LoadedMission> loaded = loadMission(in);
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return Failure;
    }
    printNotices(loaded->notices, io);
    std::optional<int> route;
    if (p.isSet(QStringLiteral("route"))) {
        bool ok = false;
        route = p.value(QStringLiteral("route")).toInt(&ok) - 1;
        if (!ok) {
            io.err << "sortie-plan: --route needs a number\n";
            return Failure;
        }
    }
    // A conversion carries the file over and says what Sortie's rules find in it; refusing is asked
    // for (--strict). The rules judge what the file states, so an imported route keeps its limits.
    const bool strict = p.isSet(QStringLiteral("strict"));
    if (strict && p.isSet(QStringLiteral("force"))) {
        io.err << "sortie-plan: --strict and --force contradict each other\n";
        return Failure;
    }
    const int issues = printIssuesOfWritten(loaded->mission, route, io);
    const int rc = saveWithGate(loaded->mission, out, route, !strict, io, wpml);
    if (rc == Ok)
        io.out << "wrote " << out << (issues > 0 ? QStringLiteral(" with %1 validation error(s): see above").arg(issues) : QString()) << "\n";
    return rc;
}

int runStats(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    p.addOption({QStringLiteral("dem"), QStringLiteral("A DEM (any raster GDAL reads, an SRTM .hgt tile) or a folder of them: check the terrain rules too."), QStringLiteral("PATH")});
    p.addOption({QStringLiteral("vehicle"), QStringLiteral("Energy profile (JSON): time and energy per leg, batteries, point of no return."),
                 QStringLiteral("PROFILE")});
    p.addOption({QStringLiteral("wind"), QStringLiteral("With --vehicle: wind speed (m/s) and the direction it blows from (degrees)."),
                 QStringLiteral("SPEED,FROM_DEG")});
    p.addOption({QStringLiteral("turns"), QStringLiteral("With --vehicle: coordinated (default) or stop (stop and turn at every waypoint)."),
                 QStringLiteral("MODE")});
    p.addOption({QStringLiteral("zones"), QStringLiteral("Zone file (.plan, .geojson, .json, .kml): check the airspace rules too. Repeatable."),
                 QStringLiteral("FILE")});
    if (!parse(p, args, 1, io))
        return Failure;
    const QString file = p.positionalArguments().at(0);
    std::optional<ZoneInput> zones;
    if (p.isSet(QStringLiteral("zones"))) {
        QString error;
        zones = readZoneInput(p.values(QStringLiteral("zones")), 20.0, &error);
        if (!zones) {
            io.err << "sortie-plan: " << error << "\n";
            return Failure;
        }
        for (const QString &n : zones->problems)
            io.err << "note: " << n << "\n";
    }
    std::optional<EnduranceInput> endurance;
    if (p.isSet(QStringLiteral("vehicle"))) {
        QString error;
        endurance = readEnduranceInput(p.value(QStringLiteral("vehicle")), p.value(QStringLiteral("wind")), p.value(QStringLiteral("turns")), &error);
        if (!endurance) {
            io.err << "sortie-plan: " << error << "\n";
            return Failure;
        }
    } else if (p.isSet(QStringLiteral("wind")) || p.isSet(QStringLiteral("turns"))) {
        io.err << "sortie-plan: --wind and --turns need --vehicle PROFILE.json\n";
        return Failure;
    }
    const Result<LoadedMission> loaded = loadMission(file);
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return Failure;
    }
    // With --dem, each route's terrain profile adds its issues (see profile).
    std::unique_ptr<terrain::ElevationSource> tiles;
    terrain::ElevationService elevation;
    std::vector<terrain::ProfileRoute> profiles;
    if (p.isSet(QStringLiteral("dem"))) {
        QString demError;
        tiles = raster::openDem(p.value(QStringLiteral("dem")), &demError);
        if (!tiles) {
            io.err << "sortie-plan: " << demError << "\n";
            return Failure;
        }
        elevation.setSources({tiles.get()});
        QString error;
        auto pr = profileRoutes(file, loaded->mission, &error);
        if (!pr) {
            io.err << "sortie-plan: " << file << ": " << error << "\n";
            return Failure;
        }
        profiles = std::move(*pr);
    }
    // The routes as the airspace check flies them, read as `profile` reads them (a WPL file's frames).
    std::vector<terrain::ProfileRoute> zoneRoutes;
    if (zones && profiles.empty()) {
        QString error;
        auto pr = profileRoutes(file, loaded->mission, &error);
        if (!pr) {
            io.err << "sortie-plan: " << file << ": " << error << "\n";
            return Failure;
        }
        zoneRoutes = std::move(*pr);
    }
    ScanPlanCache cache;
    bool errors = false;
    Json routes = Json::array();
    for (size_t ri = 0; ri < loaded->mission.routes.size(); ++ri) {
        const Route &r = loaded->mission.routes[ri];
        const RouteStatistics st = computeStatistics(r, &cache);
        ValidationReport report = validateRoute(r, &cache);
        std::optional<terrain::TerrainProfile> profile;
        if (ri < profiles.size()) {
            profile = terrain::computeProfile(profiles[ri], elevation);
            const auto found = terrain::terrainIssues(profiles[ri], *profile);
            report.issues.insert(report.issues.end(), found.begin(), found.end());
            std::stable_sort(report.issues.begin(), report.issues.end(),
                             [](const ValidationIssue &a, const ValidationIssue &b) { return a.segment < b.segment; });
        }
        // With --vehicle, the endurance rules join the validation; a route that needs more than one
        // battery (planned changes or not) or cannot be flown in the wind exits 2.
        std::optional<Result<endurance::EnduranceEstimate>> estimate;
        if (endurance) {
            estimate = endurance::estimateEndurance(r, endurance->profile, endurance->conditions, &cache);
            const auto found = endurance::enduranceIssues(r, endurance->profile, *estimate);
            report.issues.insert(report.issues.end(), found.begin(), found.end());
            std::stable_sort(report.issues.begin(), report.issues.end(),
                             [](const ValidationIssue &a, const ValidationIssue &b) { return a.segment < b.segment; });
            errors |= !estimate->ok() || !estimate->value().fitsOneBattery();
        }
        // With --zones, the airspace rules join the validation (the flown path over the ground with --dem).
        std::optional<airspace::AirspaceReport> airspaceReport;
        std::optional<airspace::ed::TimeWindow> airspaceWindow;
        if (zones) {
            const terrain::ProfileRoute pr = ri < profiles.size()     ? profiles[ri]
                                             : ri < zoneRoutes.size() ? zoneRoutes[ri]
                                                                      : terrain::profileRouteOf(r, &cache);
            const bool wpl = formatForPath(file) == FileFormat::Wpl;
            const airspace::FlownPath path = airspace::flownPath(pr, profile ? &*profile : nullptr, wpl ? airspace::FlightEnds{} : airspace::flightEndsOf(r));
            airspace::AirspaceChecker checker(zones->zones, zones->buffer);
            // Geographical zones count when they apply during a flight starting now.
            airspaceWindow = airspace::flightWindow(r, QDateTime::currentDateTimeUtc(), &cache);
            checker.setWindow(airspaceWindow);
            airspaceReport = checker.check(path);
            const auto found = airspace::airspaceIssues(*airspaceReport, *zones->zones, zones->buffer);
            report.issues.insert(report.issues.end(), found.begin(), found.end());
            std::stable_sort(report.issues.begin(), report.issues.end(),
                             [](const ValidationIssue &a, const ValidationIssue &b) { return a.segment < b.segment; });
        }
        errors |= report.hasErrors();
        if (p.isSet(QStringLiteral("json"))) {
            Json route{{"name", r.settings.name.toStdString()}, {"statistics", statisticsJson(st)}, {"validation", validationJson(report)}};
            if (airspaceReport)
                route["airspace"] = airspaceJson(*airspaceReport, *zones, {}, airspaceWindow);
            if (profile)
                route["terrain"] = terrainJson(profiles[ri], *profile, false);
            if (estimate)
                route["endurance"] = estimate->ok() ? enduranceJson(*endurance, estimate->value()) : Json(nullptr);
            routes.push_back(std::move(route));
            continue;
        }
        io.out << "Route \"" << r.settings.name << "\"\n"
               << "  waypoints " << st.waypointCount << ", area scans " << st.areaScanCount << "\n"
               << "  length " << QString::number(st.lengthMeters, 'f', 1) << " m (WGS-84 geodesic)\n"
               << "  flight time " << duration(st.flightTimeSeconds) << " (estimate)\n"
               << "  climb " << QString::number(st.climbMeters, 'f', 1) << " m, descent " << QString::number(st.descentMeters, 'f', 1) << " m\n"
               << "  photos " << st.photoCount << "\n";
        if (!st.boundingBox.empty)
            io.out << "  bounds " << st.boundingBox.south << ", " << st.boundingBox.west << " .. " << st.boundingBox.north << ", "
                   << st.boundingBox.east << "\n";
        if (profile) {
            io.out << "  terrain from " << profile->sourcesTried.join(QStringLiteral(", ")) << ": ";
            if (profile->minClearance)
                io.out << "lowest clearance " << QString::number(profile->minClearance->clearance, 'f', 1) << " m on leg "
                       << profile->minClearance->leg + 1 << "\n";
            else
                io.out << "no data under the route\n";
        }
        if (estimate && estimate->ok())
            printEndurance(io.out, r, *endurance, estimate->value());
        else if (estimate)
            io.out << "  endurance: " << estimate->error().message << "\n";
        io.out << "  " << report.errorCount() << " error(s), " << report.warningCount() << " warning(s)\n";
        for (const ValidationIssue &i : report.issues)
            io.out << "    " << (i.severity == Severity::Error ? "error" : "warning") << " [" << i.rule << "] " << i.message << "\n";
    }
    if (p.isSet(QStringLiteral("json"))) {
        Json notices = Json::array();
        for (const QString &n : loaded->notices)
            notices.push_back(n.toStdString());
        const Json doc{{"file", file.toStdString()}, {"routes", std::move(routes)}, {"notices", std::move(notices)}};
        io.out << QString::fromStdString(doc.dump(2)) << "\n";
    } else {
        printNotices(loaded->notices, io);
    }
    if (tiles) {
        for (const QString &problem : tiles->problems())
            io.err << "sortie-plan: " << problem << "\n";
        if (!tiles->problems().isEmpty())
            return Failure;
    }
    return errors ? ValidationErrors : Ok;
}

int runScan(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    const QString number = QStringLiteral("number");
    p.addOption({QStringLiteral("altitude"), QStringLiteral("Flight altitude, m."), number});
    p.addOption({QStringLiteral("gsd"), QStringLiteral("Ground sample distance, cm/px (instead of --altitude)."), number});
    p.addOption({QStringLiteral("front"), QStringLiteral("Front overlap, %."), number, QStringLiteral("75")});
    p.addOption({QStringLiteral("side"), QStringLiteral("Side overlap, %."), number, QStringLiteral("65")});
    p.addOption({QStringLiteral("angle"), QStringLiteral("Transect bearing, degrees."), number, QStringLiteral("0")});
    p.addOption({QStringLiteral("turnaround"), QStringLiteral("Turnaround distance, m."), number, QStringLiteral("10")});
    p.addOption({QStringLiteral("speed"), QStringLiteral("Speed, m/s."), number, QStringLiteral("8")});
    p.addOption({QStringLiteral("camera"), QStringLiteral("NAME,SENSOR_W_MM,SENSOR_H_MM,FOCAL_MM,IMAGE_W_PX,IMAGE_H_PX"), QStringLiteral("spec")});
    p.addOption({QStringLiteral("amsl"), QStringLiteral("The altitude is above mean sea level (default: above ground).")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable summary.")});
    p.addOption({QStringLiteral("force"), QStringLiteral("Write even with validation errors.")});
    if (!parse(p, args, 2, io))
        return Failure;
    const Result<ImportedPolygon> polygon = loadPolygon(p.positionalArguments().at(0));
    if (!polygon) {
        io.err << "sortie-plan: " << polygon.error().toString() << "\n";
        return Failure;
    }
    AreaScan scan;
    scan.polygon = polygon->polygon;
    AreaScanParameters &sp = scan.parameters;
    auto num = [&](const char *name, double *target) {
        const QString text = p.value(QLatin1String(name));  // the default when not given
        if (text.isEmpty())
            return true;
        bool ok = false;
        *target = text.toDouble(&ok);
        if (!ok)
            io.err << "sortie-plan: --" << name << " needs a number\n";
        return ok;
    };
    if (p.isSet(QStringLiteral("gsd"))) {
        sp.heightMode = ScanHeightMode::GroundSampleDistance;
        if (!num("gsd", &sp.groundSampleDistanceCm)) return Failure;
    }
    if (!num("altitude", &sp.altitude) || !num("front", &sp.frontOverlapPercent) || !num("side", &sp.sideOverlapPercent)
        || !num("angle", &sp.directionDeg) || !num("turnaround", &sp.turnaroundMeters) || !num("speed", &sp.speed))
        return Failure;
    if (p.isSet(QStringLiteral("camera"))) {
        const QStringList c = p.value(QStringLiteral("camera")).split(QLatin1Char(','));
        bool ok = c.size() == 6;
        if (ok) {
            bool a, b, d, e, f;
            sp.camera = {c[0], c[1].toDouble(&a), c[2].toDouble(&b), c[3].toDouble(&d), c[4].toInt(&e), c[5].toInt(&f)};
            ok = a && b && d && e && f;
        }
        if (!ok) {
            io.err << "sortie-plan: --camera needs NAME,SENSOR_W_MM,SENSOR_H_MM,FOCAL_MM,IMAGE_W_PX,IMAGE_H_PX\n";
            return Failure;
        }
    }
    sp.altitudeType = p.isSet(QStringLiteral("amsl")) ? AltitudeType::Amsl : AltitudeType::Agl;
    syncDerivedFields(sp);
    const AreaScanOutcome outcome = planAreaScan(scan);
    if (!outcome.ok()) {
        io.err << "sortie-plan: " << p.positionalArguments().at(0) << ": " << outcome.message << "\n";
        return Failure;
    }
    Mission mission;
    mission.name = QFileInfo(p.positionalArguments().at(1)).completeBaseName();
    Route route;
    route.settings.name = polygon->name.isEmpty() ? mission.name : polygon->name;
    route.settings.initialSpeed = sp.speed;
    route.settings.maxAltitude = std::max(route.settings.maxAltitude, outcome.plan->altitude);
    route.settings.safeAltitude = std::min(route.settings.safeAltitude, outcome.plan->altitude);
    route.segments.push_back(scan);
    mission.routes.push_back(route);
    printNotices(polygon->notices, io);
    const int rc = saveWithGate(mission, p.positionalArguments().at(1), 0, p.isSet(QStringLiteral("force")), io);
    if (rc != Ok)
        return rc;
    const AreaScanPlan &plan = *outcome.plan;
    if (p.isSet(QStringLiteral("json"))) {
        io.out << QString::fromStdString(scanPlanJson(plan).dump(2)) << "\n";
    } else {
        io.out << "area " << QString::number(plan.areaSquareMeters / 1e4, 'f', 2) << " ha, " << plan.transects.size() << " transects ("
               << plan.cells << " cell(s)), spacing " << QString::number(plan.transectSpacing, 'f', 1) << " m\n"
               << "altitude " << QString::number(plan.altitude, 'f', 1) << " m " << altitudeTypeName(sp.altitudeType) << ", GSD "
               << QString::number(plan.groundSampleDistanceCm, 'f', 2) << " cm/px\n"
               << "trigger every " << QString::number(plan.triggerDistance, 'f', 1) << " m, " << plan.photoCount << " photos, path "
               << QString::number(plan.pathLength, 'f', 0) << " m\n"
               << "wrote " << p.positionalArguments().at(1) << "\n";
    }
    return Ok;
}

namespace {

// "LAT,LON" in degrees; nullopt when it is not.
std::optional<GeoPoint> readPoint(const QString &text)
{
    const QStringList parts = text.split(QLatin1Char(','));
    bool a = false, b = false;
    const GeoPoint p{parts.size() == 2 ? parts[0].trimmed().toDouble(&a) : 0.0, parts.size() == 2 ? parts[1].trimmed().toDouble(&b) : 0.0};
    return a && b && p.isValid() ? std::optional(p) : std::nullopt;
}

} // namespace

int runResume(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("takeoff"), QStringLiteral("Where the vehicle takes off for the rest (degrees)."), QStringLiteral("LAT,LON")});
    p.addOption({QStringLiteral("photo"), QStringLiteral("Where the last photo was taken: the rest starts where the next was due."), QStringLiteral("LAT,LON")});
    p.addOption({QStringLiteral("battery-change"), QStringLiteral("The rest from the N-th battery change the endurance model places (with --vehicle)."), QStringLiteral("N")});
    p.addOption({QStringLiteral("vehicle"), QStringLiteral("Energy profile (JSON), for --battery-change."), QStringLiteral("PROFILE")});
    p.addOption({QStringLiteral("wind"), QStringLiteral("With --vehicle: wind speed (m/s) and the direction it blows from (degrees)."), QStringLiteral("SPEED,FROM_DEG")});
    p.addOption({QStringLiteral("turns"), QStringLiteral("With --vehicle: coordinated (default) or stop."), QStringLiteral("MODE")});
    p.addOption({QStringLiteral("transit"), QStringLiteral("Height of the flight over to the resume point (m, in its altitude frame)."), QStringLiteral("M")});
    p.addOption({QStringLiteral("route"), QStringLiteral("The route (1-based) of a file that holds several."), QStringLiteral("N")});
    p.addOption({QStringLiteral("force"), QStringLiteral("Write the rest even with validation errors.")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable summary.")});
    if (!parse(p, args, 2, io))
        return Failure;
    const auto takeoff = readPoint(p.value(QStringLiteral("takeoff")));
    if (!takeoff) {
        io.err << "sortie-plan: resume needs --takeoff LAT,LON (degrees), where the vehicle stands\n";
        return Failure;
    }
    if (p.isSet(QStringLiteral("photo")) == p.isSet(QStringLiteral("battery-change"))) {
        io.err << "sortie-plan: resume needs one of --photo LAT,LON and --battery-change N\n";
        return Failure;
    }
    const Result<LoadedMission> loaded = loadMission(p.positionalArguments().at(0));
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return Failure;
    }
    const auto &routes = loaded->mission.routes;
    int index = 0;
    if (p.isSet(QStringLiteral("route"))) {
        bool ok = false;
        index = p.value(QStringLiteral("route")).toInt(&ok) - 1;
        if (!ok || index < 0 || size_t(index) >= routes.size()) {
            io.err << "sortie-plan: --route takes 1 to " << routes.size() << "\n";
            return Failure;
        }
    } else if (routes.size() != 1) {
        io.err << "sortie-plan: " << p.positionalArguments().at(0) << " holds " << routes.size() << " routes: choose one with --route N\n";
        return Failure;
    }
    const Route &route = routes[size_t(index)];

    resume::ResumeRequest request;
    request.takeoff = *takeoff;
    if (p.isSet(QStringLiteral("transit"))) {
        bool ok = false;
        request.transitAltitude = p.value(QStringLiteral("transit")).toDouble(&ok);
        if (!ok || !std::isfinite(*request.transitAltitude)) {
            io.err << "sortie-plan: --transit takes metres\n";
            return Failure;
        }
    }
    if (p.isSet(QStringLiteral("photo"))) {
        const auto photo = readPoint(p.value(QStringLiteral("photo")));
        if (!photo) {
            io.err << "sortie-plan: --photo takes LAT,LON in degrees\n";
            return Failure;
        }
        request.lastPhoto = *photo;
    } else {
        if (!p.isSet(QStringLiteral("vehicle"))) {
            io.err << "sortie-plan: --battery-change needs --vehicle PROFILE.json: the changes are the endurance model's\n";
            return Failure;
        }
        QString error;
        const auto endurance = readEnduranceInput(p.value(QStringLiteral("vehicle")), p.value(QStringLiteral("wind")), p.value(QStringLiteral("turns")), &error);
        if (!endurance) {
            io.err << "sortie-plan: " << error << "\n";
            return Failure;
        }
        const auto estimate = endurance::estimateEndurance(route, endurance->profile, endurance->conditions);
        if (!estimate) {
            io.err << "sortie-plan: " << estimate.error().toString() << "\n";
            return Failure;
        }
        bool ok = false;
        const int n = p.value(QStringLiteral("battery-change")).toInt(&ok);
        if (!ok || n < 1 || size_t(n) > estimate->changes.size()) {
            io.err << "sortie-plan: the route has " << estimate->changes.size() << " battery change(s) with this profile; --battery-change takes 1 to "
                   << estimate->changes.size() << "\n";
            return Failure;
        }
        const endurance::BatteryChange &change = estimate->changes[size_t(n - 1)];
        request.from = resume::ResumeRequest::From::Place;
        request.place = change.at.position;
        request.placeDistance = change.at.distance;
    }
    const auto plan = resume::resumeRoute(route, request);
    if (!plan) {
        io.err << "sortie-plan: " << plan.error().toString() << "\n";
        return Failure;
    }
    Mission rest;
    rest.name = plan->route.settings.name;
    rest.routes.push_back(plan->route);
    const int rc = saveWithGate(rest, p.positionalArguments().at(1), 0, p.isSet(QStringLiteral("force")), io);
    if (rc != Ok)
        return rc;
    if (p.isSet(QStringLiteral("json"))) {
        Json notes = Json::array();
        for (const QString &n : plan->notes)
            notes.push_back(n.toStdString());
        const Json summary{{"name", plan->route.settings.name.toStdString()},
                           {"resumedRow", plan->resumedRow + 1},
                           {"resumeAt", {{"latitude", plan->resumeAt.latitude}, {"longitude", plan->resumeAt.longitude}}},
                           {"flown", plan->flownMetres},
                           {"remaining", plan->remainingMetres},
                           {"segments", plan->route.segments.size()},
                           {"notes", notes}};
        io.out << QString::fromStdString(summary.dump(2)) << "\n";
    } else {
        for (const QString &n : plan->notes)
            io.out << n << "\n";
        io.out << "wrote " << p.positionalArguments().at(1) << "\n";
    }
    return Ok;
}

} // namespace sortie::plan
