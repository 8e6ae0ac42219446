#include "ConflictsCommand.h"

#include "ConflictSearch.h"
#include "JsonCursor.h"
#include "MissionFiles.h"
#include "ScanPlanCache.h"

#include <QCommandLineParser>

#include <cmath>
#include <optional>

namespace sortie::plan {

using namespace sortie::deconfliction;
using namespace sortie::mission;
using namespace sortie::mission::formats;

namespace {

// Comma-separated numbers; nullopt when one is not a finite number.
std::optional<std::vector<double>> numbers(const QString &text)
{
    std::vector<double> out;
    for (const QString &part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v))
            return std::nullopt;
        out.push_back(v);
    }
    return out;
}

// Milliseconds and millimetres are plenty for a report.
double rounded(double v)
{
    return std::round(v * 1000.0) / 1000.0;
}

QString fixed(double v, int decimals = 1)
{
    return QString::number(v, 'f', decimals);
}

struct LoadedFlight
{
    ScheduledFlight flight;
    AltitudeType frame = AltitudeType::Agl;
};

// The route of one file timed as the command line flies it: straight legs at the route's speeds (or
// `speed`), the height changing evenly along each leg (no climb or descent rate), the waypoints'
// holds, from `start`.
std::optional<LoadedFlight> loadFlight(const QString &file, double start, std::optional<double> speed, Streams io)
{
    const Result<LoadedMission> loaded = loadMission(file);
    if (!loaded) {
        io.err << "sortie-plan: " << loaded.error().toString() << "\n";
        return std::nullopt;
    }
    for (const QString &n : loaded->notices)
        io.err << "note: " << n << "\n";
    const std::vector<Route> &routes = loaded->mission.routes;
    if (routes.size() != 1) {
        io.err << "sortie-plan: " << file << " holds " << routes.size() << " routes; conflicts takes one route per file\n";
        return std::nullopt;
    }
    const Route &route = routes.front();
    ScanPlanCache cache;
    std::vector<PathPoint> path = flightPath(route, &cache);
    if (path.empty()) {
        io.err << "sortie-plan: " << file << ": the route has no waypoints\n";
        return std::nullopt;
    }
    TimingParameters parameters;
    parameters.cruiseSpeed = route.settings.initialSpeed;
    if (speed) {
        parameters.cruiseSpeed = *speed;
        for (PathPoint &p : path)
            p.speed = *speed;
    }
    const Result<RouteTimeline> timeline = timePath(route, path, parameters);
    if (!timeline) {
        io.err << "sortie-plan: " << file << ": " << timeline.error().toString() << "\n";
        return std::nullopt;
    }
    LoadedFlight out;
    out.flight.name = route.settings.name;
    out.flight.timeline = *timeline;
    out.flight.start = start;
    out.frame = path.front().altitudeType;
    return out;
}

Json sideJson(const ConflictSide &s)
{
    return {{"latitude", s.position.latitude}, {"longitude", s.position.longitude}, {"altitude", rounded(s.altitude)}};
}

} // namespace

