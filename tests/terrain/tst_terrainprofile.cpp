// The terrain profile of a route, the terrain rules, the source order and terrain following.
#include "ElevationService.h"
#include "Geodesy.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "NoElevationSource.h"
#include "RouteAnalyzer.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentParameters.h"
#include "TerrainFollow.h"
#include "TerrainProfile.h"
#include "TerrainRule.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QTest>

#include <functional>

using namespace sortie::terrain;
using namespace sortie::terrain::test;
using sortie::mission::AltitudeType;
using sortie::mission::Route;
using sortie::mission::Waypoint;

namespace {
// A source from a formula, with an optional hole (a disc without data).
class FormulaSource : public ElevationSource
{
public:
    FormulaSource(QString name, std::function<std::optional<double>(const GeoPoint &)> f) : m_name(std::move(name)), m_f(std::move(f)) {}
    QString name() const override { return m_name; }
    ElevationSample sample(const GeoPoint &p) override
    {
        const auto v = m_f(p);
        return v ? ElevationSample::value(*v) : ElevationSample::noData();
    }

private:
    QString m_name;
    std::function<std::optional<double>(const GeoPoint &)> m_f;
};

ProfileRoute straight(double altitude, HeightReference reference, double lonEnd = 24.02)
{
    ProfileRoute r;
    r.waypoints.push_back({{56.9, 24.0}, altitude, reference, 0, QStringLiteral("Waypoint 1")});
    r.waypoints.push_back({{56.9, 24.01}, altitude, reference, 1, QStringLiteral("Waypoint 2")});
    r.waypoints.push_back({{56.9, lonEnd}, altitude, reference, 2, QStringLiteral("Waypoint 3")});
    return r;
}

Route routeOf(const std::vector<std::pair<GeoPoint, double>> &points, AltitudeType type)
{
    Route r;
    r.settings.name = QStringLiteral("test");
    for (const auto &[p, alt] : points) {
        Waypoint w;
        w.position = p;
        w.altitude = alt;
        w.altitudeType = type;
        r.segments.push_back(w);
    }
    return r;
}
} // namespace

class TstTerrainProfile : public QObject
{
    Q_OBJECT

private slots:
    void sampling()
    {
        const SampledPath p = samplePath({{56.9, 24.0}, {56.9, 24.01}, {56.91, 24.01}}, 30.0);
        QCOMPARE(p.legCount(), 2);
        QCOMPARE(p.vertexSample.size(), size_t(3));
        QCOMPARE(p.vertexSample.front(), 0);
        QCOMPARE(p.vertexSample.back(), int(p.points.size()) - 1);
        const double leg1 = sortie::mission::geodesicDistance({56.9, 24.0}, {56.9, 24.01});
        QCOMPARE(p.vertexDistance[1], leg1);
        for (size_t i = 1; i < p.points.size(); ++i) {
            const double gap = p.points[i].distance - p.points[i - 1].distance;
            QVERIFY(gap > 0 && gap <= 30.0 + 1e-9);
            // Each point is where its distance says: the geodesic from the leg start agrees to a centimetre.
            const int leg = p.points[i].leg;
            const double along = sortie::mission::geodesicDistance(p.vertices[size_t(leg)], p.points[i].position);
            QVERIFY2(std::abs(along - (p.points[i].distance - p.vertexDistance[size_t(leg)])) < 0.05, qPrintable(QString::number(i)));
        }
        QCOMPARE(samplePath({{1, 1}}, 30).points.size(), size_t(1));
        QVERIFY(samplePath({}, 30).points.empty());
    }

    // Clearance over a plane at 100 m: AMSL 150 gives 50 m; AGL over it is above the local ground.
    void profileOverPlane()
    {
        FormulaSource flat(QStringLiteral("flat"), [](const GeoPoint &) { return 100.0; });
        ElevationService service;
        service.setSources({&flat});
        const TerrainProfile amsl = computeProfile(straight(150, HeightReference::Amsl), service, 30);
        QVERIFY(!amsl.pending);
        QVERIFY(amsl.noData.empty());
        QVERIFY(amsl.lowStretches.empty());
        QCOMPARE(amsl.minClearance->clearance, 50.0);
        QCOMPARE(amsl.waypoints[1].altitudeAgl, 50.0);
        QCOMPARE(amsl.ground[3].source, 0);
        const TerrainProfile agl = computeProfile(straight(30, HeightReference::AboveTerrain), service, 30);
        QCOMPARE(agl.waypoints[2].altitudeAmsl, 130.0);
        QCOMPARE(agl.minClearance->clearance, 30.0);
    }

