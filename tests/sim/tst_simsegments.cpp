// Every UgCS segment type through a real HCI client and the real simulated server over loopback: the
// server lists its traverse algorithms with their parameter definitions and its profiles with their
// camera payloads; ProcessRoute's waypoints are checked by geometry (orbit on the radius, perimeter on
// the edges, passes covering the polygon at the spacing the overlap implies, camera triggers at the
// trigger distance), parameters out of range name their segment, and the vehicle takes the processed
// route as its mission.
#include "../hci/HciTestSupport.h"

#include "AlgorithmProto.h"
#include "CameraProto.h"
#include "Geodesy.h"
#include "HciClient.h"
#include "LocalTangentPlane.h"
#include "Messages.pb.h"
#include "Photogrammetry.h"
#include "SegmentPlanner.h"
#include "SimVehicle.h"

#include <QtTest>

#include <cmath>

using namespace sortie;
using hci::HciClient;
using hci::HciError;
using hci::HciObjectType;
using hci::HciSession;
using mission::GeoPoint;
using mission::LocalTangentPlane;
using mission::PlanePoint;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;
const QString kPackage = QStringLiteral("com.ugcs.ucs.service.routing.impl.");
const GeoPoint kCentre{56.9740, 24.0760};  // beside the simulator's vehicles

struct Client
{
    explicit Client(quint16 port) : client(&session)
    {
        session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("admin"), QStringLiteral("admin"));
    }
    bool ready() { return test::reaches(session, HciSession::State::Ready); }
    HciSession session;
    HciClient client;
};

template<class T>
T call(hci::HciReply *raw, HciError *error = nullptr)
{
    auto reply = test::keep(raw);
    if (!test::finishes(reply.get()))
        qFatal("no answer to %s", qPrintable(reply->requestName()));
    if (error)
        *error = reply->error();
    else if (!reply->isOk())
        qWarning("%s failed: %s", qPrintable(reply->requestName()), qPrintable(reply->error().toString()));
    return reply->response<T>();
}

const LocalTangentPlane &plane()
{
    static const LocalTangentPlane p(kCentre);
    return p;
}

pb::FigurePoint figurePoint(const PlanePoint &p, double agl = 0)
{
    const GeoPoint g = plane().unproject(p);
    pb::FigurePoint f;
    f.set_latitude(g.latitude * kRad);
    f.set_longitude(g.longitude * kRad);
    f.set_aglaltitude(agl);
    f.set_altitudetype(pb::AT_AGL);
    return f;
}

pb::SegmentDefinition segment(const char *shortClass, pb::FigureType type, const std::vector<PlanePoint> &points,
                              std::initializer_list<std::pair<const char *, const char *>> values, double agl = 0)
{
    static int serial = 0;
    pb::SegmentDefinition s;
    s.set_uuid("segment-" + std::to_string(++serial));
    s.set_algorithmclassname((kPackage + QLatin1String(shortClass)).toStdString());
    s.mutable_figure()->set_type(type);
    for (const PlanePoint &p : points)
        *s.mutable_figure()->add_points() = figurePoint(p, agl);
    if (type == pb::FT_POLYGON)  // UgCS sends polygons closed
        *s.mutable_figure()->add_points() = figurePoint(points.front(), agl);
    for (const auto &[name, value] : values) {
        auto *v = s.add_parametervalues();
        v->set_name(name);
        v->set_value(value);
    }
    return s;
}

struct Planned
{
    PlanePoint at;
    double agl;
};

// The positions a processed segment flies (Waypoint, Takeoff and Landing actions), on the test plane.
std::vector<Planned> flown(const pb::ProcessedSegment &s, double ground)
{
    std::vector<Planned> out;
    for (const auto &a : s.segmentactions()) {
        double lat = 0, lon = 0, alt = 0;
        if (a.has_waypoint())
            lat = a.waypoint().latitude(), lon = a.waypoint().longitude(), alt = a.waypoint().wgs84altitude();
        else if (a.has_takeoff())
            lat = a.takeoff().latitude(), lon = a.takeoff().longitude(), alt = a.takeoff().wgs84altitude();
        else if (a.has_landing())
            lat = a.landing().latitude(), lon = a.landing().longitude(), alt = a.landing().wgs84altitude();
        else
            continue;
        out.push_back({plane().project({lat / kRad, lon / kRad}), alt - ground});
    }
    return out;
}

