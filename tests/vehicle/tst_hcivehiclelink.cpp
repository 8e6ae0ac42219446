// HciVehicleLink + Vehicle against the simulated UgCS server: telemetry, commands under the vehicle
// lock, mission upload through route processing, another operator's lock; the HCI telemetry mapping;
// and one model for both protocols (the same fields filled, in the same units, by HCI and by VCI).
#include "CommandCatcher.h"
#include "HciClient.h"
#include "HciReply.h"
#include "HciServer.h"
#include "HciSession.h"
#include "HciRoutePass.h"
#include "HciTelemetryMapper.h"
#include "HciVehicleLink.h"
#include "Route.h"
#include "Messages.pb.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "SimVehicle.h"
#include "SimWorld.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QSignalSpy>
#include <QtTest>

#include <cmath>

using namespace sortie;
using namespace sortie::vehicle;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = 3.14159265358979323846 / 180;

struct Server
{
    Server()
        : world(config())
        , server(world)
    {
        server.setUploadStepMs(5);
        if (!server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot start the simulator: %s", qPrintable(server.errorString()));
    }
    static sim::SimWorld::Config config()
    {
        sim::SimWorld::Config c;
        c.telemetryRateHz = 20;
        c.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true}, {0, QStringLiteral("bob"), QStringLiteral("bob-pw"), false}};
        return c;
    }
    sim::SimWorld world;
    sim::HciServer server;
};

struct Operator
{
    Operator(quint16 port, const char *login, const char *password)
        : client(&session)
    {
        session.open(QStringLiteral("127.0.0.1"), port, QString::fromLatin1(login), QString::fromLatin1(password));
    }
    pb::Vehicle vehicle(const std::string &name)
    {
        auto *reply = client.listObjects(hci::HciObjectType::Vehicle);
        reply->setAutoDelete(false);
        QSignalSpy done(reply, &hci::HciReply::finished);
        if (!reply->isFinished())
            done.wait(10000);
        pb::Vehicle found;
        for (const auto &w : reply->response<pb::GetObjectListResponse>().objects())
            if (w.vehicle().name() == name)
                found = w.vehicle();
        delete reply;
        return found;
    }
    hci::HciSession session;
    hci::HciClient client;
};

using Result = test::CommandCatcher;

pb::Telemetry telemetry(const char *code, pb::Semantic semantic, pb::Subsystem subsystem = pb::S_FLIGHT_CONTROLLER)
{
    pb::Telemetry t;
    t.set_time(5000);
    t.mutable_telemetryfield()->set_code(code);
    t.mutable_telemetryfield()->set_semantic(semantic);
    t.mutable_telemetryfield()->set_subsystem(subsystem);
    return t;
}

} // namespace

class TstHciVehicleLink : public QObject
{
    Q_OBJECT
private slots:
    void mapping();
    void telemetryAndCommands();
    void missionUpload();
    void anotherOperatorsLock();
    void oneModelForBothProtocols();
    void routePassMapping();
    void routePassFollowsTheFlight();
    void routePassMalformedIsDropped();
};

