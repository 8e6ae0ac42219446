// The segment definitions, cameras, photogrammetry arithmetic and planners of core/mission/segments:
// the catalog against the facts file's names and units, the formulas against values worked by hand,
// the TraverseAlgorithm mapping both ways, and each planner's geometry.
#include "AlgorithmCatalog.h"
#include "AlgorithmProto.h"
#include "CameraProto.h"
#include "Domain.pb.h"
#include "Geodesy.h"
#include "LocalTangentPlane.h"
#include "Photogrammetry.h"
#include "SegmentPlanner.h"

#include <QtTest>

#include <cmath>

using namespace sortie::mission;
namespace pb = com::ugcs::ucs::proto;
namespace ph = sortie::mission::photogrammetry;

namespace {

const GeoPoint kOrigin{56.9700, 24.1000};

std::vector<GeoPoint> rectangle(double width, double height, const GeoPoint &centre = kOrigin)
{
    const LocalTangentPlane plane(centre);
    return {plane.unproject({-width / 2, -height / 2}), plane.unproject({width / 2, -height / 2}),
            plane.unproject({width / 2, height / 2}), plane.unproject({-width / 2, height / 2})};
}

Camera gopro() { return *builtInCamera(QStringLiteral("GoPro Hero3 Black Edition")); }
Camera p4p() { return *builtInCamera(QStringLiteral("DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)")); }

const AlgorithmDefinition &algorithm(AlgorithmKind kind) { return *AlgorithmCatalog::builtIn().byKind(kind); }

SegmentFigure polygonFigure(std::vector<GeoPoint> points)
{
    SegmentFigure f;
    f.type = FigureType::Polygon;
    points.push_back(points.front());  // closed, as UgCS sends it
    f.points = std::move(points);
    f.pointAltitudes.assign(f.points.size(), 0.0);
    return f;
}

// Distance from p to segment ab in the plane.
double toSegment(const PlanePoint &p, const PlanePoint &a, const PlanePoint &b)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

} // namespace

class TestSegmentPlanner : public QObject
{
    Q_OBJECT

private slots:
    // ---- catalog against shared/ugcs-route-segments.md ----
    void catalogHasEveryToolWithTheFactsClassNamesAndFigures()
    {
        const QString pkg = QStringLiteral("com.ugcs.ucs.service.routing.impl.");
        const struct { const char *cls; FigureType figure; } known[] = {
            {"WaypointAlgorithm", FigureType::Point}, {"TakeOffAlgorithm", FigureType::TakeoffPoint},
            {"LandingAlgorithm", FigureType::LandingPoint}, {"CircleAlgorithm", FigureType::Circle},
            {"PerimeterAlgorithm", FigureType::Polygon}, {"AreaScanAlgorithm", FigureType::Polygon},
            {"PhotogrammetryAlgorithm", FigureType::Polygon}, {"CorridorMappingAlgorithm", FigureType::Polyline},
            {"ExpandingSquareAlgorithm", FigureType::Point}, {"CreepingLineAlgorithm", FigureType::Polygon},
            {"FacadeScannerAlgorithm", FigureType::Polyline},
        };
        const AlgorithmCatalog &catalog = AlgorithmCatalog::builtIn();
        QCOMPARE(catalog.algorithms().size(), std::size(known));
        for (const auto &k : known) {
            const AlgorithmDefinition *a = catalog.byClassName(pkg + QLatin1String(k.cls));
            QVERIFY2(a, k.cls);
            QCOMPARE(a->figure, k.figure);
            QCOMPARE(algorithmKindOf(QString::fromLatin1(k.cls)), a->kind);
            QCOMPARE(algorithmClassName(a->kind), pkg + QLatin1String(k.cls));
        }
        QCOMPARE(algorithmKindOf(u"com.example.Other"), AlgorithmKind::Unknown);
    }