double toSegment(const PlanePoint &p, const PlanePoint &a, const PlanePoint &b)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

bool inside(const PlanePoint &p, const std::vector<PlanePoint> &poly)
{
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y)
            && p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    return in;
}

// Pass segments of an area segment: consecutive waypoints that lie on the same line of bearing `bearingDeg`.
std::vector<std::pair<PlanePoint, PlanePoint>> passesOf(const std::vector<Planned> &points, double bearingDeg, double minLength)
{
    const double ux = std::sin(bearingDeg * kRad), uy = std::cos(bearingDeg * kRad);
    std::vector<std::pair<PlanePoint, PlanePoint>> out;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const PlanePoint a = points[i].at, b = points[i + 1].at;
        const double dx = b.x - a.x, dy = b.y - a.y, l = std::hypot(dx, dy);
        if (l >= minLength && std::abs(dx * uy - dy * ux) / l < 1e-3)
            out.push_back({a, b});
    }
    return out;
}

QString text(const pb::ProcessedSegment &s)
{
    QStringList all;
    for (const auto &m : s.messageset().messages())
        all << QString::fromStdString(m.defaulttext());
    return all.join(QLatin1Char('\n'));
}

} // namespace

class TestSimSegments : public QObject
{
    Q_OBJECT

private slots:
    void serverDescribesEveryAlgorithm()
    {
        test::SimServer sim;
        Client c(sim.port());
        QVERIFY(c.ready());
        const auto list = call<pb::GetObjectListResponse>(c.client.listObjects(QStringLiteral("TraverseAlgorithm")));
        std::vector<pb::TraverseAlgorithm> algorithms;
        for (const auto &w : list.objects())
            algorithms.push_back(w.traversealgorithm());
        QCOMPARE(algorithms.size(), mission::AlgorithmCatalog::builtIn().algorithms().size());
        for (const mission::AlgorithmDefinition &known : mission::AlgorithmCatalog::builtIn().algorithms()) {
            const auto it = std::find_if(algorithms.begin(), algorithms.end(),
                                         [&](const auto &a) { return QString::fromStdString(a.implementationclass()) == known.className; });
            QVERIFY2(it != algorithms.end(), qPrintable(known.className));
            QVERIFY(it->id() > 0);
            // From the server's description alone: every parameter with its type and default.
            const mission::AlgorithmDefinition described = mission::algorithmFromProto(*it);
            QCOMPARE(described.figure, known.figure);
            QCOMPARE(described.parameters.size(), known.parameters.size());
            for (size_t i = 0; i < known.parameters.size(); ++i) {
                QCOMPARE(described.parameters[i].name, known.parameters[i].name);
                QCOMPARE(described.parameters[i].type, known.parameters[i].type);
                QCOMPARE(described.parameters[i].defaultValue, known.parameters[i].defaultValue);
                QCOMPARE(described.parameters[i].advanced, known.parameters[i].advanced);
            }
        }
        const mission::AlgorithmCatalog catalog = mission::catalogFromProto(algorithms);
        const auto photo = catalog.byClassName(kPackage + QStringLiteral("PhotogrammetryAlgorithm"));
        QVERIFY(photo && photo->serverId > 0);
        QCOMPARE(photo->parameter(u"groundSampleDistance")->unit(), QStringLiteral("cm/px"));
        QCOMPARE(photo->parameter(u"overlapForward")->description, QStringLiteral("Forward overlap (1–90 %)"));
        QCOMPARE(*photo->parameter(u"overlapForward")->maximum, 90.0);
    }