int runConflicts(const QStringList &args, Streams io)
{
    QCommandLineParser p;
    p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    p.addOption({QStringLiteral("start"), QStringLiteral("Each route's start, seconds (default 0)."), QStringLiteral("SECONDS,SECONDS,...")});
    p.addOption({QStringLiteral("speed"), QStringLiteral("Fly every leg at this ground speed, m/s."), QStringLiteral("M/S")});
    p.addOption({QStringLiteral("separation"), QStringLiteral("Horizontal and vertical separation, m (default 20,15)."), QStringLiteral("H,V")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    if (!p.parse(QStringList{QStringLiteral("sortie-plan")} + args)) {
        io.err << "sortie-plan: " << p.errorText() << "\n";
        return Failure;
    }
    const QStringList files = p.positionalArguments();
    if (files.size() < 2) {
        io.err << "sortie-plan: conflicts expects at least two route files, got " << files.size() << "\n";
        return Failure;
    }
    std::vector<double> starts(size_t(files.size()), 0.0);
    if (p.isSet(QStringLiteral("start"))) {
        const auto given = numbers(p.value(QStringLiteral("start")));
        if (!given) {
            io.err << "sortie-plan: --start needs numbers of seconds separated by commas, got \"" << p.value(QStringLiteral("start")) << "\"\n";
            return Failure;
        }
        if (given->size() != starts.size()) {
            io.err << "sortie-plan: --start gives " << given->size() << " start(s) for " << files.size() << " route files\n";
            return Failure;
        }
        starts = *given;
    }
    std::optional<double> speed;
    if (p.isSet(QStringLiteral("speed"))) {
        bool ok = false;
        speed = p.value(QStringLiteral("speed")).toDouble(&ok);
        if (!ok || !(*speed > 0) || !std::isfinite(*speed)) {
            io.err << "sortie-plan: --speed needs a positive number of metres per second\n";
            return Failure;
        }
    }
    ConflictQuery query;
    if (p.isSet(QStringLiteral("separation"))) {
        const auto given = numbers(p.value(QStringLiteral("separation")));
        if (!given || given->size() != 2 || !((*given)[0] > 0) || !((*given)[1] > 0)) {
            io.err << "sortie-plan: --separation needs two positive numbers of metres, horizontal,vertical (like 20,15)\n";
            return Failure;
        }
        query.separation = {(*given)[0], (*given)[1]};
    }

    std::vector<ScheduledFlight> flights;
    std::optional<AltitudeType> frame;
    bool framesDiffer = false;
    for (qsizetype i = 0; i < files.size(); ++i) {
        std::optional<LoadedFlight> f = loadFlight(files[i], starts[size_t(i)], speed, io);
        if (!f)
            return Failure;
        framesDiffer |= frame && *frame != f->frame;
        frame = f->frame;
        flights.push_back(std::move(f->flight));
    }
    if (framesDiffer)
        io.err << "note: the routes' altitudes are in different frames (AGL and AMSL); they are compared as the numbers they are\n";

    const ConflictReport report = findConflicts(flights, query);
    if (p.isSet(QStringLiteral("json"))) {
        Json conflicts = Json::array();
        for (const Conflict &c : report.conflicts)
            conflicts.push_back({{"routes", {c.first + 1, c.second + 1}},
                                 {"legs", {c.firstAt.leg, c.secondAt.leg}},
                                 {"time", rounded(c.time)},
                                 {"horizontal", rounded(c.horizontal)},
                                 {"vertical", rounded(c.vertical)},
                                 {"from", rounded(c.interval.begin)},
                                 {"to", rounded(c.interval.end)},
                                 {"positions", {sideJson(c.firstAt), sideJson(c.secondAt)}}});
        io.out << QString::fromStdString(Json{{"pairs", report.pairs},
                                              {"separation", {{"horizontal", query.separation.horizontal}, {"vertical", query.separation.vertical}}},
                                              {"conflicts", std::move(conflicts)}}
                                             .dump(2))
               << "\n";
    } else {
        io.out << files.size() << " routes, " << report.pairs << (report.pairs == 1 ? " pair" : " pairs") << ", separation "
               << query.separation.horizontal << " m across and " << query.separation.vertical << " m in height: "
               << (report.conflicts.empty() ? QStringLiteral("no conflict") : QStringLiteral("%1 conflict(s)").arg(report.conflicts.size())) << "\n";
        for (const Conflict &c : report.conflicts)
            io.out << "  routes " << c.first + 1 << " (" << files[c.first] << ", leg " << c.firstAt.leg << ") and " << c.second + 1 << " ("
                   << files[c.second] << ", leg " << c.secondAt.leg << "): from " << fixed(c.interval.begin) << " s to "
                   << fixed(c.interval.end) << " s, closest at " << fixed(c.time) << " s: " << fixed(c.horizontal) << " m across, "
                   << fixed(c.vertical) << " m in height\n";
    }
    return report.conflicts.empty() ? Ok : ValidationErrors;
}

} // namespace sortie::plan