    void parametersCarryTheFactsNamesTypesUnitsAndDefaults()
    {
        struct Row { AlgorithmKind kind; const char *name; ParameterType type; const char *unit; const char *def; };
        const Row rows[] = {
            {AlgorithmKind::Photogrammetry, "groundSampleDistance", ParameterType::Double, "cm/px", "2"},
            {AlgorithmKind::Photogrammetry, "overlapForward", ParameterType::Double, "%", "60"},
            {AlgorithmKind::Photogrammetry, "overlapSide", ParameterType::Double, "%", "30"},
            {AlgorithmKind::Photogrammetry, "camTopFacingForward", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::Photogrammetry, "camera", ParameterType::Selection, "", ""},
            {AlgorithmKind::Photogrammetry, "directionAngle", ParameterType::Double, "°", "0"},
            {AlgorithmKind::Photogrammetry, "generateAdditionalWaypoints", ParameterType::Boolean, "", "false"},
            {AlgorithmKind::AreaScan, "sideDistance", ParameterType::Double, "m", "20"},
            {AlgorithmKind::AreaScan, "height", ParameterType::Double, "m", "50"},
            {AlgorithmKind::AreaScan, "overshoot", ParameterType::Double, "m", ""},
            {AlgorithmKind::AreaScan, "overshootSpeed", ParameterType::Double, "m/s", ""},
            {AlgorithmKind::AreaScan, "tolerance", ParameterType::Double, "m", "3"},
            {AlgorithmKind::AreaScan, "actionExecution", ParameterType::Selection, "", "ACTIONS_EVERY_POINT"},
            {AlgorithmKind::AreaScan, "areaScanAllowPartialCalculation", ParameterType::Boolean, "", "false"},
            {AlgorithmKind::AreaScan, "doubleGrid", ParameterType::Boolean, "", "false"},
            {AlgorithmKind::Circle, "loops", ParameterType::Integer, "", "1"},
            {AlgorithmKind::Circle, "flightClockwise", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::Circle, "basePointsQnt", ParameterType::Integer, "", ""},
            {AlgorithmKind::Circle, "followTerrain", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::Perimeter, "heightAgl", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::Perimeter, "loops", ParameterType::Integer, "", "1"},
            {AlgorithmKind::Waypoint, "wpTurnType", ParameterType::Selection, "", "STOP_AND_TURN"},
            {AlgorithmKind::Waypoint, "speed", ParameterType::Double, "m/s", ""},
            {AlgorithmKind::TakeOff, "avoidTerrain", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::Landing, "avoidObstacles", ParameterType::Boolean, "", "true"},
            {AlgorithmKind::ExpandingSquare, "searchRadius", ParameterType::Double, "m", "350"},
            {AlgorithmKind::ExpandingSquare, "overlapSide", ParameterType::Double, "%", "10"},
            {AlgorithmKind::CreepingLine, "overlapSide", ParameterType::Double, "%", "10"},
            {AlgorithmKind::Corridor, "width", ParameterType::Double, "m", "30"},
        };
        for (const Row &r : rows) {
            const ParameterDefinition *p = algorithm(r.kind).parameter(QString::fromLatin1(r.name));
            QVERIFY2(p, r.name);
            QCOMPARE(p->type, r.type);
            QCOMPARE(p->unit(), QString::fromUtf8(r.unit));
            QCOMPARE(p->defaultValue, QString::fromLatin1(r.def));
        }
        // Ranges the facts give: overlaps 1–90 %, the creeping line's side overlap at most 50 %.
        QCOMPARE(*algorithm(AlgorithmKind::Photogrammetry).parameter(u"overlapForward")->minimum, 1.0);
        QCOMPARE(*algorithm(AlgorithmKind::Photogrammetry).parameter(u"overlapSide")->maximum, 90.0);
        QCOMPARE(*algorithm(AlgorithmKind::CreepingLine).parameter(u"overlapSide")->maximum, 50.0);
        // Photogrammetry has no height (it follows from the GSD); the names the old code used are gone.
        QVERIFY(!algorithm(AlgorithmKind::Photogrammetry).parameter(u"height"));
        QVERIFY(!algorithm(AlgorithmKind::AreaScan).parameter(u"sideOverlap"));
        QVERIFY(!algorithm(AlgorithmKind::AreaScan).parameter(u"forwardOverlap"));
        const auto &exec = algorithm(AlgorithmKind::AreaScan).parameter(u"actionExecution")->choices;
        QCOMPARE(exec.size(), size_t(3));
        QCOMPARE(exec[2].value, QStringLiteral("ACTIONS_ON_FORWARD_PASSES"));
        QCOMPARE(algorithm(AlgorithmKind::Circle).parameter(u"actionExecution")->choices.size(), size_t(2));
    }