    void profilesCarryTheirCameraPayloads()
    {
        test::SimServer sim;
        Client c(sim.port());
        QVERIFY(c.ready());
        const auto profiles = call<pb::GetObjectListResponse>(c.client.listObjects(QStringLiteral("VehicleProfile")));
        const pb::VehicleProfile *emu = nullptr;
        for (const auto &w : profiles.objects())
            if (w.vehicleprofile().name() == "EMU Copter")
                emu = &w.vehicleprofile();
        QVERIFY(emu);
        QCOMPARE(emu->payloadprofiles_size(), 1);
        const pb::PayloadProfile &gopro = emu->payloadprofiles(0).payloadprofile();
        QCOMPARE(gopro.name(), std::string("GoPro Hero3 Black Edition"));
        QCOMPARE(gopro.payloadtype(), pb::PT_CAMERA);
        for (const auto &p : gopro.parameters())
            if (p.type() == pb::PPT_TRUE_FOCAL_LENGTH)
                QCOMPARE(p.value(), 0.0028);  // metres on the wire
        const auto camera = mission::cameraFromPayload(gopro);
        QVERIFY(camera);
        QVERIFY(std::abs(camera->focalLengthMm - 2.8) < 1e-9);
        const auto payloads = call<pb::GetObjectListResponse>(c.client.listObjects(QStringLiteral("PayloadProfile")));
        QVERIFY(payloads.objects_size() >= 3);
        // The vehicles fly the profile with its camera.
        const auto vehicles = call<pb::GetObjectListResponse>(c.client.listObjects(HciObjectType::Vehicle));
        QCOMPARE(vehicles.objects(0).vehicle().profile().payloadprofiles_size(), 1);
    }

    void selectionValuesOfferTheProfilesCameras()
    {
        test::SimServer sim;
        Client c(sim.port());
        QVERIFY(c.ready());
        const auto vehicles = call<pb::GetObjectListResponse>(c.client.listObjects(HciObjectType::Vehicle));
        const pb::VehicleProfile &profile = vehicles.objects(0).vehicle().profile();
        pb::GetParametersSelectionValuesRequest request;
        request.set_clientid(-1);
        request.mutable_route()->mutable_vehicleprofile()->set_id(profile.id());
        request.mutable_algorithm()->set_implementationclass((kPackage + QStringLiteral("PhotogrammetryAlgorithm")).toStdString());
        const auto response = call<pb::GetParametersSelectionValuesResponse>(c.session.send(request));
        mission::AlgorithmDefinition photo = *mission::AlgorithmCatalog::builtIn().byKind(mission::AlgorithmKind::Photogrammetry);
        mission::applySelections(photo, {response.selections().begin(), response.selections().end()});
        const auto &cameras = photo.parameter(u"camera")->choices;
        QCOMPARE(cameras.size(), size_t(1));
        QCOMPARE(cameras[0].value, QString::number(profile.payloadprofiles(0).payloadprofile().id()));
        QCOMPARE(cameras[0].displayName, QStringLiteral("GoPro Hero3 Black Edition"));
        QCOMPARE(photo.parameter(u"camera")->defaultValue, cameras[0].value);
        QCOMPARE(photo.parameter(u"wpTurnType")->choices.size(), size_t(4));
        QCOMPARE(photo.parameter(u"actionExecution")->choices.size(), size_t(3));

        request.mutable_algorithm()->set_implementationclass("com.example.Nothing");
        HciError error;
        call<pb::GetParametersSelectionValuesResponse>(c.session.send(request), &error);
        QVERIFY(error.message().contains(QLatin1String("com.example.Nothing")));
    }

