// UAS geographical zones at a national file's size (Switzerland publishes about 1,200 in ED-269): a
// generated ED-269 file of 1,200 zones over 20 x 20 km around the shared 10,000-waypoint route
// (tests/mission/BenchRoute.h, near Riga): polygons of 8 to 120 vertices and circles, 50 to 800 m
// across, one in five with three stacked volumes (metres and feet, AGL and AMSL), one in four on a
// weekly schedule, one in seven between two dates, every restriction. Read, turned into zones and
// indexed; then the route checked against them in a flight's window. Targets: reading and indexing
// under 400 ms (a file loaded once a day); a fresh check under 50 ms (it runs when the zones or the
// window change; bench_airspace's 20 ms is for sparser, smaller zones, and this set's first run
// missed it: docs/performance.md); the re-check after moving one waypoint under 16 ms (what a drag
// costs).
#include "AirspaceCheck.h"
#include "AirspaceRule.h"
#include "BenchClock.h"
#include "BenchRoute.h"
#include "FlownPath.h"
#include "GeoZoneReader.h"
#include "Geodesy.h"
#include "ZoneFiles.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <random>

using namespace sortie::airspace;
using namespace sortie::mission;
using namespace sortie::test;

namespace {
bool report(const char *what, Timing t, double targetMs)
{
    const Verdict v = judge(t, targetMs);
    std::printf("%-56s %8.3f ms wall, %8.3f ms CPU, worst %8.3f ms", what, t.wallMs, t.cpuMs, t.worstMs);
    if (targetMs > 0)
        std::printf("  (target < %.0f ms)%s", targetMs, v.note);
    std::printf("\n");
    return v.met;
}

QString number(double v)
{
    return QString::number(v, 'f', 7);
}

QByteArray generatedEd269(int n)
{
    std::mt19937 random(269);
    std::uniform_real_distribution<double> where(-10000, 10000), size(25, 400), unit(0, 1);
    const LocalTangentPlane plane({56.95, 24.1});
    static const char *const restrictions[] = {"PROHIBITED", "REQ_AUTHORISATION", "CONDITIONAL", "NO_RESTRICTION"};
    QStringList features;
    for (int i = 0; i < n; ++i) {
        const double x = where(random), y = where(random), r = size(random);
        QString projection;
        if (i % 3 == 0) {
            const GeoPoint c = plane.unproject({x, y});
            projection = QStringLiteral(R"({"type": "Circle", "center": [%1, %2], "radius": %3})").arg(number(c.longitude), number(c.latitude)).arg(r);
        } else {
            const int vertices = 8 + (i * 7) % 113;
            QStringList ring;
            for (int k = 0; k <= vertices; ++k) {
                const double a = 2 * M_PI * (k % vertices) / vertices, rr = r * (0.8 + 0.2 * std::sin(3 * a + i));
                const GeoPoint p = plane.unproject({x + rr * std::cos(a), y + rr * std::sin(a)});
                ring << QStringLiteral("[%1, %2]").arg(number(p.longitude), number(p.latitude));
            }
            projection = QStringLiteral(R"({"type": "Polygon", "coordinates": [[%1]]})").arg(ring.join(QStringLiteral(", ")));
        }
        QStringList volumes;
        if (i % 5 == 0) {
            volumes << QStringLiteral(R"({"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AGL", "upperLimit": 50, "upperVerticalReference": "AGL", "horizontalProjection": %1})").arg(projection)
                    << QStringLiteral(R"({"uomDimensions": "FT", "lowerLimit": 164, "lowerVerticalReference": "AGL", "upperLimit": 394, "upperVerticalReference": "AGL", "horizontalProjection": %1})").arg(projection)
                    << QStringLiteral(R"({"uomDimensions": "M", "lowerLimit": 120, "lowerVerticalReference": "AGL", "upperLimit": 99999, "upperVerticalReference": "AMSL", "horizontalProjection": %1})").arg(projection);
        } else {
            volumes << QStringLiteral(R"({"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AGL", "upperLimit": %1, "upperVerticalReference": "AGL", "horizontalProjection": %2})")
                           .arg(i % 2 ? 120 : 62).arg(projection);
        }
        QString applicability = QStringLiteral(R"([{"permanent": "YES"}])");
        if (i % 4 == 0)
            applicability = QStringLiteral(R"([{"permanent": "NO", "schedule": [{"day": ["SAT", "SUN"], "startTime": "18:00:00.00Z", "endTime": "23:00:00.00Z"}, {"day": ["FRI"], "startTime": "22:00Z", "endTime": "02:00Z"}]}])");
        else if (i % 7 == 0)
            applicability = QStringLiteral(R"([{"permanent": "NO", "startDateTime": "2026-05-01T00:00:00Z", "endDateTime": "2026-09-30T23:59:59Z"}])");
        features << QStringLiteral(R"({"identifier": "LV%1", "country": "LVA", "name": "Zone %1", "type": "COMMON", "restriction": "%2",
            "reason": ["AIR_TRAFFIC"], "message": "Generated zone %1", "applicability": %3,
            "zoneAuthority": [{"name": "Authority %1", "email": "zone%1@example.org", "purpose": "AUTHORIZATION", "intervalBefore": "P1D"}],
            "geometry": [%4]})")
                        .arg(i + 1)
                        .arg(QLatin1String(restrictions[i % 4]), applicability, volumes.join(QStringLiteral(", ")));
    }
    return QStringLiteral(R"({"title": "bench", "description": "generated", "features": [%1]})").arg(features.join(QStringLiteral(",\n"))).toUtf8();
}
} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    constexpr int kWaypoints = 10000, kZones = 1200;
    std::printf("Sortie geographical zones benchmark (%d ED-269 zones, %d waypoints; median of repeated runs; load average %.2f on %u cores)\n",
                kZones, kWaypoints, loadAverage(), std::thread::hardware_concurrency());
    const QByteArray data = generatedEd269(kZones);
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("zones.json"));
    {
        QFile f(file);
        if (!f.open(QIODevice::WriteOnly) || f.write(data) != data.size())
            return 2;
    }
    std::printf("%-56s %.1f MB\n", "  generated file", data.size() / 1e6);

    bool ok = true;
    ed::GeoZoneFile geo;
    report("read ED-269 (parse, zones, volumes, schedules)", median(5, [&] { geo = ed::readEd269(data).value(); }), 0);
    std::shared_ptr<const ZoneSet> zones;
    ok &= report("read + zones + index (loadZoneFile, ZoneSet)", median(5, [&] {
        zones = std::make_shared<const ZoneSet>(loadZoneFile(file).value().zones);
    }), 400);
    std::printf("%-56s %zu geographical zones, %zu zones (volumes), %lld problems\n", "  ", geo.zones.size(), zones->zones().size(),
                qlonglong(geo.problems.size()));

    Route route = benchRoute(kWaypoints);
    FlownPath path;
    report("flown path in 3D", median(5, [&] { path = flownPath(route); }), 0);
    // A Saturday evening: the weekend zones apply.
    const QDateTime start = QDateTime::fromString(QStringLiteral("2026-06-06T18:30:00Z"), Qt::ISODate);
    ed::TimeWindow window;
    report("flight window (time model over the route)", median(5, [&] { window = flightWindow(route, start); }), 0);
    std::printf("%-56s %s to %s\n", "  ", qPrintable(window.from.toString(Qt::ISODate)), qPrintable(window.to.toString(Qt::ISODate)));
    AirspaceReport found;
    ok &= report("check: every leg, fresh checker, in the window", median(11, [&] {
        AirspaceChecker checker(zones);
        checker.setWindow(window);
        found = checker.check(path);
    }), 50);
    Authorisations none;
    int errors = 0, warnings = 0, information = 0;
    for (const AirspaceViolation &v : found.violations)
        switch (findingLevel(v, zones->zones()[size_t(v.zone)], none)) {
        case FindingLevel::Error: ++errors; break;
        case FindingLevel::Warning: ++warnings; break;
        case FindingLevel::Information: ++information; break;
        }
    std::printf("%-56s %d errors, %d warnings, %d information, %zu near; %d zones apply, %d do not\n", "  found", errors, warnings, information,
                found.warnings.size(), found.zones, found.outsideWindow);
    report("  the messages of every finding, one by one", median(5, [&] {
        for (const AirspaceViolation &v : found.violations)
            (void)violationMessage(v, zones->zones()[size_t(v.zone)], none);
    }), 0);
    std::size_t issues = 0;
    report("  the route's issues (airspaceIssues, as AirspaceRule)", median(5, [&] { issues = airspaceIssues(found, *zones, 20.0, none).size(); }), 0);
    std::printf("%-56s %zu issues\n", "  ", issues);

    // A 20-minute window on a Monday morning: the weekend evenings do not apply.
    const QDateTime monday = QDateTime::fromString(QStringLiteral("2026-06-08T09:00:00Z"), Qt::ISODate);
    AirspaceReport short_;
    report("check in a 20-minute window on a Monday morning", median(11, [&] {
        AirspaceChecker checker(zones);
        checker.setWindow(ed::TimeWindow{monday, monday.addSecs(1200)});
        short_ = checker.check(path);
    }), 0);
    std::printf("%-56s %zu findings, %zu near; %d zones apply, %d do not\n", "  found", short_.violations.size(), short_.warnings.size(), short_.zones,
                short_.outsideWindow);

    AirspaceChecker checker(zones);
    checker.setWindow(window);
    checker.check(path);
    const LocalTangentPlane plane = path.plane;
    const GeoPoint at = std::get<Waypoint>(route.segments[5050]).position;
    std::vector<FlownPath> dragged;
    for (int i = 0; i < 11; ++i) {
        std::get<Waypoint>(route.segments[5050]).position = geodesicDirect(at, 45, 3.0 * (i + 1)).point;
        dragged.push_back(flownPath(route, nullptr, nullptr, &plane));
    }
    ok &= report("re-check after moving one waypoint (same window)", measure(11, [&](int i) {
        checker.setWindow(window);
        found = checker.check(dragged[size_t(i)]);
    }), 16);
    std::printf("%-56s %d legs checked again\n", "  ", checker.legsCheckedLastTime());
    std::printf("%s\n", ok ? "all targets met" : "TARGET MISSED");
    return ok ? 0 : 1;
}