    void valuesAreReadTheWayUgcsPeersWriteThem()
    {
        const AlgorithmDefinition &photo = algorithm(AlgorithmKind::Photogrammetry);
        const ParameterValues values{{QStringLiteral("camTopFacingForward"), QStringLiteral("False")},
                                     {QStringLiteral("overlapSide"), QStringLiteral(" 45.0 ")},
                                     {QStringLiteral("overshoot"), QString()},
                                     {QStringLiteral("mystery"), QStringLiteral("kept")}};
        const ParameterReader r(photo, values);
        QCOMPARE(r.boolean(u"camTopFacingForward"), std::optional<bool>(false));
        QCOMPARE(r.number(u"overlapSide"), std::optional<double>(45.0));
        QCOMPARE(r.number(u"overlapForward"), std::optional<double>(60.0));  // the default
        QVERIFY(!r.number(u"overshoot"));                                    // "" = not set, no default
        QCOMPARE(r.text(u"mystery"), std::optional<QString>(QStringLiteral("kept")));
        QVERIFY(r.problems().empty());
        QCOMPARE(parameterNumberText(2.5), QStringLiteral("2.5"));
        QCOMPARE(parameterNumberText(0.1), QStringLiteral("0.1"));
        QCOMPARE(parameterNumberText(60), QStringLiteral("60"));
    }

    void outOfRangeValuesAreNamed()
    {
        const AlgorithmDefinition &photo = algorithm(AlgorithmKind::Photogrammetry);
        const ParameterValues values{{QStringLiteral("overlapForward"), QStringLiteral("95")},
                                     {QStringLiteral("camTopFacingForward"), QStringLiteral("maybe")},
                                     {QStringLiteral("wpTurnType"), QStringLiteral("LOOP")}};
        const auto problems = ParameterReader(photo, values).problems();
        QCOMPARE(problems.size(), size_t(3));
        QCOMPARE(problems[0], QStringLiteral("wpTurnType: 'LOOP' is not one of its choices"));
        QCOMPARE(problems[1], QStringLiteral("overlapForward: 95 is above the maximum of 90 %"));
        QCOMPARE(problems[2], QStringLiteral("camTopFacingForward: 'maybe' is neither true nor false"));
        QCOMPARE(algorithm(AlgorithmKind::Circle).parameter(u"loops")->check(QStringLiteral("1.5")),
                 QStringLiteral("loops: '1.5' is not a whole number"));
    }

    // ---- TraverseAlgorithm mapping ----
    void serverDescriptionsRoundTripAndAreCompletedFromTheCatalog()
    {
        for (const AlgorithmDefinition &a : AlgorithmCatalog::builtIn().algorithms()) {
            const pb::TraverseAlgorithm wire = algorithmToProto(a);
            QCOMPARE(QString::fromStdString(wire.implementationclass()), a.className);
            QCOMPARE(wire.parameterdefinitions_size(), int(a.parameters.size()));
            AlgorithmDefinition back = algorithmFromProto(wire, &AlgorithmCatalog::builtIn());
            // The wire description carries the range in words; everything else comes back as it was.
            for (size_t i = 0; i < back.parameters.size(); ++i)
                back.parameters[i].description = a.parameters[i].description;
            QCOMPARE(back, a);
        }
        const pb::TraverseAlgorithm wire = algorithmToProto(algorithm(AlgorithmKind::Photogrammetry));
        const auto &gsd = wire.parameterdefinitions(3);
        QCOMPARE(gsd.name(), std::string("groundSampleDistance"));
        QCOMPARE(gsd.physicalsemantic(), pb::PS_GSD);
        QCOMPARE(gsd.type(), pb::PT_DOUBLE);
        QCOMPARE(QString::fromStdString(gsd.description()), QStringLiteral("Ground sample distance (0.05–1000 cm/px)"));
    }

    void aNewServerAlgorithmGetsADefinitionFromItsDescriptionAlone()
    {
        pb::TraverseAlgorithm a;
        a.set_id(77);
        a.set_name("Spiral");
        a.set_implementationclass("com.example.SpiralAlgorithm");
        a.set_figuretype(pb::FT_CIRCLE);
        auto *d = a.add_parameterdefinitions();
        d->set_name("turns");
        d->set_type(pb::PT_INTEGER);
        d->set_defaultvalue("3");
        d->set_category(pb::PG_ADVANCED);
        d->set_validationregex("[0-9]+");
        auto *s = a.add_parameterdefinitions();
        s->set_name("speed");
        s->set_type(pb::PT_DOUBLE);
        s->set_physicalsemantic(pb::PS_SPEED);
        const AlgorithmCatalog catalog = catalogFromProto({a});
        const AlgorithmDefinition *spiral = catalog.byClassName(u"com.example.SpiralAlgorithm");
        QVERIFY(spiral);
        QCOMPARE(spiral->kind, AlgorithmKind::Unknown);
        QCOMPARE(spiral->serverId, 77);
        QCOMPARE(spiral->figure, FigureType::Circle);
        QCOMPARE(spiral->parameters[0].type, ParameterType::Integer);
        QVERIFY(spiral->parameters[0].advanced);
        QCOMPARE(spiral->parameters[0].check(QStringLiteral("x2")), QStringLiteral("turns: 'x2' is not a number"));
        QCOMPARE(spiral->parameters[1].unit(), QStringLiteral("m/s"));
        // The built-in tools the server did not list are still there.
        QCOMPARE(catalog.algorithms().size(), AlgorithmCatalog::builtIn().algorithms().size() + 1);
    }