    void everySegmentTypeIsProcessedToItsGeometry()
    {
        test::SimServer sim;
        Client c(sim.port());
        QVERIFY(c.ready());
        const auto vehicles = call<pb::GetObjectListResponse>(c.client.listObjects(HciObjectType::Vehicle));
        const pb::Vehicle emu = vehicles.objects(0).vehicle();
        const double ground = sim.world.groundElevation();

        const std::vector<PlanePoint> field{{-200, -150}, {250, -180}, {300, 160}, {-150, 200}};
        const std::vector<PlanePoint> road{{-400, -300}, {0, -250}, {300, -380}};
        pb::Route route;
        route.set_name("every segment");
        route.mutable_vehicleprofile()->set_id(emu.profile().id());  // by id: the server completes it from its store
        route.set_initialspeed(5);
        *route.add_segments() = segment("TakeOffAlgorithm", pb::FT_TAKEOFF_POINT, {{-50, -20}}, {}, 20);
        *route.add_segments() = segment("CircleAlgorithm", pb::FT_CIRCLE, {{0, 0}}, {{"loops", "2"}, {"flightClockwise", "true"}}, 45);
        route.mutable_segments(1)->mutable_figure()->add_parameters()->set_value(60);
        *route.add_segments() = segment("PerimeterAlgorithm", pb::FT_POLYGON, field, {{"height", "40"}, {"loops", "1"}});
        *route.add_segments() = segment("AreaScanAlgorithm", pb::FT_POLYGON, field,
                                        {{"height", "50"}, {"altitudeType", "AGL"}, {"sideDistance", "30"},
                                         {"directionAngle", "20"}, {"overshoot", "10"}, {"speed", "8"}});
        *route.add_segments() = segment("PhotogrammetryAlgorithm", pb::FT_POLYGON, field,
                                        {{"camera", "GoPro Hero3 Black Edition"}, {"groundSampleDistance", "2"},
                                         {"overlapForward", "60"}, {"overlapSide", "30"}, {"directionAngle", "0"},
                                         {"altitudeType", "AGL"}, {"actionExecution", "ACTIONS_ON_FORWARD_PASSES"}});
        *route.add_segments() = segment("CorridorMappingAlgorithm", pb::FT_POLYLINE, road,
                                        {{"width", "120"}, {"groundSampleDistance", "2"}, {"altitudeType", "AGL"}});
        *route.add_segments() = segment("LandingAlgorithm", pb::FT_LANDING_POINT, {{-50, -20}}, {});

        const auto response = call<pb::ProcessRouteResponse>(c.client.processRoute(route));
        const pb::ProcessedRoute &processed = response.processedroute();
        QCOMPARE(processed.segments_size(), 7);
        for (const auto &s : processed.segments())
            QVERIFY2(s.status() == pb::RPS_PROCESSED, qPrintable(text(s)));
        for (int i = 0; i < 7; ++i)
            QCOMPARE(processed.segments(i).uuid(), route.segments(i).uuid());

        // Take-off and landing: their actions at the point.
        QVERIFY(processed.segments(0).segmentactions(1).has_takeoff());
        QVERIFY(std::abs(flown(processed.segments(0), ground)[0].agl - 20) < 1e-6);
        QVERIFY(processed.segments(6).segmentactions(1).has_landing());

        // Orbit: every point 60 m (±1 m) from the centre, 2 laps, clockwise.
        const auto orbit = flown(processed.segments(1), ground);
        const int perLap = mission::circlePointsPerLap(60);
        QCOMPARE(int(orbit.size()), 2 * perLap + 1);
        for (size_t i = 0; i < orbit.size(); ++i) {
            QVERIFY(std::abs(std::hypot(orbit[i].at.x, orbit[i].at.y) - 60) <= 1.0);
            QVERIFY(std::abs(orbit[i].agl - 45) < 1e-6);
            if (i > 0)  // clockwise seen from above: the cross product of successive radii is negative
                QVERIFY(orbit[i - 1].at.x * orbit[i].at.y - orbit[i - 1].at.y * orbit[i].at.x < 0);
        }

        // Perimeter: every point on the polygon's edges, every corner visited, at the height.
        const auto perimeter = flown(processed.segments(2), ground);
        QCOMPARE(perimeter.size(), field.size() + 1);
        for (const Planned &p : perimeter) {
            double nearest = 1e9;
            for (size_t i = 0; i < field.size(); ++i)
                nearest = std::min(nearest, toSegment(p.at, field[i], field[(i + 1) % field.size()]));
            QVERIFY(nearest < 0.05);
            QVERIFY(std::abs(p.agl - 40) < 1e-6);
        }

        // Area scan: passes along 20°, 30 m apart, covering the polygon, overshooting by 10 m.
        const auto scan = flown(processed.segments(3), ground);
        const auto scanPasses = passesOf(scan, 20, 5);
        QVERIFY(scanPasses.size() >= 16);
        const double nx = std::cos(20 * kRad), ny = -std::sin(20 * kRad);  // across the passes
        std::vector<double> offsets;
        for (const auto &[a, b] : scanPasses)
            offsets.push_back(a.x * nx + a.y * ny);
        std::sort(offsets.begin(), offsets.end());
        offsets.erase(std::unique(offsets.begin(), offsets.end(), [](double x, double y) { return std::abs(x - y) < 0.05; }), offsets.end());
        for (size_t i = 1; i < offsets.size(); ++i)
            QVERIFY2(std::abs(offsets[i] - offsets[i - 1] - 30) < 0.05, qPrintable(QString::number(offsets[i] - offsets[i - 1])));
        for (double x = -300; x <= 300; x += 7) {
            for (double y = -200; y <= 200; y += 7) {
                // Points at least half a spacing inside: the line beside them crosses the polygon there.
                double boundary = 1e9;
                for (size_t i = 0; i < field.size(); ++i)
                    boundary = std::min(boundary, toSegment({x, y}, field[i], field[(i + 1) % field.size()]));
                if (!inside({x, y}, field) || boundary < 15)
                    continue;
                double nearest = 1e9;
                for (const auto &[a, b] : scanPasses)
                    nearest = std::min(nearest, toSegment({x, y}, a, b));
                QVERIFY2(nearest <= 15.0 + 0.05, qPrintable(QStringLiteral("%1,%2 is %3 m from a pass").arg(x).arg(y).arg(nearest)));
            }
        }
        for (const Planned &p : scan)
            QVERIFY(std::abs(p.agl - 50) < 1e-6);

        // Photogrammetry with the profile's GoPro at 2 cm/px, 60/30 %: 36.30 m high, passes 56 m apart,
        // a photo every 58.995 × 0.4 = 23.598 m, the series started and stopped on each pass.
        const pb::ProcessedSegment &photo = processed.segments(4);
        const auto shots = flown(photo, ground);
        for (const Planned &p : shots)
            QVERIFY(std::abs(p.agl - 36.3047) < 1e-3);
        const auto photoPasses = passesOf(shots, 0, 50);
        QVERIFY(photoPasses.size() >= 8);
        for (size_t i = 1; i < photoPasses.size(); ++i)
            QVERIFY(std::abs(std::abs(photoPasses[i].first.x - photoPasses[i - 1].first.x) - 56.0) < 0.05);
        int starts = 0, stops = 0, facing = 0;
        for (const auto &a : photo.segmentactions()) {
            if (a.has_cameraseriesbydistance()) {
                QCOMPARE(a.origin(), pb::OO_SYSTEM);
                if (a.cameraseriesbydistance().interval() > 0) {
                    ++starts;
                    QVERIFY(std::abs(a.cameraseriesbydistance().interval() - 23.598055) < 1e-5);
                } else {
                    ++stops;
                }
            }
            if (a.has_cameracontrol() && std::abs(a.cameracontrol().tilt() - 3.14159265358979 / 2) < 1e-9)
                ++facing;
        }
        QCOMPARE(starts, int(photoPasses.size()));
        QCOMPARE(stops, starts);
        QCOMPARE(facing, 1);
        QVERIFY(text(photo).contains(QLatin1String("photos every 23.6 m")));

        // Corridor: every point within half the width of the centre line.
        const auto corridor = flown(processed.segments(5), ground);
        QVERIFY(corridor.size() >= 6);
        for (const Planned &p : corridor)
            QVERIFY(std::min(toSegment(p.at, road[0], road[1]), toSegment(p.at, road[1], road[2])) <= 60.0 + 1e-6);

        QVERIFY(processed.estimateddistance() > 5000);

        // The vehicle takes the processed route as its mission: every waypoint, take-off and landing.
        HciError error;
        call<pb::AcquireLockResponse>(c.client.acquireLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
        auto upload = test::keep(c.client.uploadRoute(emu, processed, false));
        QVERIFY(test::finishes(upload.get()));
        QVERIFY2(upload->isOk(), qPrintable(upload->error().toString()));
        size_t expected = 0;
        for (const auto &s : processed.segments())
            expected += flown(s, ground).size();
        const auto &missionPoints = sim.world.vehicle(emu.id())->model().mission();
        QCOMPARE(missionPoints.size(), expected);
        // Lands straight down: reached at the height the last leg left at (the ground is level here), then landed on.
        QVERIFY(missionPoints.back().landHere);
        QVERIFY(std::abs(missionPoints.back().altitudeAgl - missionPoints[missionPoints.size() - 2].altitudeAgl) < 1e-6);
        const PlanePoint last = plane().project({missionPoints.back().latitude, missionPoints.back().longitude});
        QVERIFY(std::hypot(last.x + 50, last.y + 20) < 0.01);
    }

    void outOfRangeParametersNameTheSegment()
    {
        test::SimServer sim;
        Client c(sim.port());
        QVERIFY(c.ready());
        const auto vehicles = call<pb::GetObjectListResponse>(c.client.listObjects(HciObjectType::Vehicle));
        pb::Route route;
        *route.mutable_vehicleprofile() = vehicles.objects(0).vehicle().profile();
        route.set_initialspeed(5);
        *route.add_segments() = segment("WaypointAlgorithm", pb::FT_POINT, {{0, 0}}, {}, 30);
        *route.add_segments() = segment("PhotogrammetryAlgorithm", pb::FT_POLYGON, {{0, 0}, {100, 0}, {100, 100}},
                                        {{"overlapForward", "95"}, {"groundSampleDistance", "2"}});
        *route.add_segments() = segment("CircleAlgorithm", pb::FT_CIRCLE, {{0, 0}}, {{"loops", "0"}}, 30);
        route.mutable_segments(2)->mutable_figure()->add_parameters()->set_value(50);
        *route.add_segments() = segment("AreaScanAlgorithm", pb::FT_POLYGON, {{0, 0}, {100, 0}}, {});

        const auto processed = call<pb::ProcessRouteResponse>(c.client.processRoute(route)).processedroute();
        QCOMPARE(processed.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(processed.segments(1).status(), pb::RPS_INVALID);
        QCOMPARE(processed.segments(1).messageset().messages(0).severity(), pb::MS_ERROR);
        QCOMPARE(text(processed.segments(1)), QStringLiteral("Segment 2 (Photogrammetry): overlapForward: 95 is above the maximum of 90 %"));
        QCOMPARE(processed.segments(2).status(), pb::RPS_INVALID);
        QCOMPARE(text(processed.segments(2)), QStringLiteral("Segment 3 (Circle): loops: 0 is below the minimum of 1"));
        QCOMPARE(processed.segments(3).status(), pb::RPS_INVALID);
        QCOMPARE(text(processed.segments(3)), QStringLiteral("Segment 4 (Area scan): An area scan needs a polygon of at least 3 vertices."));

        // A camera too slow for the speed is a warning, not an error.
        pb::Route fast = route;
        fast.clear_segments();
        *fast.add_segments() = segment("PhotogrammetryAlgorithm", pb::FT_POLYGON, {{0, 0}, {300, 0}, {300, 300}, {0, 300}},
                                       {{"groundSampleDistance", "1"}, {"overlapForward", "85"}, {"speed", "10"}, {"altitudeType", "AGL"}});
        const auto warned = call<pb::ProcessRouteResponse>(c.client.processRoute(fast)).processedroute();
        QCOMPARE(warned.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(warned.segments(0).messageset().messages(0).severity(), pb::MS_WARNING);
        QVERIFY(text(warned.segments(0)).contains(QLatin1String("at most every 1 s")));
    }
};

QTEST_GUILESS_MAIN(TestSimSegments)
#include "tst_simsegments.moc"