void TstHciVehicleLink::mapping()
{
    pb::TelemetryEvent e;
    auto add = [&](pb::Telemetry t) { *e.add_telemetry() = std::move(t); };
    auto lat = telemetry("latitude", pb::S_LATITUDE);
    lat.mutable_value()->set_doublevalue(0.99);
    add(lat);
    auto gimbal = telemetry("roll", pb::S_ROLL, pb::S_GIMBAL);
    gimbal.mutable_value()->set_floatvalue(1.0f);
    add(gimbal);
    auto capacity = telemetry("battery_level", pb::S_CAPACITY_LEVEL);
    capacity.mutable_value()->set_intvalue(80);
    add(capacity);
    auto mode = telemetry("flight_mode", pb::S_FLIGHT_MODE);
    mode.mutable_value()->set_stringvalue("RTL");
    add(mode);
    auto armed = telemetry("is_armed", pb::S_BOOL);
    armed.mutable_value()->set_boolvalue(true);
    add(armed);
    auto other = telemetry("payload_ok", pb::S_BOOL);
    other.mutable_value()->set_boolvalue(true);
    add(other);
    auto unavailable = telemetry("ground_speed", pb::S_GROUND_SPEED);
    unavailable.mutable_value();
    add(unavailable);
    auto untimed = telemetry("satellite_count", pb::S_SATELLITE_COUNT);
    untimed.clear_time();
    untimed.mutable_value()->set_intvalue(9);
    add(untimed);
    // NaN and infinity are no readings (fuzz_hci_telemetry's rule): skipped like an empty value.
    auto notANumber = telemetry("longitude", pb::S_LONGITUDE);
    notANumber.mutable_value()->set_doublevalue(std::nan(""));
    add(notANumber);
    auto infinite = telemetry("heading", pb::S_HEADING);
    infinite.mutable_value()->set_doublevalue(HUGE_VAL);
    add(infinite);
    const TelemetryBatch b = hciTelemetry(e, 777);
    QCOMPARE(b.size(), size_t(5));
    QVERIFY(b[0].field == TelemetryField::Latitude && std::abs(b[0].value - 0.99 / kRad) < 1e-12 && b[0].time == 5000); // radians become degrees
    QVERIFY(b[1].field == TelemetryField::BatteryRemaining && b[1].value == 0.8);
    QVERIFY(b[2].field == TelemetryField::Mode && b[2].value == double(FlightMode::ReturnHome));
    QVERIFY(b[3].field == TelemetryField::Armed && b[3].value == 1.0);
    QVERIFY(b[4].field == TelemetryField::Satellites && b[4].time == 777);
}

void TstHciVehicleLink::telemetryAndCommands()
{
    Server sim;
    Operator op(sim.server.port(), "admin", "admin");
    QTRY_VERIFY(op.session.isReady());
    const pb::Vehicle emu = op.vehicle("EMU-101");
    QVERIFY(emu.id() > 0);
    HciVehicleLink link(&op.client, emu);
    Vehicle v(&link);
    QCOMPARE(v.protocol(), QStringLiteral("HCI"));
    QCOMPARE(v.name(), QStringLiteral("EMU-101"));
    QCOMPARE(v.linkState(), VehicleLink::State::Disconnected);
    link.start();
    QTRY_VERIFY(v.isConnected());
    QTRY_VERIFY(v.position().isValid());
    QTRY_COMPARE(v.mode(), QStringLiteral("manual"));
    QTRY_COMPARE(v.gpsFix(), 3);
    QVERIFY(!v.armed());

    QSignalSpy finished(&v, &Vehicle::commandFinished);
    v.arm();
    QTRY_COMPARE(finished.count(), 1);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QTRY_VERIFY(v.armed());
    Result takeoff, disarm, land;
    link.takeoff(4, takeoff.callback());
    QTRY_VERIFY(takeoff.done);
    QVERIFY2(takeoff.result.ok, qPrintable(takeoff.result.message));
    QTRY_VERIFY_WITH_TIMEOUT(v.altitudeAgl() > 3.5, 15000);
    link.arm(false, disarm.callback()); // refused in the air, with the server's reason
    QTRY_VERIFY(disarm.done);
    QVERIFY(!disarm.result.ok);
    QVERIFY2(disarm.result.message.startsWith(QLatin1String("disarm: ")), qPrintable(disarm.result.message));
    link.land(land.callback());
    QTRY_VERIFY(land.done);
    QVERIFY(land.result.ok);
    QTRY_VERIFY_WITH_TIMEOUT(!v.armed(), 15000);
    QVERIFY(!sim.world.locks().holder(QStringLiteral("Vehicle"), emu.id())); // every lock released

    link.stop();
    QCOMPARE(v.linkState(), VehicleLink::State::Disconnected);
}