    // Level at 300 m AMSL over a valley that falls from 200 m to 150 m and back: 120 m above the
    // surface is passed in the valley only; one warning per leg, at its highest point.
    void aboveTheSurfaceLimitInAValley()
    {
        FormulaSource valley(QStringLiteral("valley"), [](const GeoPoint &p) { return p.longitude < 24.005 || p.longitude > 24.015 ? 200.0 : 150.0; });
        ElevationService service;
        service.setSources({&valley});
        const ProfileRoute r = straight(300, HeightReference::Amsl);
        const auto issues = terrainIssues(r, computeProfile(r, service, 10));
        QCOMPARE(issues.size(), size_t(2));
        for (int leg : {0, 1}) {
            const auto &i = issues[size_t(leg)];
            QCOMPARE(i.rule, QStringLiteral("terrain-above-surface-limit"));
            QCOMPARE(i.severity, sortie::mission::Severity::Warning);
            QCOMPARE(i.segment, leg);
            QVERIFY2(i.message.contains(QStringLiteral("flies up to 150.0 m above the ground")) && i.message.contains(QStringLiteral("allows 120.0 m above the surface")),
                     qPrintable(i.message));
        }
        // 100 m above the valley floor is inside the limit everywhere.
        const ProfileRoute low = straight(250, HeightReference::Amsl);
        QVERIFY(terrainIssues(low, computeProfile(low, service, 10)).empty());
        // The limit is the route's to set (an authorisation in the specific category).
        ProfileRoute authorised = r;
        authorised.surfaceHeightLimit = 150.0;
        QVERIFY(terrainIssues(authorised, computeProfile(authorised, service, 10)).empty());
    }