    // ---- cameras and arithmetic, against values worked by hand ----
    void payloadProfilesAreInMetres()
    {
        pb::PayloadProfile p;  // UgCS's demo GoPro Hero3 Black (facts §4)
        p.set_name("GoPro Hero3 Black Edition");
        p.set_payloadtype(pb::PT_CAMERA);
        for (auto [type, value] : {std::pair{pb::PPT_TRUE_FOCAL_LENGTH, 0.0028}, {pb::PPT_SENSOR_WIDTH, 0.00617},
                                   {pb::PPT_SENSOR_HEIGHT, 0.00455}, {pb::PPT_SENSOR_HORIZONTAL_PIXELS, 4000.0},
                                   {pb::PPT_SENSOR_VERTICAL_PIXELS, 3000.0}, {pb::PPT_MIN_TRIGGERING_INTERVAL, 1.0}}) {
            auto *param = p.add_parameters();
            param->set_type(type);
            param->set_value(value);
        }
        const auto c = cameraFromPayload(p);
        QVERIFY(c);
        QVERIFY(std::abs(c->focalLengthMm - 2.8) < 1e-9);
        QVERIFY(std::abs(c->sensorWidthMm - 6.17) < 1e-9);
        QCOMPARE(c->imageWidthPx, 4000);
        QCOMPARE(c->minTriggerIntervalS, 1.0);
        const auto back = cameraFromPayload(payloadFromCamera(*c));
        QVERIFY(back && std::abs(back->sensorHeightMm - 4.55) < 1e-9);
        p.mutable_parameters()->RemoveLast();
        p.mutable_parameters()->RemoveLast();  // no vertical resolution: not a complete camera
        QVERIFY(!cameraFromPayload(p));
    }

    void gsdHeightAndFootprint()
    {
        // GoPro: H = 0.02 m × 2.8 mm × 4000 px / 6.17 mm = 36.3047 m; footprint 80 m × 58.995 m.
        QVERIFY(std::abs(ph::heightForGsd(gopro(), 2.0) - 36.304700162) < 1e-6);
        QVERIFY(std::abs(ph::gsdAtHeight(gopro(), 100) - 5.508928571) < 1e-6);
        const auto f = ph::footprint(gopro(), ph::heightForGsd(gopro(), 2.0));
        QVERIFY(std::abs(f.across - 80.0) < 1e-9);
        QVERIFY(std::abs(f.along - 58.995137763) < 1e-6);
        const auto turned = ph::footprint(gopro(), ph::heightForGsd(gopro(), 2.0), false);
        QVERIFY(std::abs(turned.across - 58.995137763) < 1e-6);
        QVERIFY(std::abs(turned.along - 80.0) < 1e-9);
        // Phantom 4 Pro at 100 m: 150 m × 100 m, GSD 13.2 / (8.8 × 5472) × 100 m = 2.7412 cm/px.
        QVERIFY(std::abs(ph::gsdAtHeight(p4p(), 100) - 2.741228070) < 1e-6);
        QVERIFY(std::abs(ph::footprint(p4p(), 100).across - 150.0) < 1e-9);
        QVERIFY(std::abs(ph::footprint(p4p(), 100).along - 100.0) < 1e-9);
    }