namespace {

mission::Route routeOf(std::initializer_list<std::array<double, 4>> points) // lat, lon (deg), alt AGL, speed
{
    mission::Route r;
    r.settings.name = QStringLiteral("link test");
    for (const auto &p : points) {
        mission::Waypoint w;
        w.position = {p[0], p[1]};
        w.altitude = p[2];
        w.speed = p[3];
        r.segments.push_back(w);
    }
    return r;
}

struct Prepared
{
    bool done = false;
    CommandResult result;
    PreparedMission mission;
    VehicleLink::PrepareDone callback()
    {
        return [this](const CommandResult &r, const PreparedMission &m) {
            done = true;
            result = r;
            mission = m;
        };
    }
};

} // namespace

void TstHciVehicleLink::missionUpload()
{
    Server sim;
    Operator op(sim.server.port(), "admin", "admin");
    QTRY_VERIFY(op.session.isReady());
    HciVehicleLink link(&op.client, op.vehicle("EMU-102"));
    link.start();
    QSignalSpy missionChanged(&link, &VehicleLink::missionChanged);
    // The server processes the route against the vehicle's profile; what comes back is uploaded.
    Prepared prepared, bad;
    link.prepareMission(routeOf({{56.9499, 24.1052, 20, 6}, {56.9501, 24.1056, 25, 5}}), prepared.callback());
    QTRY_VERIFY_WITH_TIMEOUT(prepared.done, 15000);
    QVERIFY2(prepared.result.ok, qPrintable(prepared.result.message));
    QVERIFY(prepared.mission.native);
    QVERIFY(prepared.mission.items.size() >= 2);
    QVERIFY(std::abs(prepared.mission.items.back().longitude - 24.1056) < 1e-6);
    QCOMPARE(missionChanged.count(), 0); // nothing was sent yet

    std::vector<UploadStep> steps;
    VehicleLink::UploadObserver observer;
    observer.step = [&](UploadStep step, int, int) {
        if (steps.empty() || steps.back() != step)
            steps.push_back(step);
    };
    Result upload;
    link.uploadMission(prepared.mission, observer, upload.callback());
    QTRY_VERIFY_WITH_TIMEOUT(upload.done, 15000);
    QVERIFY2(upload.result.ok, qPrintable(upload.result.message));
    QCOMPARE(missionChanged.count(), 1);
    QCOMPARE(steps, (std::vector<UploadStep>{UploadStep::Locking, UploadStep::Sending, UploadStep::Releasing}));
    const sim::SimVehicle *emu = sim.world.vehicle(link.vehicleObjectId());
    QVERIFY(emu->model().mission().size() >= 2);
    QVERIFY(std::abs(emu->model().mission().back().longitude - 24.1056) < 1e-7);
    QVERIFY(!sim.world.locks().holder(QStringLiteral("Vehicle"), link.vehicleObjectId())); // released

    // Refused by the server's processing, naming the segment; nothing to upload.
    link.prepareMission(routeOf({{56.95, 24.1, -30, 5}}), bad.callback());
    QTRY_VERIFY_WITH_TIMEOUT(bad.done, 15000);
    QVERIFY(!bad.result.ok);
    QVERIFY2(bad.result.message.startsWith(QLatin1String("Segment 1: ")), qPrintable(bad.result.message));
    QVERIFY2(bad.result.message.contains(QLatin1String("below the ground")), qPrintable(bad.result.message));

    // A mission prepared by another link (no server plan) is refused, not half-sent.
    Result foreign;
    link.uploadMission(PreparedMission{prepared.mission.items, {}, {}}, {}, foreign.callback());
    QTRY_VERIFY(foreign.done);
    QVERIFY(!foreign.result.ok);

    bool refused = false;
    link.downloadMission([&](const CommandResult &r, const std::vector<MissionItem> &) { refused = !r.ok; });
    QTRY_VERIFY(refused);
    QVERIFY(!(link.capabilities() & VehicleLink::MissionDownload));
    QVariantMap params;
    link.readParameters([&](const CommandResult &, const QVariantMap &p) { params = p; });
    QTRY_VERIFY(!params.isEmpty());
}