    // A ridge between waypoints 1 and 2: the waypoints are high enough, the leg is not.
    void ridgeBetweenWaypoints()
    {
        // 300 m high around 24.005°E, 20 m elsewhere.
        FormulaSource ridge(QStringLiteral("ridge"), [](const GeoPoint &p) { return std::abs(p.longitude - 24.005) < 0.001 ? 300.0 : 20.0; });
        ElevationService service;
        service.setSources({&ridge});
        ProfileRoute r = straight(100, HeightReference::Amsl);
        const TerrainProfile profile = computeProfile(r, service, 10);
        QVERIFY(profile.minClearance);
        QCOMPARE(profile.minClearance->clearance, -200.0);
        QCOMPARE(profile.minClearance->leg, 0);
        QCOMPARE(profile.lowStretches.size(), size_t(1));
        const double legLength = profile.path.vertexDistance[1];
        QVERIFY(profile.minClearance->distanceAlongLeg > legLength * 0.4 && profile.minClearance->distanceAlongLeg < legLength * 0.6);
        const auto issues = terrainIssues(r, profile);
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].rule, QStringLiteral("terrain-clearance"));
        QCOMPARE(issues[0].severity, sortie::mission::Severity::Error);
        QCOMPARE(issues[0].segment, 0);
        QVERIFY2(issues[0].message.startsWith(QStringLiteral("Leg 1 (Waypoint 1 → Waypoint 2) flies 200.0 m below the ground at ")),
                 qPrintable(issues[0].message));
        QVERIFY(issues[0].message.contains(QStringLiteral("safe distance of 10.0 m")));

        // 9 m over flat ground is too low too; 10 m is not.
        FormulaSource flat(QStringLiteral("flat"), [](const GeoPoint &) { return 20.0; });
        service.setSources({&flat});
        QCOMPARE(terrainIssues(r, computeProfile(straight(29, HeightReference::Amsl), service)).size(), size_t(2));
        QVERIFY(terrainIssues(r, computeProfile(straight(30, HeightReference::Amsl), service)).empty());
    }

    // A hole in the data: reported per leg with the sources tried, never as 0 m.
    void noDataStretches()
    {
        FormulaSource holed(QStringLiteral("holed"), [](const GeoPoint &p) -> std::optional<double> {
            if (p.longitude > 24.012 && p.longitude < 24.015)
                return std::nullopt;
            return 10.0;
        });
        NoElevationSource none;
        ElevationService service;
        service.setSources({&holed, &none});
        ProfileRoute r = straight(100, HeightReference::Amsl);
        const TerrainProfile profile = computeProfile(r, service, 30);
        QCOMPARE(profile.noData.size(), size_t(1));
        QCOMPARE(profile.noData[0].leg, 1);
        for (size_t i = 0; i < profile.size(); ++i) {
            const double lon = profile.path.points[i].position.longitude;
            if (lon > 24.0121 && lon < 24.0149) {
                QVERIFY(!profile.ground[i].hasValue());
                QVERIFY(std::isnan(profile.ground[i].ground));
                QVERIFY(std::isnan(profile.clearance(i)));
                QVERIFY(profile.noData[0].fromDistance <= profile.path.points[i].distance);
                QVERIFY(profile.noData[0].toDistance >= profile.path.points[i].distance);
            }
        }
        const auto issues = terrainIssues(r, profile);
        QCOMPARE(issues.size(), size_t(1));
        QCOMPARE(issues[0].rule, QStringLiteral("terrain-no-data"));
        QCOMPARE(issues[0].severity, sortie::mission::Severity::Warning);
        QCOMPARE(issues[0].segment, 1);
        QVERIFY(issues[0].message.startsWith(QStringLiteral("Leg 2 (Waypoint 2 → Waypoint 3): no terrain data from ")));
        QVERIFY(issues[0].message.contains(QStringLiteral("(tried: holed, none)")));

        // AGL waypoints over the hole: their height is unknown, an error.
        ProfileRoute agl = straight(50, HeightReference::AboveTerrain, 24.013);
        const auto aglIssues = terrainIssues(agl, computeProfile(agl, service, 30));
        QVERIFY(std::any_of(aglIssues.begin(), aglIssues.end(), [](const auto &i) {
            return i.rule == QLatin1String("terrain-agl-no-data") && i.segment == 2 && i.severity == sortie::mission::Severity::Error
                   && i.message.startsWith(QLatin1String("Waypoint 3: the altitude is above the ground, but there is no terrain data there"));
        }));
    }

    // The first source with a value wins, and says so; the next fills its holes.
    void sourceOrder()
    {
        FormulaSource west(QStringLiteral("west"), [](const GeoPoint &p) -> std::optional<double> {
            return p.longitude < 24.01 ? std::optional<double>(5.0) : std::nullopt;
        });
        FormulaSource everywhere(QStringLiteral("everywhere"), [](const GeoPoint &) { return 7.0; });
        ElevationService service;
        QSignalSpy changed(&service, &ElevationService::changed);
        service.setSources({&west, &everywhere});
        QCOMPARE(changed.count(), 1);
        QCOMPARE(service.sample({56.9, 24.0}).source, 0);
        QCOMPARE(service.sample({56.9, 24.0}).ground, 5.0);
        QCOMPARE(service.sample({56.9, 24.02}).source, 1);
        QCOMPARE(service.sourceName(1), QStringLiteral("everywhere"));
        QCOMPARE(service.sourceName(-1), QStringLiteral("none"));
        const TerrainProfile p = computeProfile(straight(100, HeightReference::Amsl), service);
        QCOMPARE(p.ground.front().source, 0);
        QCOMPARE(p.ground.back().source, 1);
        ElevationService empty;
        QCOMPARE(empty.sample({56.9, 24.0}).status, SampleStatus::NoData);
        QCOMPARE(empty.sourceNames(), QStringList{QStringLiteral("none")});
    }

    // The same answers from tiles on disk as from the formula they were written from.
    void tilesAgreeWithFormula()
    {
        QTemporaryDir dir;
        QVERIFY(writeHgt(dir.filePath("N56E024.hgt"), 1201, [](int r, int c) { return 10 + c / 2 + r / 3; }));
        HgtTileSource tiles(dir.path());
        ElevationService service;
        service.setSources({&tiles});
        const TerrainProfile p = computeProfile(straight(30, HeightReference::AboveTerrain), service, 30);
        QCOMPARE(p.noData.size(), size_t(0));
        for (size_t i = 0; i < p.size(); ++i)
            QCOMPARE(p.ground[i].ground, tiles.sample(p.path.points[i].position).ground);
        QCOMPARE(p.waypoints[0].altitudeAgl, 30.0);
        QCOMPARE(p.waypoints[0].ground.ground, tiles.sample({56.9, 24.0}).ground);
    }

    void rulesInTheAnalyzer()
    {
        FormulaSource hill(QStringLiteral("hill"), [](const GeoPoint &p) { return std::abs(p.longitude - 24.005) < 0.001 ? 90.0 : 10.0; });
        ElevationService service;
        service.setSources({&hill});
        TerrainRule rule(&service);
        sortie::mission::RouteModel model;
        model.resetRoute(routeOf({{{56.9, 24.0}, 60}, {{56.9, 24.01}, 60}}, AltitudeType::Amsl));
        sortie::mission::RouteAnalyzer analyzer(&model);
        analyzer.setDelay(0);
        QSignalSpy recomputed(&analyzer, &sortie::mission::RouteAnalyzer::recomputed);
        analyzer.addRule(&rule);
        QVERIFY(recomputed.wait());
        const auto &issues = analyzer.validation().issues;
        QVERIFY(std::any_of(issues.begin(), issues.end(), [](const auto &i) { return i.rule == QLatin1String("terrain-clearance") && i.segment == 0; }));
        // The ground changes (another source): the rule runs again without an edit.
        FormulaSource low(QStringLiteral("low"), [](const GeoPoint &) { return 0.0; });
        service.setSources({&low});
        QVERIFY(recomputed.wait());
        const auto &after = analyzer.validation().issues;
        QVERIFY(std::none_of(after.begin(), after.end(), [](const auto &i) { return i.rule.startsWith(QLatin1String("terrain")); }));
    }

    // Changing the altitude type keeps the flown height through the ground; without ground, the number.
    void altitudeTypeKeepsHeight()
    {
        FormulaSource ground(QStringLiteral("g"), [](const GeoPoint &p) -> std::optional<double> {
            return p.longitude < 24.015 ? std::optional<double>(30.0) : std::nullopt;
        });
        ElevationService service;
        service.setSources({&ground});
        sortie::mission::RouteModel model;
        QUndoStack stack;
        model.resetRoute(routeOf({{{56.9, 24.0}, 50}, {{56.9, 24.02}, 50}}, AltitudeType::Agl));
        sortie::mission::RouteEditor editor(&model, &stack);
        editor.setGroundLookup([&service](const GeoPoint &p) { return service.groundAt(p); });
        QVERIFY(editor.setAltitudeType({0, 1}, AltitudeType::Amsl));
        auto wp = [&](int row) { return *sortie::mission::asWaypoint(model.segment(row)); };
        QCOMPARE(wp(0).altitude, 80.0);  // 50 m above 30 m ground
        QCOMPARE(wp(1).altitude, 50.0);  // no ground there: kept
        QCOMPARE(wp(1).altitudeType, AltitudeType::Amsl);
        QVERIFY(editor.setAltitudeType({0}, AltitudeType::Agl));
        QCOMPARE(wp(0).altitude, 50.0);
        QVERIFY(editor.setAltitudeType({0}, AltitudeType::Amsl, false));  // the operator keeps the number
        QCOMPARE(wp(0).altitude, 50.0);
        stack.undo();
        stack.undo();
        QCOMPARE(wp(0).altitude, 80.0);
    }

    // An altitude given as AMSL or AGL goes into each waypoint in its own type, through the ground;
    // where the ground is unknown the whole edit is refused and nothing changes.
    void altitudeSetInEitherFrame()
    {
        FormulaSource ground(QStringLiteral("g"), [](const GeoPoint &p) -> std::optional<double> {
            return p.longitude < 24.015 ? std::optional<double>(30.0) : std::nullopt;
        });
        ElevationService service;
        service.setSources({&ground});
        sortie::mission::RouteModel model;
        QUndoStack stack;
        Route route = routeOf({{{56.9, 24.0}, 50}, {{56.9, 24.01}, 100}, {{56.9, 24.02}, 50}}, AltitudeType::Agl);
        std::get<sortie::mission::Waypoint>(route.segments[1]).altitudeType = AltitudeType::Amsl;
        model.resetRoute(route);
        sortie::mission::RouteEditor editor(&model, &stack);
        editor.setGroundLookup([&service](const GeoPoint &p) { return service.groundAt(p); });
        auto wp = [&](int row) { return *sortie::mission::asWaypoint(model.segment(row)); };
        QVERIFY(editor.setAltitudeIn({0, 1}, 90, AltitudeType::Amsl));
        QCOMPARE(wp(0).altitude, 60.0);  // AGL: 90 m AMSL over 30 m ground
        QCOMPARE(wp(0).altitudeType, AltitudeType::Agl);
        QCOMPARE(wp(1).altitude, 90.0);  // AMSL as typed
        QCOMPARE(stack.count(), 1);      // one undo step
        QVERIFY(editor.setAltitudeIn({1}, 40, AltitudeType::Agl));
        QCOMPARE(wp(1).altitude, 70.0);
        QCOMPARE(wp(1).altitudeType, AltitudeType::Amsl);
        // Waypoint 3 has no ground under it: AMSL cannot become its AGL number, so nothing changes.
        QSignalSpy refused(&editor, &sortie::mission::RouteEditor::refused);
        QVERIFY(!editor.setAltitudeIn({1, 2}, 120, AltitudeType::Amsl));
        QCOMPARE(refused.count(), 1);
        QVERIFY(refused.at(0).at(0).toString().contains(QStringLiteral("Waypoint 3")));
        QCOMPARE(wp(1).altitude, 70.0);
        QCOMPARE(wp(2).altitude, 50.0);
        QVERIFY(editor.setAltitudeIn({2}, 45, AltitudeType::Agl));  // its own type needs no ground
        QCOMPARE(wp(2).altitude, 45.0);
    }

    // A pass over a hill: points are added where the ground bends, and every probe stays in tolerance.
    void followTerrainOverAHill()
    {
        auto height = [](const GeoPoint &p) { return 50.0 + 40.0 * std::exp(-std::pow((p.longitude - 24.01) / 0.003, 2)); };
        FormulaSource hill(QStringLiteral("hill"), height);
        ElevationService service;
        service.setSources({&hill});
        const std::vector<FollowVertex> pass{{{56.9, 24.0}, 30}, {{56.9, 24.02}, 30}};
        FollowOptions options;
        options.tolerance = 3;
        const FollowResult r = followTerrain(pass, options, service);
        QVERIFY(r.ok());
        QVERIFY(r.points.size() > 4);
        QCOMPARE(r.points.front().position, pass.front().position);
        QCOMPARE(r.points.back().position, pass.back().position);
        QCOMPARE(r.points.front().vertex, 0);
        QCOMPARE(r.points.back().vertex, 1);
        for (size_t i = 1; i + 1 < r.points.size(); ++i)
            QCOMPARE(r.points[i].vertex, -1);
        // Between consecutive points, the straight climb stays within 3 m of 30 m above the ground.
        const SampledPath probes = samplePath({pass.front().position, pass.back().position}, 2.0);
        size_t k = 0;
        for (const PathSamplePoint &pp : probes.points) {
            while (k + 1 < r.points.size() - 1 && r.points[k + 1].position.longitude < pp.position.longitude)
                ++k;
            const auto &a = r.points[k], &b = r.points[k + 1];
            const double f = (pp.position.longitude - a.position.longitude) / (b.position.longitude - a.position.longitude);
            const double alt = a.altitudeAmsl + f * (b.altitudeAmsl - a.altitudeAmsl);
            QVERIFY2(std::abs(alt - height(pp.position) - 30) < 3.5, qPrintable(QString::number(pp.distance)));
        }
        // Flat ground needs no extra point; no data refuses.
        FormulaSource flat(QStringLiteral("flat"), [](const GeoPoint &) { return 5.0; });
        service.setSources({&flat});
        QCOMPARE(followTerrain(pass, options, service).points.size(), size_t(2));
        // A pass that climbs from 30 m to 50 m above flat ground: an added point wants the height between.
        FormulaSource ridge(QStringLiteral("ridge"), [](const GeoPoint &p) { return p.longitude > 24.0099 && p.longitude < 24.0101 ? 80.0 : 5.0; });
        service.setSources({&ridge});
        const FollowResult climbing = followTerrain({{{56.9, 24.0}, 30}, {{56.9, 24.02}, 50}}, options, service);
        QVERIFY(climbing.ok());
        QCOMPARE(climbing.points.front().altitudeAmsl, 35.0);
        QCOMPARE(climbing.points.back().altitudeAmsl, 55.0);
        bool onRidge = false;
        for (const FollowPoint &p : climbing.points)
            if (p.ground == 80.0) {
                onRidge = true;
                QVERIFY(std::abs(p.altitudeAmsl - 80.0 - 40.0) < 0.5);  // halfway: 40 m wanted
            }
        QVERIFY(onRidge);
        NoElevationSource none;
        service.setSources({&none});
        const FollowResult refused = followTerrain(pass, options, service);
        QCOMPARE(refused.status, SampleStatus::NoData);
        QVERIFY(refused.message.contains(QStringLiteral("tried: none")));
    }

    // An area scan flown AGL follows the terrain (UgCS's area tools do, within `tolerance`): the
    // profile flies over the hill its passes cross, where straight passes at the same height would
    // fly into it. Flown AMSL, or as waypoints, it does not follow.
    void aglScanFollowsTheTerrain()
    {
        auto height = [](const GeoPoint &p) { return 20.0 + 80.0 * std::exp(-std::pow((p.longitude - 24.01) / 0.002, 2)); };
        FormulaSource hill(QStringLiteral("hill"), height);
        ElevationService service;
        service.setSources({&hill});

        sortie::mission::AreaScan scan;
        scan.polygon = {{56.900, 24.000}, {56.900, 24.020}, {56.902, 24.020}, {56.902, 24.000}};
        scan.parameters.altitude = 40;
        scan.parameters.altitudeType = AltitudeType::Agl;
        scan.parameters.directionDeg = 90;  // passes east-west, across the hill
        scan.parameters.sideDistanceMeters = 100;
        scan.parameters.turnaroundMeters = 0;
        Route route;
        route.segments.push_back(scan);
        QCOMPARE(terrainFollowTolerance(route.segments[0]), std::optional<double>(kDefaultFollowTolerance));

        const ProfileRoute profileRoute = profileRouteOf(route);
        QVERIFY(profileRoute.waypoints.size() >= 4);
        QCOMPARE(profileRoute.waypoints.front().followTolerance, kDefaultFollowTolerance);
        const TerrainProfile followed = computeProfile(profileRoute, service, 10);
        QVERIFY(followed.minClearance);
        QVERIFY2(followed.minClearance->clearance > 40 - kDefaultFollowTolerance - 0.5,
                 qPrintable(QString::number(followed.minClearance->clearance)));
        QVERIFY(followed.lowStretches.empty());

        // The same passes, straight: into the hill.
        ProfileRoute straight = profileRoute;
        for (ProfileWaypoint &w : straight.waypoints)
            w.followTolerance = -1;
        const TerrainProfile flown = computeProfile(straight, service, 10);
        QVERIFY(flown.minClearance && flown.minClearance->clearance < 0);
        QVERIFY(!flown.lowStretches.empty());

        // The scan's own tolerance, typed as the operator types it: a looser one lets the ground come closer.
        sortie::mission::Segment loose = route.segments[0];
        QVERIFY(sortie::mission::setParameterValue(loose, QStringLiteral("tolerance"), QStringLiteral("15")));
        QCOMPARE(terrainFollowTolerance(loose), std::optional<double>(15.0));
        Route looseRoute;
        looseRoute.segments.push_back(loose);
        const TerrainProfile looser = computeProfile(profileRouteOf(looseRoute), service, 10);
        QVERIFY(looser.minClearance && followed.minClearance);
        QVERIFY2(looser.minClearance->clearance > 40 - 15 - 0.5, qPrintable(QString::number(looser.minClearance->clearance)));
        QVERIFY2(looser.minClearance->clearance < followed.minClearance->clearance - 1,
                 qPrintable(QStringLiteral("%1 vs %2").arg(looser.minClearance->clearance).arg(followed.minClearance->clearance)));
        // Emptied: the server's own again.
        QVERIFY(sortie::mission::setParameterValue(loose, QStringLiteral("tolerance"), QString()));
        QCOMPARE(terrainFollowTolerance(loose), std::optional<double>(kDefaultFollowTolerance));
        QVERIFY(!sortie::mission::parameterValue(loose, QStringLiteral("tolerance")).isValid());

        // AMSL scans and waypoints fly straight.
        std::get<sortie::mission::AreaScan>(route.segments[0]).parameters.altitudeType = AltitudeType::Amsl;
        QCOMPARE(terrainFollowTolerance(route.segments[0]), std::nullopt);
        QCOMPARE(profileRouteOf(route).waypoints.front().followTolerance, -1.0);
        QCOMPARE(terrainFollowTolerance(sortie::mission::Segment(sortie::mission::Waypoint{})), std::nullopt);
    }
};

QTEST_GUILESS_MAIN(TstTerrainProfile)
#include "tst_terrainprofile.moc"