    void overlapsSpacingTriggersAndPhotos()
    {
        QVERIFY(std::abs(ph::passSpacing(150, 65) - 52.5) < 1e-9);
        QVERIFY(std::abs(ph::triggerDistance(100, 75) - 25.0) < 1e-9);
        QVERIFY(std::abs(ph::overlapFor(52.5, 150) - 65.0) < 1e-9);
        QCOMPARE(ph::photosOnPass(100, 25), 5);
        QCOMPARE(ph::photosOnPass(99.9, 25), 4);
        QCOMPARE(ph::estimatedPhotos(1e6, 52.5, 25), 762);  // 1e6 / 1312.5 = 761.9
        QCOMPARE(ph::triggerInterval(25, 10, p4p()), 2.5);
        const Camera m3e = *builtInCamera(QStringLiteral("DJI Mavic 3 Enterprise (wide)"));
        QCOMPARE(ph::triggerInterval(5, 10, m3e), 0.7);  // 0.5 s asked, the camera needs 0.7 s
        QVERIFY(std::abs(ph::maxSpeedForTrigger(5, m3e) - 7.142857143) < 1e-6);
        const auto figures = ph::figuresForGsd(gopro(), 2.0, 60, 30, true, 5);
        QVERIFY(std::abs(figures.passSpacing - 56.0) < 1e-9);
        QVERIFY(std::abs(figures.triggerDistance - 23.598055105) < 1e-6);
        QVERIFY(std::abs(figures.triggerIntervalS - 23.598055105 / 5) < 1e-6);
        QCOMPARE(figures.gsdCm, 2.0);
        QVERIFY(std::abs(ph::figuresForHeight(p4p(), 100, 75, 65, true, 10).passSpacing - 52.5) < 1e-9);
    }

    void everyBuiltInCameraIsComplete()
    {
        QVERIFY(builtInCameras().size() >= 8);
        for (const Camera &c : builtInCameras()) {
            QVERIFY2(c.isValid(), qPrintable(c.name));
            // Published sensors are between a 1/2.3" and a full frame, pixels roughly square.
            QVERIFY(c.sensorWidthMm >= 4.5 && c.sensorWidthMm <= 36.0);
            const double pitchW = c.sensorWidthMm / c.imageWidthPx, pitchH = c.sensorHeightMm / c.imageHeightPx;
            QVERIFY2(std::abs(pitchW / pitchH - 1) < 0.03, qPrintable(c.name));
        }
    }

    // ---- planners ----
    void orbitIsOnTheRadiusInTheChosenSense()
    {
        SegmentFigure f;
        f.type = FigureType::Circle;
        f.points = {kOrigin};
        f.pointAltitudes = {40};
        f.parameters = {120.0};
        PlanContext ctx;
        ctx.previousPosition = GeoPoint{kOrigin.latitude, kOrigin.longitude + 0.01};  // due east
        const ParameterValues values{{QStringLiteral("loops"), QStringLiteral("2")},
                                     {QStringLiteral("flightClockwise"), QStringLiteral("false")}};
        const auto out = planSegment(algorithm(AlgorithmKind::Circle), f, values, ctx);
        QVERIFY(out.ok());
        const int perLap = circlePointsPerLap(120);
        QCOMPARE(int(out.plan->points.size()), 2 * perLap + 1);
        double previousBearing = 90;
        for (size_t i = 0; i < out.plan->points.size(); ++i) {
            const auto inv = geodesicInverse(kOrigin, out.plan->points[i].position);
            QVERIFY(std::abs(inv->distance - 120.0) < 1e-3);
            QCOMPARE(out.plan->points[i].height, 40.0);
            if (i == 0)
                QVERIFY(std::abs(inv->azimuth1Deg - 90) < 0.1);  // starts on the side the vehicle comes from
            else  // counter-clockwise: the bearing decreases by one step each point
                QVERIFY(std::abs(std::remainder(previousBearing - inv->azimuth1Deg, 360.0) - 360.0 / perLap) < 0.01);
            previousBearing = inv->azimuth1Deg;
        }
        // basePointsQnt fixes the points per lap; a missing radius is refused.
        const auto fixed = planSegment(algorithm(AlgorithmKind::Circle), f, {{QStringLiteral("basePointsQnt"), QStringLiteral("6")}}, {});
        QCOMPARE(fixed.plan->points.size(), size_t(7));
        f.parameters.clear();
        QVERIFY(!planSegment(algorithm(AlgorithmKind::Circle), f, {}, {}).ok());
        // sagitta ≤ 1 m: 120 m radius needs ceil(π / acos(1 − 1/120)) = 25 points
        QCOMPARE(circlePointsPerLap(120), 25);
        QCOMPARE(circlePointsPerLap(2), 8);
    }