void TstHciVehicleLink::anotherOperatorsLock()
{
    Server sim;
    Operator admin(sim.server.port(), "admin", "admin"), bob(sim.server.port(), "bob", "bob-pw");
    QTRY_VERIFY(admin.session.isReady() && bob.session.isReady());
    const pb::Vehicle emu = admin.vehicle("EMU-103");
    auto *lock = bob.client.acquireLock(hci::HciObjectType::Vehicle, emu.id());
    QSignalSpy locked(lock, &hci::HciReply::finished);
    QVERIFY(locked.wait(10000));
    HciVehicleLink link(&admin.client, emu);
    Result arm;
    link.arm(true, arm.callback());
    QTRY_VERIFY(arm.done);
    QVERIFY(!arm.result.ok);
    QVERIFY2(arm.result.message.contains(QLatin1String("bob")), qPrintable(arm.result.message));
    QVERIFY(!sim.world.vehicle(emu.id())->model().state().armed);
}

void TstHciVehicleLink::oneModelForBothProtocols()
{
    Server hciSim;
    Operator op(hciSim.server.port(), "admin", "admin");
    QTRY_VERIFY(op.session.isReady());
    HciVehicleLink hciLink(&op.client, op.vehicle("EMU-101"));
    sim::SimVciVehicle vciSim(sim::SimVciOptions{});
    sim::SimVciListener listener(&vciSim);
    QVERIFY(listener.listen(0));
    VciVehicleLink vciLink(*vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port())));
    Vehicle viaHci(&hciLink), viaVci(&vciLink);
    hciLink.start();
    vciLink.start();
    const TelemetryField common[] = {TelemetryField::Latitude, TelemetryField::Longitude, TelemetryField::AltitudeAmsl,
                                     TelemetryField::AltitudeAgl, TelemetryField::Roll, TelemetryField::Pitch,
                                     TelemetryField::Heading, TelemetryField::GroundSpeed, TelemetryField::VerticalSpeed,
                                     TelemetryField::BatteryVoltage, TelemetryField::GpsFix, TelemetryField::Satellites,
                                     TelemetryField::Armed, TelemetryField::Mode};
    for (TelemetryField f : common) {
        QTRY_VERIFY2(viaHci.last(f).has_value(), fieldName(f).data());
        QTRY_VERIFY2(viaVci.last(f).has_value(), fieldName(f).data());
    }
    // Same places near Riga, in degrees on the map and in the fields, from either protocol.
    QVERIFY(std::abs(viaHci.position().latitude() - 56.95) < 0.05);
    QVERIFY(std::abs(viaVci.position().latitude() - 56.95) < 0.05);
    QVERIFY(std::abs(viaHci.value(TelemetryField::Latitude) - viaVci.value(TelemetryField::Latitude)) < 0.05);
    QCOMPARE(viaHci.mode(), viaVci.mode());
    QCOMPARE(viaHci.gpsFix(), viaVci.gpsFix());
    QVERIFY(viaHci.batteryVoltage() > 14 && viaVci.batteryVoltage() > 14);
    QCOMPARE(viaHci.protocol(), QStringLiteral("HCI"));
    QCOMPARE(viaVci.protocol(), QStringLiteral("VCI"));
}


namespace {

pb::ObjectModificationEvent passEvent(pb::ModificationType type, int id, int vehicle, int count, int index = -1)
{
    pb::ObjectModificationEvent e;
    e.set_modificationtype(type);
    e.set_objecttype("RoutePass");
    e.set_objectid(id);
    if (type == pb::MT_DELETE)
        return e;
    auto *p = e.mutable_object()->mutable_routepass();
    p->set_id(id);
    p->mutable_vehicle()->set_id(vehicle);
    p->set_waypointcount(count);
    if (index >= 0)
        p->set_waypointindex(index);
    return e;
}

double fieldIn(const TelemetryBatch &b, TelemetryField f)
{
    for (const auto &u : b)
        if (u.field == f)
            return u.value;
    return qQNaN();
}

// Applies the batches a link emits to a fresh record of the mission fields, in order.
QList<int> missionCurrents(const QSignalSpy &spy)
{
    QList<int> seen;
    for (const auto &args : spy) {
        const double v = fieldIn(args.at(0).value<TelemetryBatch>(), TelemetryField::MissionCurrent);
        if (!qIsNaN(v) && (seen.isEmpty() || seen.back() != int(v)))
            seen.append(int(v));
    }
    return seen;
}

} // namespace

