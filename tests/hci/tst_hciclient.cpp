// HciClient's typed calls against the simulated server: objects (listed, created, updated, deleted,
// with the events a second session sees), locks between two sessions, commands that fly a vehicle,
// route processing with validation, upload with progress, live telemetry and its history.
#include "HciClient.h"
#include "HciSubscription.h"
#include "HciTestSupport.h"
#include "Messages.pb.h"
#include "SimVehicle.h"

#include <QtTest>

#include <cmath>

using namespace sortie;
using hci::HciClient;
using hci::HciError;
using hci::HciObjectType;
using hci::HciSession;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;
constexpr const char *kWaypointAlgorithm = "com.ugcs.ucs.service.routing.impl.WaypointAlgorithm";

struct Client
{
    Client(quint16 port, const char *login = "admin", const char *password = "admin")
        : client(&session)
    {
        session.open(QStringLiteral("127.0.0.1"), port, QString::fromLatin1(login), QString::fromLatin1(password));
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

pb::Vehicle vehicleNamed(HciClient &client, const std::string &name)
{
    const auto list = call<pb::GetObjectListResponse>(client.listObjects(HciObjectType::Vehicle));
    for (const auto &w : list.objects())
        if (w.vehicle().name() == name)
            return w.vehicle();
    return {};
}

pb::SegmentDefinition waypoint(double latDeg, double lonDeg, double agl, const char *speed)
{
    pb::SegmentDefinition s;
    s.set_algorithmclassname(kWaypointAlgorithm);
    s.mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s.mutable_figure()->add_points();
    p->set_latitude(latDeg * kRad);
    p->set_longitude(lonDeg * kRad);
    p->set_aglaltitude(agl);
    p->set_altitudetype(pb::AT_AGL);
    auto *v = s.add_parametervalues();
    v->set_name("speed");
    v->set_value(speed);
    return s;
}

pb::Route route(const pb::Vehicle &vehicle, double thirdAltitude = 40)
{
    pb::Route r;
    r.set_name("Pier survey");
    *r.mutable_vehicleprofile() = vehicle.profile();
    r.set_maxaltitude(100);
    r.set_safealtitude(20);
    r.set_initialspeed(5);
    r.set_maxspeed(10);
    *r.add_segments() = waypoint(56.9763, 24.0731, 30, "5.0");
    *r.add_segments() = waypoint(56.9772, 24.0745, 40, "6.0");
    *r.add_segments() = waypoint(56.9768, 24.0760, thirdAltitude, "6.0");
    return r;
}

// The last value of a telemetry field seen in events, by code.
struct TelemetryWatch
{
    QHash<QString, pb::Value> last;
    qint64 lastTime = 0;
    void take(const pb::EventWrapper &e, int vehicleId)
    {
        if (!e.has_telemetryevent() || e.telemetryevent().vehicle().id() != vehicleId)
            return;
        for (const auto &t : e.telemetryevent().telemetry()) {
            last[QString::fromStdString(t.telemetryfield().code())] = t.value();
            lastTime = t.time();
        }
    }
    double number(const char *code) const
    {
        const pb::Value v = last.value(QLatin1String(code));
        return v.has_doublevalue() ? v.doublevalue() : v.has_floatvalue() ? v.floatvalue() : v.intvalue();
    }
    QString text(const char *code) const { return QString::fromStdString(last.value(QLatin1String(code)).stringvalue()); }
};

} // namespace

class TestHciClient : public QObject
{
    Q_OBJECT

private slots:
    void listsWhatTheServerOffers()
    {
        test::SimServer sim;
        Client a(sim.port());
        QVERIFY(a.ready());
        const auto vehicles = call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::Vehicle));
        QCOMPARE(vehicles.objecttype(), std::string("Vehicle"));
        QStringList names;
        for (const auto &w : vehicles.objects())
            names << QString::fromStdString(w.vehicle().name());
        QCOMPARE(names, (QStringList{"EMU-101", "EMU-102", "EMU-103"}));
        QCOMPARE(vehicles.objects(0).vehicle().profile().name(), std::string("EMU Copter"));

