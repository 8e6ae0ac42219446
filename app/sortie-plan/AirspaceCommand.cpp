#include "AirspaceCommand.h"

#include "AirspaceReport.h"
#include "AirspaceRule.h"
#include "ElevationService.h"
#include "FlownPath.h"
#include "DemOpener.h"
#include "MissionFiles.h"
#include "TerrainReport.h"

#include <QCommandLineParser>

#include <cmath>

namespace sortie::plan {

using namespace sortie::mission;
using namespace sortie::mission::formats;

int runAirspace(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    p.addOption({QStringLiteral("zones"), QStringLiteral("A zone file: .plan (geofence), .geojson / .json, .kml. Repeatable."), QStringLiteral("FILE")});
    p.addOption({QStringLiteral("dem"), QStringLiteral("A DEM (any raster GDAL reads, an SRTM .hgt tile) or a folder of them (AGL heights, terrain following)."), QStringLiteral("PATH")});
    p.addOption({QStringLiteral("buffer"), QStringLiteral("Warn when a leg comes this close to a zone, m."), QStringLiteral("METERS"), QStringLiteral("20")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    if (!p.parse(QStringList{QStringLiteral("sortie-plan")} + args)) {
        io.err << "sortie-plan: " << p.errorText() << "\n";
        return Failure;
    }
    if (p.positionalArguments().size() != 1) {
        io.err << "sortie-plan: airspace expects one route file, got " << p.positionalArguments().size() << "\n";
        return Failure;
    }
    if (!p.isSet(QStringLiteral("zones"))) {
        io.err << "sortie-plan: airspace needs --zones FILE (.plan, .geojson, .json or .kml)\n";
        return Failure;
    }
    bool ok = false;
    const double buffer = p.value(QStringLiteral("buffer")).toDouble(&ok);
    if (!ok || !(buffer >= 0) || !std::isfinite(buffer)) {
        io.err << "sortie-plan: --buffer needs a number of metres, 0 or more\n";
        return Failure;
    }
    QString error;
    const std::optional<ZoneInput> zones = readZoneInput(p.values(QStringLiteral("zones")), buffer, &error);
    if (!zones) {
        io.err << "sortie-plan: " << error << "\n";
        return Failure;
    }
    std::unique_ptr<terrain::ElevationSource> tiles;
    terrain::ElevationService service;
    if (p.isSet(QStringLiteral("dem"))) {
        QString demError;
        tiles = raster::openDem(p.value(QStringLiteral("dem")), &demError);
        if (!tiles) {
            io.err << "sortie-plan: " << demError << "\n";
            return Failure;
        }
        service.setSources({tiles.get()});
    }
    const QString file = p.positionalArguments().at(0);
    const Result<LoadedMission> loaded = loadMission(file);
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return Failure;
    }
    for (const QString &n : loaded->notices)
        io.err << "note: " << n << "\n";
    for (const QString &n : zones->problems)
        io.err << "note: " << n << "\n";
    const auto routes = profileRoutes(file, loaded->mission, &error);
    if (!routes) {
        io.err << "sortie-plan: " << file << ": " << error << "\n";
        return Failure;
    }
    const bool wpl = formatForPath(file) == FileFormat::Wpl;

    const bool json = p.isSet(QStringLiteral("json"));
    bool violations = false;
    Json out = Json::array();
    for (size_t i = 0; i < routes->size(); ++i) {
        const terrain::ProfileRoute &route = (*routes)[i];
        std::optional<terrain::TerrainProfile> ground;
        if (tiles)
            ground = terrain::computeProfile(route, service);
        const airspace::FlightEnds ends = !wpl && i < loaded->mission.routes.size() ? airspace::flightEndsOf(loaded->mission.routes[i])
                                                                                    : airspace::FlightEnds{};
        const airspace::FlownPath path = airspace::flownPath(route, ground ? &*ground : nullptr, ends);
        airspace::AirspaceChecker checker(zones->zones, buffer);
        const airspace::AirspaceReport report = checker.check(path);
        violations |= !report.violations.empty();
        if (json) {
            out.push_back({{"name", route.name.toStdString()}, {"airspace", airspaceJson(report, *zones)}});
            continue;
        }
        io.out << "Route \"" << route.name << "\": " << report.zones << " zone(s), " << report.violations.size() << " violation(s), "
               << report.warnings.size() << " warning(s) within " << buffer << " m\n";
        for (const auto &v : report.violations)
            io.out << "  error: " << airspace::violationMessage(v, zones->zones->zones()[size_t(v.zone)]) << "\n";
        for (const auto &w : report.warnings)
            io.out << "  warning: " << airspace::warningMessage(w, zones->zones->zones()[size_t(w.zone)], buffer) << "\n";
    }
    if (json) {
        Json problems = Json::array();
        for (const QString &n : zones->problems)
            problems.push_back(n.toStdString());
        io.out << QString::fromStdString(Json{{"file", file.toStdString()}, {"routes", std::move(out)}, {"zoneProblems", std::move(problems)}}.dump(2))
               << "\n";
    }
    if (tiles) {
        for (const QString &problem : tiles->problems())
            io.err << "sortie-plan: " << problem << "\n";
        if (!tiles->problems().isEmpty())
            return Failure;
    }
    return violations ? ValidationErrors : Ok;
}

} // namespace sortie::plan