    void perimeterFollowsTheEdgesForEachLoop()
    {
        const auto square = rectangle(200, 100);
        const auto out = planSegment(algorithm(AlgorithmKind::Perimeter), polygonFigure(square),
                                     {{QStringLiteral("loops"), QStringLiteral("2")}, {QStringLiteral("height"), QStringLiteral("35")}}, {});
        QVERIFY(out.ok());
        QCOMPARE(out.plan->points.size(), size_t(9));  // 4 corners × 2 laps, back to the start
        for (size_t i = 0; i < 8; ++i)
            QCOMPARE(out.plan->points[i].position, square[i % 4]);
        QCOMPARE(out.plan->points.back().position, square[0]);
        QCOMPARE(out.plan->points[3].height, 35.0);
        QCOMPARE(out.plan->points[3].frame, HeightFrame::Agl);
        QVERIFY(std::abs(out.plan->length - 2 * 600.0) < 0.5);
    }

    void areaScanPassesAreSpacedAlongTheDirectionAndOvershoot()
    {
        const auto field = rectangle(400, 300);
        const ParameterValues values{{QStringLiteral("sideDistance"), QStringLiteral("25")},
                                     {QStringLiteral("directionAngle"), QStringLiteral("0")},
                                     {QStringLiteral("overshoot"), QStringLiteral("15")},
                                     {QStringLiteral("height"), QStringLiteral("60")},
                                     {QStringLiteral("altitudeType"), QStringLiteral("AGL")}};
        const auto out = planSegment(algorithm(AlgorithmKind::AreaScan), polygonFigure(field), values, {});
        QVERIFY(out.ok());
        const SegmentPlan &plan = *out.plan;
        QCOMPARE(plan.passes, 16);  // ceil(400 / 25)
        QCOMPARE(plan.points.size(), size_t(16 * 4));
        const LocalTangentPlane plane(kOrigin);
        for (int k = 0; k < plan.passes; ++k) {
            const PlanePoint o0 = plane.project(plan.points[4 * k].position), s = plane.project(plan.points[4 * k + 1].position),
                             e = plane.project(plan.points[4 * k + 2].position), o1 = plane.project(plan.points[4 * k + 3].position);
            QVERIFY(plan.points[4 * k].overshoot && plan.points[4 * k + 3].overshoot);
            QVERIFY(plan.points[4 * k + 1].onPass && plan.points[4 * k + 2].onPass);
            QVERIFY(std::abs(s.x - e.x) < 0.01);                      // north–south at direction 0
            QVERIFY(std::abs(std::abs(s.y - e.y) - 300) < 0.05);      // across the whole field
            QVERIFY(std::abs(std::hypot(o0.x - s.x, o0.y - s.y) - 15) < 0.01);
            QVERIFY(std::abs(std::hypot(o1.x - e.x, o1.y - e.y) - 15) < 0.01);
            if (k > 0) {
                const PlanePoint prev = plane.project(plan.points[4 * (k - 1) + 1].position);
                QVERIFY(std::abs(std::abs(s.x - prev.x) - 25) < 0.01);
            }
            QCOMPARE(plan.points[4 * k + 1].frame, HeightFrame::Agl);
        }
        // A double grid adds the crossing sweep.
        ParameterValues doubled = values;
        doubled.push_back({QStringLiteral("doubleGrid"), QStringLiteral("True")});
        QCOMPARE(planSegment(algorithm(AlgorithmKind::AreaScan), polygonFigure(field), doubled, {}).plan->passes, 16 + 12);
    }