        const auto users = call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::User));
        QCOMPARE(users.objects_size(), 2);
        for (const auto &w : users.objects())
            QVERIFY(!w.user().has_password());
        const auto algorithms = call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::TraverseAlgorithm));
        QCOMPARE(algorithms.objects(0).traversealgorithm().implementationclass(), std::string(kWaypointAlgorithm));
        QVERIFY(call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::VehicleProfile)).objects_size() >= 1);
        QVERIFY(call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::Mission)).objects_size() >= 1);

        const auto commands = call<pb::GetObjectListResponse>(a.client.listObjects(HciObjectType::CommandDefinition));
        QSet<QString> codes;
        for (const auto &w : commands.objects())
            if (w.commanddefinition().vehicle().name() == "EMU-101")
                codes.insert(QString::fromStdString(w.commanddefinition().code()));
        for (const char *code : {"arm", "disarm", "takeoff_command", "auto", "mission_pause", "mission_resume", "land_command",
                                 "return_to_home", "waypoint", "manual"})
            QVERIFY2(codes.contains(QLatin1String(code)), code);

        // A renamed vehicle is renamed in its telemetry too.
        pb::Vehicle renamed = vehicles.objects(2).vehicle();
        renamed.set_name("EMU-103 (north pier)");
        QCOMPARE(call<pb::CreateOrUpdateObjectResponse>(a.client.createOrUpdate(renamed)).object().vehicle().version(), 2);
        QCOMPARE(sim.world.vehicle(renamed.id())->reference().name(), renamed.name());

        HciError error;
        call<pb::GetObjectResponse>(a.client.getObject(HciObjectType::Route, 99999), &error);
        QCOMPARE(error.kind(), HciError::Kind::Server);
        QVERIFY(error.message().contains(QLatin1String("Route 99999 does not exist")));
    }

    void changesReachASecondSession()
    {
        test::SimServer sim;
        Client a(sim.port()), b(sim.port(), "bob", "s3cret-bob");
        QVERIFY(a.ready() && b.ready());
        QList<pb::ObjectModificationEvent> seen;
        auto *routes = b.client.subscribeObjectChanges(HciObjectType::Route);
        connect(routes, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) { seen.append(e.objectmodificationevent()); });
        QTRY_VERIFY(routes->isActive());

        const pb::Vehicle emu = vehicleNamed(a.client, "EMU-101");
        auto created = call<pb::CreateOrUpdateObjectResponse>(a.client.createOrUpdate(route(emu))).object().route();
        QVERIFY(created.id() > 0);
        QCOMPARE(created.version(), 1);
        QCOMPARE(created.segments_size(), 3);
        QVERIFY(created.segments(0).id() > 0 && !created.segments(0).uuid().empty());
        QTRY_COMPARE(seen.size(), 1);
        QCOMPARE(seen[0].modificationtype(), pb::MT_CREATE);
        QCOMPARE(seen[0].objectid(), created.id());
        QCOMPARE(seen[0].object().route().name(), std::string("Pier survey"));

        pb::Route renamed = created;
        renamed.set_name("Pier survey, north");
        const auto updated = call<pb::CreateOrUpdateObjectResponse>(a.client.createOrUpdate(renamed)).object().route();
        QCOMPARE(updated.version(), 2);
        QTRY_COMPARE(seen.size(), 2);
        QCOMPARE(seen[1].modificationtype(), pb::MT_UPDATE);
        QCOMPARE(seen[1].object().route().name(), std::string("Pier survey, north"));

        // Bob still holds version 1: his save is refused rather than overwriting Alice's.
        HciError stale;
        call<pb::CreateOrUpdateObjectResponse>(b.client.createOrUpdate(created), &stale);
        QVERIFY2(stale.message().contains(QLatin1String("changed by someone else")), qPrintable(stale.message()));

        pb::Route fields;
        fields.set_id(created.id());
        fields.set_safealtitude(35);
        const auto patched = call<pb::UpdateObjectFieldsResponse>(a.client.updateFields(fields, {"safeAltitude"})).object().route();
        QCOMPARE(patched.safealtitude(), 35.0);
        QCOMPARE(patched.name(), std::string("Pier survey, north"));
        QCOMPARE(patched.version(), 3);
        QTRY_COMPARE(seen.size(), 3);

        const auto deleted = call<pb::DeleteObjectResponse>(a.client.deleteObject(HciObjectType::Route, created.id()));
        QCOMPARE(deleted.objectid(), created.id());
        QTRY_COMPARE(seen.size(), 4);
        QCOMPARE(seen[3].modificationtype(), pb::MT_DELETE);
        QCOMPARE(seen[3].objectid(), created.id());
    }

    void locksKeepTwoSessionsApart()
    {
        test::SimServer sim;
        Client a(sim.port()), b(sim.port(), "bob", "s3cret-bob");
        QVERIFY(a.ready() && b.ready());
        const pb::Vehicle emu = vehicleNamed(a.client, "EMU-102");
        QList<pb::LockEvent> events;
        auto *locks = b.client.subscribeLocks(HciObjectType::Vehicle);
        connect(locks, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) { events.append(e.lockevent()); });
        QTRY_VERIFY(locks->isActive());

        HciError error;
        call<pb::AcquireLockResponse>(a.client.acquireLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
        QTRY_COMPARE(events.size(), 1);
        QCOMPARE(events[0].lock().owner().login(), std::string("admin"));

        call<pb::AcquireLockResponse>(b.client.acquireLock(HciObjectType::Vehicle, emu.id()), &error);
        QCOMPARE(error.kind(), HciError::Kind::Server);
        QVERIFY2(error.message().contains(QLatin1String("locked by user 'admin'")), qPrintable(error.message()));
        const auto check = call<pb::CheckLockResponse>(b.client.checkLock(HciObjectType::Vehicle, emu.id()));
        QCOMPARE(check.lock().owner().login(), std::string("admin"));
        const auto refused = call<pb::SendCommandResponse>(b.client.sendCommand(emu, QStringLiteral("arm")));
        QCOMPARE(refused.commandresults(0).commandstatus(), pb::CS_REJECTED);

        // Bob's release of Alice's lock does nothing (ifExclusive); hers frees it for him.
        call<pb::ReleaseLockResponse>(b.client.releaseLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
        QVERIFY(call<pb::CheckLockResponse>(b.client.checkLock(HciObjectType::Vehicle, emu.id())).has_lock());
        call<pb::ReleaseLockResponse>(a.client.releaseLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
        QTRY_COMPARE(events.size(), 2);
        QVERIFY(!events[1].has_lock());
        call<pb::AcquireLockResponse>(b.client.acquireLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
    }

    void commandsFlyTheVehicle()
    {
        test::SimServer sim;
        Client a(sim.port());
        QVERIFY(a.ready());
        const pb::Vehicle emu = vehicleNamed(a.client, "EMU-103");
        TelemetryWatch watch;
        auto *telemetry = a.client.subscribeTelemetry(emu.id());
        connect(telemetry, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) { watch.take(e, emu.id()); });
        QList<pb::CommandEvent> commandEvents;
        auto *commands = a.client.subscribeCommands(emu);
        connect(commands, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) { commandEvents.append(e.commandevent()); });
        QTRY_COMPARE(commandEvents.size(), 1); // the vehicle's commands as they stand
        QCOMPARE(commandEvents[0].vehicle().id(), emu.id());

        auto status = [&](const char *code, QVariantMap args = {}) {
            return call<pb::SendCommandResponse>(a.client.sendCommand(emu, QString::fromLatin1(code), args)).commandresults(0);
        };
        QCOMPARE(status("takeoff_command").commandstatus(), pb::CS_FAILED); // not armed yet
        QCOMPARE(status("arm").commandstatus(), pb::CS_SUCCEEDED);
        QTRY_COMPARE(watch.last.value(QStringLiteral("is_armed")).boolvalue(), true);
        QTRY_VERIFY(commandEvents.size() >= 2); // arming changed what is available
        QCOMPARE(status("takeoff_command", {{"altitude_agl", 8.0}}).commandstatus(), pb::CS_SUCCEEDED);
        QTRY_VERIFY_WITH_TIMEOUT(watch.number("altitude_agl") > 5, 15000);
        QCOMPARE(watch.text("flight_mode").isEmpty(), false);

        // Click & go: latitude and longitude in radians.
        const double lat = watch.number("latitude"), lon = watch.number("longitude");
        const auto go = status("waypoint", {{"latitude", lat + 0.000003}, {"longitude", lon}, {"altitude_agl", 8.0}, {"ground_speed", 3.0}});
        QCOMPARE(go.commandstatus(), pb::CS_SUCCEEDED);
        QTRY_COMPARE(watch.text("flight_mode"), QStringLiteral("GUIDED"));
        QCOMPARE(int(watch.number("control_mode")), 2);

        QCOMPARE(status("land_command").commandstatus(), pb::CS_SUCCEEDED);
        QTRY_COMPARE(watch.text("flight_mode"), QStringLiteral("LAND"));
        const auto unknown = status("barrel_roll");
        QCOMPARE(unknown.commandstatus(), pb::CS_REJECTED);
        QVERIFY(unknown.errormessage().find("barrel_roll") != std::string::npos);
    }

    void processValidatesAndUploadReportsProgress()
    {
        test::SimServer sim;
        Client a(sim.port());
        QVERIFY(a.ready());
        const pb::Vehicle emu = vehicleNamed(a.client, "EMU-101");

        const auto bad = call<pb::ProcessRouteResponse>(a.client.processRoute(route(emu, 150))).processedroute();
        QCOMPARE(bad.segments(0).status(), pb::RPS_PROCESSED);
        QCOMPARE(bad.segments(2).status(), pb::RPS_INVALID);
        QCOMPARE(bad.segments(2).wrongpointnumber(), 0);
        QVERIFY(bad.segments(2).messageset().messages(0).defaulttext().find("maximum altitude") != std::string::npos);

        const auto processed = call<pb::ProcessRouteResponse>(a.client.processRoute(route(emu)));
        QVERIFY(!processed.hash().empty());
        const auto &good = processed.processedroute();
        for (const auto &s : good.segments())
            QCOMPARE(s.status(), pb::RPS_PROCESSED);
        QCOMPARE(good.segments(0).estimateddistance(), 0.0);
        QVERIFY(good.segments(1).estimateddistance() > 100 && good.segments(1).estimateddistance() < 150);
        QVERIFY(good.segments(1).estimatedtime() > good.segments(1).estimateddistance() / 6.0);
        QVERIFY(std::abs(good.estimateddistance() - good.segments(1).estimateddistance() - good.segments(2).estimateddistance()) < 1e-6);

        HciError error;
        call<pb::AcquireLockResponse>(a.client.acquireLock(HciObjectType::Vehicle, emu.id()), &error);
        QVERIFY(!error);
        auto upload = test::keep(a.client.uploadRoute(emu, good));
        QList<std::tuple<QString, int, int>> progress;
        connect(upload.get(), &hci::HciReply::progress, this,
                [&](const QString &title, int value, int max) { progress.append({title, value, max}); });
        QVERIFY(test::finishes(upload.get()));
        QVERIFY2(upload->isOk(), qPrintable(upload->error().toString()));
        QVERIFY(progress.size() >= 4);
        QCOMPARE(std::get<0>(progress.first()), QStringLiteral("Uploading route to EMU-101"));
        QCOMPARE(std::get<1>(progress.last()), std::get<2>(progress.last()));
        QCOMPARE(sim.world.vehicle(emu.id())->model().mission().size(), size_t(3));

        const auto invalidUpload = test::keep(a.client.uploadRoute(emu, bad));
        QVERIFY(test::finishes(invalidUpload.get()));
        QVERIFY(invalidUpload->error().message().contains(QLatin1String("Segment 3")));
    }

    void telemetryIsLiveAndKeptAsHistory()
    {
        test::SimServer sim;
        Client a(sim.port());
        QVERIFY(a.ready());
        const pb::Vehicle emu = vehicleNamed(a.client, "EMU-101");
        TelemetryWatch watch;
        auto *telemetry = a.client.subscribeTelemetry();
        QSet<int> vehicles;
        int batches = 0;
        connect(telemetry, &hci::HciSubscription::received, this, [&](const pb::EventWrapper &e) {
            vehicles.insert(e.telemetryevent().vehicle().id());
            batches += e.telemetryevent().vehicle().id() == emu.id();
            watch.take(e, emu.id());
        });
        QTRY_COMPARE(vehicles.size(), 3);
        QTRY_VERIFY(batches >= 4); // enough history for the query below
        QTRY_VERIFY(watch.last.contains(QStringLiteral("flight_mode")));
        // Radians, near Riga; times in ms since the epoch, now.
        QVERIFY(std::abs(watch.number("latitude") - 56.9762 * kRad) < 1e-4);
        QVERIFY(std::abs(watch.number("longitude") - 24.0730 * kRad) < 1e-4);
        QVERIFY(std::abs(watch.lastTime - QDateTime::currentMSecsSinceEpoch()) < 5000);
        for (const char *code : {"altitude_amsl", "altitude_agl", "ground_speed", "vertical_speed", "heading", "battery_voltage",
                                 "gps_fix_type", "satellite_count", "control_mode", "is_armed"})
            QVERIFY2(watch.last.contains(QLatin1String(code)), code);
        QCOMPARE(int(watch.number("gps_fix_type")), 3);

        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        // The simulator pages whole samples of its 17 fields (battery current and level among them).
        const auto history = call<pb::GetTelemetryResponse>(a.client.telemetryHistory(emu, now - 60000, now, 51));
        QCOMPARE(history.telemetry_size(), 51);
        QVERIFY(history.has_nexttelemetrytime());
        QVERIFY(history.telemetry(0).time() <= history.nexttelemetrytime());
        QCOMPARE(history.telemetry(0).telemetryfield().code(), std::string("latitude"));
    }
};

QTEST_MAIN(TestHciClient)
#include "tst_hciclient.moc"