void TstHciVehicleLink::routePassMapping()
{
    using Kind = HciRoutePassTracker::Outcome::Kind;
    HciRoutePassTracker t(7);
    // Uploaded, not yet flown: the count, no active waypoint.
    auto o = t.apply(passEvent(pb::MT_CREATE, 40, 7, 5), 100);
    QCOMPARE(o.kind, Kind::Applied);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCurrent), -1.0);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCount), 5.0);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionState), double(MissionState::Idle));
    o = t.apply(passEvent(pb::MT_UPDATE, 40, 7, 5, 2), 200);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCurrent), 2.0);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionReached), 2.0);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionState), double(MissionState::Active));
    QCOMPARE(o.batch.front().time, int64_t(200));
    // Another vehicle's pass, and the removal of a pass we do not follow: nothing.
    QCOMPARE(t.apply(passEvent(pb::MT_UPDATE, 41, 8, 5, 4), 300).kind, Kind::Ignored);
    QCOMPARE(t.apply(passEvent(pb::MT_DELETE, 41, 0, 0), 300).kind, Kind::Ignored);
    // Removed before its last waypoint: no longer executed, not complete.
    o = t.apply(passEvent(pb::MT_DELETE, 40, 0, 0), 400);
    QCOMPARE(o.kind, Kind::Applied);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionState), double(MissionState::Idle));
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCurrent), -1.0);
    // The server added the vehicle's position as a first waypoint: indexes shift onto our mission.
    t.setUploadedCount(3);
    o = t.apply(passEvent(pb::MT_UPDATE, 42, 7, 4, 1), 500);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCurrent), 0.0);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCount), 3.0);
    o = t.apply(passEvent(pb::MT_UPDATE, 42, 7, 4, 3), 600);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionCurrent), 2.0);
    // Removed after its last waypoint: fully processed.
    o = t.apply(passEvent(pb::MT_DELETE, 42, 0, 0), 700);
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionState), double(MissionState::Complete));
    QCOMPARE(fieldIn(o.batch, TelemetryField::MissionReached), 3.0);
    // Malformed: each dropped with its reason.
    auto bad = passEvent(pb::MT_UPDATE, 43, 7, 3, 3);
    o = t.apply(bad, 800);
    QCOMPARE(o.kind, Kind::Dropped);
    QVERIFY2(o.reason.contains(QLatin1String("outside the route's 3 waypoints")), qPrintable(o.reason));
    bad.mutable_object()->mutable_routepass()->clear_vehicle();
    QVERIFY(t.apply(bad, 800).reason.contains(QLatin1String("names no vehicle")));
    bad = passEvent(pb::MT_CREATE, 44, 7, 0);
    QVERIFY(t.apply(bad, 800).reason.contains(QLatin1String("no waypoint count")));
    bad.mutable_object()->Clear();
    QVERIFY(t.apply(bad, 800).reason.contains(QLatin1String("carries no RoutePass")));
    bad.set_objecttype("Route");
    QCOMPARE(t.apply(bad, 800).kind, Kind::Dropped);
}

