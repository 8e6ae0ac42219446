#include "AirspaceCommand.h"

#include "AirspaceReport.h"
#include "AirspaceRule.h"
#include "ElevationService.h"
#include "FlownPath.h"
#include "DemOpener.h"
#include "MissionFiles.h"
#include "TerrainReport.h"

#include <QCommandLineParser>
#include <QTimeZone>

#include <algorithm>

#include <cmath>

namespace sortie::plan {

using namespace sortie::mission;
using namespace sortie::mission::formats;

int runAirspace(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    p.addOption({QStringLiteral("zones"), QStringLiteral("A zone file: .plan (geofence), .geojson / .json, .kml, or UAS geographical zones (ED-269, ED-318; by content). Repeatable."), QStringLiteral("FILE")});
    p.addOption({QStringLiteral("dem"), QStringLiteral("A DEM (any raster GDAL reads, an SRTM .hgt tile) or a folder of them (AGL heights, terrain following)."), QStringLiteral("PATH")});
    p.addOption({QStringLiteral("buffer"), QStringLiteral("Warn when a leg comes this close to a zone, m."), QStringLiteral("METERS"), QStringLiteral("20")});
    p.addOption({QStringLiteral("at"), QStringLiteral("The flight's planned start, ISO 8601 UTC (default: now). UAS geographical zones (ED-269, ED-318) count when they apply during the flight."), QStringLiteral("ISO-8601-UTC")});
    p.addOption({QStringLiteral("authorisation"), QStringLiteral("An authorisation for a UAS geographical zone: its identifier and the authorisation's reference. Repeatable."), QStringLiteral("IDENTIFIER=REFERENCE")});
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
    // --at and --authorisation override what the route file holds (RouteSettings::plannedStart,
    // authorisations); without them the file's own are used, and now when it has no start.
    std::optional<QDateTime> start;
    if (p.isSet(QStringLiteral("at"))) {
        const QString at = p.value(QStringLiteral("at"));
        start = QDateTime::fromString(at, Qt::ISODateWithMs);
        if (!start->isValid() || !at.contains(QLatin1Char('T'))) {
            io.err << "sortie-plan: --at needs an ISO 8601 date and time, e.g. 2026-06-06T18:00:00Z (got \"" << at << "\")\n";
            return Failure;
        }
        if (start->timeSpec() == Qt::LocalTime)  // no offset written: UTC, as the option says
            start = QDateTime(start->date(), start->time(), QTimeZone::utc());
        start = start->toUTC();
    }
    airspace::Authorisations given;
    for (const QString &a : p.values(QStringLiteral("authorisation"))) {
        const qsizetype eq = a.indexOf(QLatin1Char('='));
        if (eq <= 0 || eq == a.size() - 1) {
            io.err << "sortie-plan: --authorisation needs IDENTIFIER=REFERENCE (got \"" << a << "\")\n";
            return Failure;
        }
        given[a.left(eq).trimmed()] = a.mid(eq + 1).trimmed();
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
    for (const auto &[identifier, reference] : given) {
        const auto &all = zones->zones->zones();
        if (std::none_of(all.begin(), all.end(), [&, &id = identifier](const airspace::Zone &z) { return z.geoZone && z.geoZone->identifier == id; }))
            io.err << "note: --authorisation " << identifier << ": no UAS geographical zone has that identifier\n";
    }
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
        // The flight's window: from --at (or the route's planned start, or now) to the route's end
        // by the time model; the route's authorisations with --authorisation's over them.
        const mission::Route *own = !wpl && i < loaded->mission.routes.size() ? &loaded->mission.routes[i] : nullptr;
        const QDateTime from = start ? *start : own && own->settings.plannedStart ? *own->settings.plannedStart : QDateTime::currentDateTimeUtc();
        airspace::Authorisations authorisations = given;
        if (own)
            authorisations.insert(own->settings.authorisations.begin(), own->settings.authorisations.end());
        QString timingNote;
        const airspace::ed::TimeWindow window = own ? airspace::flightWindow(*own, from, nullptr, &timingNote)
                                                    : airspace::ed::TimeWindow{from, from};
        if (!timingNote.isEmpty())
            io.err << "note: route \"" << route.name << "\" cannot be timed (" << timingNote << "): zones count when they apply at its start\n";
        airspace::AirspaceChecker checker(zones->zones, buffer);
        checker.setWindow(window);
        const airspace::AirspaceReport report = checker.check(path);
        const auto &all = zones->zones->zones();
        std::vector<const airspace::AirspaceViolation *> errors, cautions, information;
        for (const auto &v : report.violations) {
            switch (airspace::findingLevel(v, all[size_t(v.zone)], authorisations)) {
            case airspace::FindingLevel::Error: errors.push_back(&v); break;
            case airspace::FindingLevel::Warning: cautions.push_back(&v); break;
            case airspace::FindingLevel::Information: information.push_back(&v); break;
            }
        }
        violations |= !errors.empty();
        if (json) {
            out.push_back({{"name", route.name.toStdString()}, {"airspace", airspaceJson(report, *zones, authorisations, window)}});
            continue;
        }
        io.out << "Route \"" << route.name << "\": " << report.zones << " zone(s), " << errors.size() << " violation(s), "
               << report.warnings.size() + cautions.size() << " warning(s) within " << buffer << " m";
        if (report.outsideWindow > 0)
            io.out << "; " << report.outsideWindow << " zone(s) do not apply from " << window.from.toString(Qt::ISODate) << " to "
                   << window.to.toString(Qt::ISODate);
        io.out << "\n";
        for (const auto *v : errors)
            io.out << "  error: " << airspace::violationMessage(*v, all[size_t(v->zone)], authorisations) << "\n";
        for (const auto *v : cautions)
            io.out << "  warning: " << airspace::violationMessage(*v, all[size_t(v->zone)], authorisations) << "\n";
        for (const auto *v : information)
            io.out << "  information: " << airspace::violationMessage(*v, all[size_t(v->zone)], authorisations) << "\n";
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