    void photogrammetryFliesAtTheGsdHeightWithTriggersAtTheTriggerDistance()
    {
        PlanContext ctx;
        ctx.cameras = {{41, gopro()}};
        const ParameterValues values{{QStringLiteral("camera"), QStringLiteral("41")},
                                     {QStringLiteral("groundSampleDistance"), QStringLiteral("2")},
                                     {QStringLiteral("directionAngle"), QStringLiteral("90")},
                                     {QStringLiteral("actionExecution"), QStringLiteral("ACTIONS_ON_FORWARD_PASSES")},
                                     {QStringLiteral("noActionsAtLastPoint"), QStringLiteral("false")},
                                     {QStringLiteral("overshoot"), QStringLiteral("10")}};
        const auto out = planSegment(algorithm(AlgorithmKind::Photogrammetry), polygonFigure(rectangle(500, 560)), values, ctx);
        QVERIFY(out.ok());
        const SegmentPlan &plan = *out.plan;
        QVERIFY(std::abs(plan.height - 36.3047) < 1e-3);
        QVERIFY(std::abs(plan.passSpacing - 56.0) < 1e-9);
        QVERIFY(std::abs(plan.triggerDistance - 23.598055) < 1e-5);
        QCOMPARE(plan.passes, 10);  // 560 / 56
        QCOMPARE(plan.photos, 10 * (int(500 / 23.598055) + 1));
        QCOMPARE(plan.points.front().camera.front().kind, CameraCommand::Kind::FaceDown);
        int starts = 0, stops = 0;
        for (const PlannedPoint &p : plan.points) {
            for (const CameraCommand &c : p.camera) {
                if (c.kind == CameraCommand::Kind::StartSeries) {
                    ++starts;
                    QVERIFY(std::abs(c.value - plan.triggerDistance) < 1e-9);
                }
                stops += c.kind == CameraCommand::Kind::StopSeries;
            }
            QCOMPARE(p.userActions, p.onPass);
        }
        QCOMPARE(starts, 10);
        QCOMPARE(stops, 10);
        // The camera named by name works too; an unknown one and a missing GSD are refused by name.
        QVERIFY(planSegment(algorithm(AlgorithmKind::Photogrammetry), polygonFigure(rectangle(500, 560)),
                            {{QStringLiteral("camera"), gopro().name}}, ctx).ok());
        const auto unknown = planSegment(algorithm(AlgorithmKind::Photogrammetry), polygonFigure(rectangle(500, 560)),
                                         {{QStringLiteral("camera"), QStringLiteral("Box Brownie")}}, ctx);
        QCOMPARE(unknown.errors.front(), QStringLiteral("camera: 'Box Brownie' is not a camera of the vehicle profile"));
        const auto noCamera = planSegment(algorithm(AlgorithmKind::Photogrammetry), polygonFigure(rectangle(500, 560)), {}, {});
        QVERIFY(noCamera.errors.front().startsWith(QStringLiteral("camera:")));
    }

    void extraWaypointsSitAtEveryPhoto()
    {
        PlanContext ctx;
        ctx.cameras = {{1, p4p()}};
        const ParameterValues values{{QStringLiteral("groundSampleDistance"), QStringLiteral("2.741228070175")},  // 100 m
                                     {QStringLiteral("overlapForward"), QStringLiteral("75")},
                                     {QStringLiteral("overlapSide"), QStringLiteral("65")},
                                     {QStringLiteral("generateAdditionalWaypoints"), QStringLiteral("true")}};
        const auto out = planSegment(algorithm(AlgorithmKind::Photogrammetry), polygonFigure(rectangle(50, 210)), values, ctx);
        QVERIFY(out.ok());
        QCOMPARE(out.plan->passes, 1);
        // One pass of 210 m with a photo every 25 m: the ends plus 8 points between.
        QCOMPARE(out.plan->points.size(), size_t(10));
        for (size_t i = 1; i + 1 < out.plan->points.size(); ++i)
            QVERIFY(std::abs(geodesicDistance(out.plan->points[i - 1].position, out.plan->points[i].position) - 25) < 0.01);
    }

    void concaveAreasAreCoveredWithoutLeavingThem()
    {
        const LocalTangentPlane plane(kOrigin);
        const std::vector<PlanePoint> u{{-150, -100}, {150, -100}, {150, 100}, {50, 100}, {50, -20}, {-50, -20}, {-50, 100}, {-150, 100}};
        std::vector<GeoPoint> poly;
        for (const auto &p : u)
            poly.push_back(plane.unproject(p));
        const auto out = planSegment(algorithm(AlgorithmKind::AreaScan), polygonFigure(poly),
                                     {{QStringLiteral("sideDistance"), QStringLiteral("20")}, {QStringLiteral("directionAngle"), QStringLiteral("90")}}, {});
        QVERIFY(out.ok());
        // Every pass point inside (or on) the U; the notch's inside is never crossed.
        for (const PlannedPoint &p : out.plan->points) {
            const PlanePoint q = plane.project(p.position);
            QVERIFY(!(q.x > -49.9 && q.x < 49.9 && q.y > -19.9));
        }
        for (size_t i = 0; i + 1 < out.plan->points.size(); ++i) {
            if (!out.plan->points[i].onPass || !out.plan->points[i + 1].onPass)
                continue;
            const PlanePoint a = plane.project(out.plan->points[i].position), b = plane.project(out.plan->points[i + 1].position);
            if (std::abs(a.y - b.y) > 0.01)
                continue;  // a connection between cells
            QVERIFY(!(a.y > -19.9 && std::min(a.x, b.x) < -50.1 && std::max(a.x, b.x) > 50.1));
        }
    }

