#include "ProfileCommand.h"

#include "ElevationService.h"
#include "DemOpener.h"
#include "MissionFiles.h"
#include "TerrainReport.h"
#include "TerrainRule.h"

#include <QCommandLineParser>
#include <QFile>

#include <cmath>

namespace sortie::plan {

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace sortie::terrain;

namespace {
QString cell(double v, int width, int decimals = 1)
{
    return (std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("-")).rightJustified(width);
}

} // namespace

int runProfile(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    p.addOption({QStringLiteral("dem"), QStringLiteral("A DEM: any raster GDAL reads (GeoTIFF, .hgt, ...) or a folder of them."), QStringLiteral("PATH")});
    p.addOption({QStringLiteral("step"), QStringLiteral("Sampling step, m."), QStringLiteral("METERS"), QStringLiteral("30")});
    p.addOption({QStringLiteral("safe-distance"), QStringLiteral("Clearance to keep from the ground, m (default: the route's vehicle profile, 10)."),
                 QStringLiteral("METERS")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    if (!p.parse(QStringList{QStringLiteral("sortie-plan")} + args)) {
        io.err << "sortie-plan: " << p.errorText() << "\n";
        return Failure;
    }
    if (p.positionalArguments().size() != 1) {
        io.err << "sortie-plan: profile expects one route file, got " << p.positionalArguments().size() << "\n";
        return Failure;
    }
    if (!p.isSet(QStringLiteral("dem"))) {
        io.err << "sortie-plan: profile needs --dem PATH (a DEM file GDAL reads, an SRTM .hgt tile, or a folder of them)\n";
        return Failure;
    }
    bool ok = false;
    const double step = p.value(QStringLiteral("step")).toDouble(&ok);
    if (!ok || !(step > 0) || !std::isfinite(step)) {
        io.err << "sortie-plan: --step needs a positive number of metres\n";
        return Failure;
    }
    std::optional<double> safeDistance;
    if (p.isSet(QStringLiteral("safe-distance"))) {
        safeDistance = p.value(QStringLiteral("safe-distance")).toDouble(&ok);
        if (!ok || !(*safeDistance >= 0)) {
            io.err << "sortie-plan: --safe-distance needs a number of metres\n";
            return Failure;
        }
    }
    QString demError;
    const std::unique_ptr<ElevationSource> dem = raster::openDem(p.value(QStringLiteral("dem")), &demError);
    if (!dem) {
        io.err << "sortie-plan: " << demError << "\n";
        return Failure;
    }
    ElevationService service;
    service.setSources({dem.get()});
    const QString file = p.positionalArguments().at(0);
    const Result<LoadedMission> loaded = loadMission(file);
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return Failure;
    }
    for (const QString &n : loaded->notices)
        io.err << "note: " << n << "\n";
    QString error;
    const auto routes = profileRoutes(file, loaded->mission, &error);
    if (!routes) {
        io.err << "sortie-plan: " << file << ": " << error << "\n";
        return Failure;
    }

    const bool json = p.isSet(QStringLiteral("json"));
    bool errors = false;
    Json out = Json::array();
    for (ProfileRoute route : *routes) {
        if (safeDistance)
            route.safeDistance = *safeDistance;
        const TerrainProfile profile = computeProfile(route, service, step);
        const std::vector<ValidationIssue> issues = terrainIssues(route, profile);
        for (const ValidationIssue &i : issues)
            errors |= i.severity == Severity::Error;
        if (json) {
            Json r{{"name", route.name.toStdString()}, {"terrain", terrainJson(route, profile, true)}};
            r["validation"] = Json::array();
            for (const ValidationIssue &i : issues)
                r["validation"].push_back({{"severity", i.severity == Severity::Error ? "error" : "warning"},
                                           {"rule", i.rule.toStdString()}, {"message", i.message.toStdString()}});
            out.push_back(std::move(r));
            continue;
        }
        io.out << "Route \"" << route.name << "\": " << QString::number(profile.path.length(), 'f', 1) << " m, "
               << profile.size() << " samples every " << step << " m, ground from " << profile.sourcesTried.join(QStringLiteral(", ")) << "\n";
        if (profile.minClearance)
            io.out << "  lowest clearance " << QString::number(profile.minClearance->clearance, 'f', 1) << " m on leg "
                   << profile.minClearance->leg + 1 << " at " << QString::number(profile.minClearance->distance, 'f', 1) << " m ("
                   << QString::number(profile.minClearance->distanceAlongLeg, 'f', 1) << " m along the leg)\n";
        else
            io.out << "  lowest clearance unknown: no terrain data under the route\n";
        for (const VerticalMove &v : profile.verticals)
            io.out << "  vertical " << (v.climb ? "climb" : "descent") << " at " << QString::number(v.distance, 'f', 1) << " m on leg "
                   << v.leg + 1 << ": " << cell(v.fromAmsl, 0) << " → " << cell(v.toAmsl, 0) << " m AMSL\n";
        io.out << "  " << QStringLiteral("distance").rightJustified(10) << QStringLiteral("leg").rightJustified(5)
               << QStringLiteral("latitude").rightJustified(13) << QStringLiteral("longitude").rightJustified(14)
               << QStringLiteral("ground").rightJustified(9) << QStringLiteral("altitude").rightJustified(10)
               << QStringLiteral("clearance").rightJustified(11) << "\n";
        for (size_t i = 0; i < profile.size(); ++i) {
            const auto &pt = profile.path.points[i];
            io.out << "  " << cell(pt.distance, 10) << QString::number(pt.leg + 1).rightJustified(5)
                   << cell(pt.position.latitude, 13, 7) << cell(pt.position.longitude, 14, 7) << cell(profile.ground[i].ground, 9)
                   << cell(profile.altitudeAmsl[i], 10) << cell(profile.clearance(i), 11) << "\n";
        }
        for (const ValidationIssue &i : issues)
            io.out << "  " << (i.severity == Severity::Error ? "error" : "warning") << " [" << i.rule << "] " << i.message << "\n";
    }
    if (json)
        io.out << QString::fromStdString(Json{{"file", file.toStdString()}, {"dem", p.value(QStringLiteral("dem")).toStdString()},
                                              {"routes", std::move(out)}}.dump(2)) << "\n";
    // A tile that turned out corrupt when the path reached it: the output shows no data there; say why.
    for (const QString &problem : dem->problems())
        io.err << "sortie-plan: " << problem << "\n";
    if (!dem->problems().isEmpty())
        return Failure;
    return errors ? ValidationErrors : Ok;
}

} // namespace sortie::plan