void TstHciVehicleLink::routePassFollowsTheFlight()
{
    Server sim;
    Operator op(sim.server.port(), "admin", "admin");
    QTRY_VERIFY(op.session.isReady());
    HciVehicleLink link(&op.client, op.vehicle("EMU-102")), other(&op.client, op.vehicle("EMU-101"));
    Vehicle v(&link), bystander(&other);
    QSignalSpy batches(&link, &VehicleLink::telemetryReceived);
    link.start();
    other.start();
    QTRY_VERIFY(v.isConnected() && v.position().isValid());
    // Three short legs from where the vehicle stands.
    const QGeoCoordinate at = v.position();
    auto step = [&](double east) { return at.atDistanceAndAzimuth(east, 90); };
    const QGeoCoordinate a = step(12), b = step(24), c = step(36);
    Prepared prepared;
    link.prepareMission(routeOf({{a.latitude(), a.longitude(), 12, 8}, {b.latitude(), b.longitude(), 12, 8},
                                 {c.latitude(), c.longitude(), 12, 8}}), prepared.callback());
    QTRY_VERIFY_WITH_TIMEOUT(prepared.done, 15000);
    QVERIFY2(prepared.result.ok, qPrintable(prepared.result.message));
    const int count = int(prepared.mission.items.size());
    Result upload;
    link.uploadMission(prepared.mission, {}, upload.callback());
    QTRY_VERIFY_WITH_TIMEOUT(upload.done, 15000);
    QVERIFY2(upload.result.ok, qPrintable(upload.result.message));
    // The server's RoutePass: on board, not yet flown.
    QTRY_COMPARE(v.missionCount(), count);
    QCOMPARE(v.missionCurrent(), -1);
    QCOMPARE(sim.world.store().list(QStringLiteral("RoutePass")).size(), size_t(1));

    Result arm, fly;
    link.arm(true, arm.callback());
    QTRY_VERIFY(arm.done);
    QVERIFY2(arm.result.ok, qPrintable(arm.result.message));
    link.setMode(FlightMode::Auto, fly.callback());
    QTRY_VERIFY(fly.done);
    QVERIFY2(fly.result.ok, qPrintable(fly.result.message));
    // The active waypoint advances through every waypoint, then the route is fully processed.
    QTRY_COMPARE_WITH_TIMEOUT(v.missionState(), QStringLiteral("complete"), 30000);
    QList<int> expected{-1}; // on board, then each waypoint in turn, then done
    for (int i = 0; i < count; ++i)
        expected << i;
    expected << -1;
    QCOMPARE(missionCurrents(batches), expected);
    QCOMPARE(v.missionCurrent(), -1);
    QVERIFY(sim.world.store().list(QStringLiteral("RoutePass")).empty());
    // The other vehicle's link saw every event and took none of them.
    QVERIFY(!bystander.last(TelemetryField::MissionCurrent).has_value());
    QVERIFY(bystander.lastError().isEmpty());
}

void TstHciVehicleLink::routePassMalformedIsDropped()
{
    Server sim;
    Operator op(sim.server.port(), "admin", "admin");
    QTRY_VERIFY(op.session.isReady());
    HciVehicleLink link(&op.client, op.vehicle("EMU-103"));
    Vehicle v(&link);
    QSignalSpy errors(&link, &VehicleLink::errorOccurred);
    link.start();
    QTRY_VERIFY(v.isConnected());
    // A pass the server publishes with an index past its own count (written straight into the
    // simulator's store, which publishes it as it would any change).
    pb::DomainObjectWrapper w;
    auto *pass = w.mutable_routepass();
    pass->mutable_vehicle()->set_id(link.vehicleObjectId());
    pass->set_waypointcount(4);
    pass->set_waypointindex(9);
    QVERIFY(sim.world.store().save(QStringLiteral("RoutePass"), w, 1).object);
    QTRY_COMPARE(errors.count(), 1);
    QVERIFY2(errors.at(0).at(0).toString().contains(QLatin1String("waypoint index 9 is outside the route's 4 waypoints")),
             qPrintable(errors.at(0).at(0).toString()));
    QVERIFY(!v.last(TelemetryField::MissionCurrent).has_value()); // nothing of it was taken
    // The stream goes on: a well-formed pass for this vehicle is followed.
    pass->set_waypointindex(1);
    QVERIFY(sim.world.store().save(QStringLiteral("RoutePass"), w, 2).object);
    QTRY_COMPARE(v.missionCurrent(), 1);
    QCOMPARE(v.missionCount(), 4);
    QCOMPARE(errors.count(), 1);
}

QTEST_GUILESS_MAIN(TstHciVehicleLink)
#include "tst_hcivehiclelink.moc"