    void corridorPassesStayWithinTheWidth()
    {
        const LocalTangentPlane plane(kOrigin);
        const std::vector<PlanePoint> centre{{-300, 0}, {0, 50}, {300, -40}};
        SegmentFigure f;
        f.type = FigureType::Polyline;
        for (const auto &p : centre)
            f.points.push_back(plane.unproject(p));
        PlanContext ctx;
        ctx.cameras = {{1, gopro()}};
        const auto out = planSegment(algorithm(AlgorithmKind::Corridor), f,
                                     {{QStringLiteral("width"), QStringLiteral("150")}, {QStringLiteral("groundSampleDistance"), QStringLiteral("2")}}, ctx);
        QVERIFY(out.ok());
        QCOMPARE(out.plan->passes, 3);  // ceil(150 / 56)
        for (const PlannedPoint &p : out.plan->points) {
            const PlanePoint q = plane.project(p.position);
            const double d = std::min(toSegment(q, centre[0], centre[1]), toSegment(q, centre[1], centre[2]));
            QVERIFY2(d <= 75.0, qPrintable(QString::number(d)));
        }
        // The middle pass is the centre line itself.
        const PlanePoint mid = plane.project(out.plan->points[3].position);
        QVERIFY(std::abs(mid.x - 300) < 0.01 || std::abs(mid.x + 300) < 0.01);
    }

    void takeoffLandingAndSarTools()
    {
        SegmentFigure point;
        point.points = {kOrigin};
        point.pointAltitudes = {25};
        auto takeoff = planSegment(algorithm(AlgorithmKind::TakeOff), point, {}, {});
        QCOMPARE(takeoff.plan->points.front().kind, PlannedPoint::Kind::Takeoff);
        QCOMPARE(takeoff.plan->points.front().height, 25.0);
        auto landing = planSegment(algorithm(AlgorithmKind::Landing), point, {}, {});
        QCOMPARE(landing.plan->points.front().kind, PlannedPoint::Kind::Landing);
        QCOMPARE(landing.plan->points.front().height, 0.0);

        PlanContext ctx;
        ctx.cameras = {{1, gopro()}};
        // GoPro at 50 m: 110.18 m across, 10 % overlap -> 99.16 m between legs, to 350 m.
        auto square = planSegment(algorithm(AlgorithmKind::ExpandingSquare), point, {}, ctx);
        QVERIFY(square.ok());
        const double spacing = 50 * 6.17 / 2.8 * 0.9;
        QVERIFY(std::abs(square.plan->passSpacing - spacing) < 1e-9);
        QCOMPARE(square.plan->passes, 14);  // legs of 1..7 spacings, two each, while ≤ 700 m
        QVERIFY(std::abs(geodesicDistance(square.plan->points[0].position, square.plan->points[1].position) - spacing) < 0.01);

        auto creeping = planSegment(algorithm(AlgorithmKind::CreepingLine), polygonFigure(rectangle(1000, 1000)), {}, ctx);
        QVERIFY(creeping.ok());
        QCOMPARE(creeping.plan->passes, int(std::ceil(1000 / spacing)));

        SegmentFigure wall;
        wall.type = FigureType::Polyline;
        wall.points = {rectangle(100, 2)[0], rectangle(100, 2)[1]};
        auto facade = planSegment(algorithm(AlgorithmKind::FacadeScanner), wall,
                                  {{QStringLiteral("minHeight"), QStringLiteral("10")}, {QStringLiteral("maxHeight"), QStringLiteral("40")}}, ctx);
        QVERIFY(facade.ok());
        QCOMPARE(facade.plan->points.front().camera.front().kind, CameraCommand::Kind::FaceHeading);
        QVERIFY(std::abs(facade.plan->points.front().camera.front().value - 0.0) < 0.5);  // A→B runs east: the wall is north
        for (const PlannedPoint &p : facade.plan->points)
            QVERIFY(p.height >= 10 && p.height <= 40);
        auto inverted = planSegment(algorithm(AlgorithmKind::FacadeScanner), wall,
                                    {{QStringLiteral("minHeight"), QStringLiteral("40")}, {QStringLiteral("maxHeight"), QStringLiteral("10")}}, ctx);
        QVERIFY(inverted.errors.front().startsWith(QStringLiteral("maxHeight:")));
    }
};

QTEST_APPLESS_MAIN(TestSegmentPlanner)
#include "tst_segmentplanner.moc"
