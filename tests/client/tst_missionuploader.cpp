// MissionUploader, the one path from a route to a vehicle, against the simulators over loopback: the
// UgCS server (HCI: processing, the vehicle's lock, another session's lock, a server that goes away
// mid-upload) and a simulated VCI vehicle (PUT, read back with GET, then flown on auto). Every upload
// and command lands in the fleet's command log.
#include "ConnectionController.h"
#include "ElevationService.h"
#include "ElevationSetup.h"
#include "HciClient.h"
#include "HciReply.h"
#include "MissionUploader.h"
#include "SimFixture.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "SimVehicle.h"
#include "VciVehicleLink.h"
#include "VehicleFleet.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using client::MissionUploader;
using client::VehicleFleet;
using State = MissionUploader::State;

namespace {

mission::Waypoint waypoint(double lat, double lon, double altitude, double speed = 6)
{
    mission::Waypoint w;
    w.position = {lat, lon};
    w.altitude = altitude;
    w.speed = speed;
    return w;
}

// Three waypoints near the simulators' home (Riga), inside every limit of the route's settings.
mission::Route goodRoute()
{
    mission::Route r;
    r.settings.name = QStringLiteral("Uploader test");
    r.segments = {waypoint(56.9500, 24.1050, 30), waypoint(56.9503, 24.1056, 35), waypoint(56.9506, 24.1050, 30)};
    return r;
}

// One operator with a fleet: the server's vehicles, and VCI vehicles added by address, which take
// the ground under their routes from the server, as the program sets it up.
struct Operator
{
    Operator(const QString &address, const QString &user, const QString &password)
        : client(&session)
        , connection(&session)
        , elevation(&session)
        , fleet(&client, elevation.service())
    {
        elevation.configure(QString());
        uploader.setCommandLog(fleet.commandLog());
        QSignalSpy ready(&connection, &client::ConnectionController::ready);
        connection.connectToServer(address, user, password);
        ok = ready.wait(10000);
    }
    vehicle::Vehicle *hciVehicle(const QString &name)
    {
        for (int row = 0; row < fleet.count(); ++row) {
            if (fleet.vehicleAt(row)->protocol() == QLatin1String("HCI") && fleet.vehicleAt(row)->name() == name)
                return fleet.vehicleAt(row);
        }
        return nullptr;
    }
    hci::HciSession session;
    hci::HciClient client;
    client::ConnectionController connection;
    terrain::ElevationSetup elevation;
    VehicleFleet fleet;
    MissionUploader uploader;
    bool ok = false;
};

} // namespace

class TestMissionUploader : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::SimFixture> m_sim;
    std::unique_ptr<Operator> m_op;
    QList<State> m_states;

    vehicle::Vehicle *emu(const QString &name = QStringLiteral("EMU-101"))
    {
        QDeadlineTimer deadline(10000);
        while ((!m_op->hciVehicle(name) || !m_op->hciVehicle(name)->isConnected()) && !deadline.hasExpired())
            QTest::qWait(10);
        return m_op->hciVehicle(name);
    }
    const sim::SimVehicle *simVehicle(vehicle::Vehicle *v) { return m_sim->world.vehicle(v->id().toInt()); }
    // A request through the operator's one connection, answered: whatever the client sent before it
    // has reached the simulated server, which handles requests as they arrive on the stream. So
    // "nothing was sent" is proved by what arrived before this answer, not by a pause.
    bool roundTrip()
    {
        hci::HciReply *reply = m_op->client.listObjects(hci::HciObjectType::Vehicle);  // deletes itself once finished
        QSignalSpy done(reply, &hci::HciReply::finished);
        return done.wait(10000);
    }
    const vehicle::CommandLog::Entry &lastLogged() { return m_op->fleet.commandLog()->at(m_op->fleet.commandLog()->count() - 1); }

private slots:
    void init()
    {
        m_sim = std::make_unique<test::SimFixture>();
        m_op = std::make_unique<Operator>(m_sim->address(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(m_op->ok);
        m_states.clear();
        connect(&m_op->uploader, &MissionUploader::stateChanged, this, [this] {
            if (m_states.isEmpty() || m_states.last() != m_op->uploader.state())
                m_states.append(m_op->uploader.state());
        });
    }

    void cleanup()
    {
        m_op.reset();
        m_sim.reset();
    }

    void hciUploadGoesThroughEveryStep()
    {
        vehicle::Vehicle *v = emu();
        QVERIFY(v);
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        QSignalSpy uploaded(&m_op->uploader, &MissionUploader::uploaded);
        QSignalSpy missionChanged(v, &vehicle::Vehicle::missionChanged);
        QVERIFY(m_op->uploader.start(goodRoute(), v));
        QVERIFY(!m_op->uploader.start(goodRoute(), v)); // one at a time
        QVERIFY(finished.wait(15000));
        QCOMPARE(finished.first().first().toBool(), true);
        QCOMPARE(m_op->uploader.state(), State::Done);
        QCOMPARE(m_states, (QList<State>{State::Validating, State::Processing, State::Locking, State::Uploading, State::Releasing, State::Done}));
        QCOMPARE(uploaded.count(), 1);
        // The vehicle holds it (the server's plan), the fly view has it, the lock is free again.
        const auto &held = simVehicle(v)->model().mission();
        QVERIFY(held.size() >= 3);
        QCOMPARE(v->mission().size(), held.size());
        QCOMPARE(missionChanged.count(), 1);
        QVERIFY(std::abs(v->mission().back().latitude - held.back().latitude) < 1e-9);
        QVERIFY(!m_sim->world.locks().holder(QStringLiteral("Vehicle"), v->id().toInt()));
        QVERIFY2(m_op->uploader.message().startsWith(QStringLiteral("Uploaded to EMU-101: ")), qPrintable(m_op->uploader.message()));
        QCOMPARE(lastLogged().vehicle, QStringLiteral("EMU-101"));
        QCOMPARE(lastLogged().command, QStringLiteral("upload \"Uploader test\""));
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Done);
        QVERIFY(lastLogged().answered >= lastLogged().sent);
    }

    void refusedOnAValidationError()
    {
        vehicle::Vehicle *v = emu();
        mission::Route route = goodRoute();
        std::get<mission::Waypoint>(route.segments[1]).speed = 0; // an error: the speed must be positive
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        QVERIFY(m_op->uploader.start(route, v));
        QCOMPARE(m_op->uploader.state(), State::Failed);
        QCOMPARE(finished.count(), 1);
        QCOMPARE(m_op->uploader.culprit(), 1);
        QVERIFY2(m_op->uploader.message().startsWith(QStringLiteral("Not uploaded: Waypoint 2: ")), qPrintable(m_op->uploader.message()));
        QCOMPARE(m_states, (QList<State>{State::Validating, State::Failed}));
        QVERIFY(roundTrip()); // nothing is on its way to the vehicle either
        QVERIFY(simVehicle(v)->model().mission().empty());
        QVERIFY(v->mission().empty());
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Failed);
    }

    void warningsAndUnsavedEditsAskOnce()
    {
        vehicle::Vehicle *v = emu();
        mission::Route route = goodRoute();
        std::get<mission::Waypoint>(route.segments[2]).altitude = 10; // below the safe altitude: a warning
        QVERIFY(m_op->uploader.start(route, v, true));
        QCOMPARE(m_op->uploader.state(), State::AwaitingConfirmation);
        const QString question = m_op->uploader.question();
        QVERIFY2(question.contains(QLatin1String("not saved")), qPrintable(question));
        QVERIFY2(question.contains(QLatin1String("Waypoint 3: altitude")), qPrintable(question));
        QVERIFY2(question.endsWith(QLatin1String("Upload to EMU-101?")), qPrintable(question));
        QVERIFY(m_op->uploader.hasUnsavedEdits());
        QVERIFY(roundTrip());
        QVERIFY(simVehicle(v)->model().mission().empty()); // nothing goes before the answer
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        m_op->uploader.confirm();
        QVERIFY(finished.wait(15000));
        QCOMPARE(m_op->uploader.state(), State::Done);
        QVERIFY(m_op->uploader.question().isEmpty());
        QVERIFY(!simVehicle(v)->model().mission().empty());
    }

    void refusedWhileAnotherSessionHoldsTheLock()
    {
        vehicle::Vehicle *v = emu(QStringLiteral("EMU-102"));
        QVERIFY(v);
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        hci::HciReply *lock = bob.client.acquireLock(hci::HciObjectType::Vehicle, v->id().toInt());
        QSignalSpy locked(lock, &hci::HciReply::finished);
        QVERIFY(locked.wait(10000));
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        QVERIFY(m_op->uploader.start(goodRoute(), v));
        QVERIFY(finished.wait(15000));
        QCOMPARE(m_op->uploader.state(), State::Failed);
        QVERIFY2(m_op->uploader.message().contains(QLatin1String("cannot take control of EMU-102")), qPrintable(m_op->uploader.message()));
        QVERIFY2(m_op->uploader.message().contains(QLatin1String("bob")), qPrintable(m_op->uploader.message()));
        QVERIFY(!m_states.contains(State::Uploading));
        QVERIFY(simVehicle(v)->model().mission().empty());
        QVERIFY(v->mission().empty());
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Failed);
    }

    void serverGoneMidUploadIsAFailureNeverDone()
    {
        vehicle::Vehicle *v = emu();
        m_sim->server.setUploadStepMs(300); // a slow transfer, so that it can be cut
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        QSignalSpy uploaded(&m_op->uploader, &MissionUploader::uploaded);
        QVERIFY(m_op->uploader.start(goodRoute(), v));
        QTRY_COMPARE_WITH_TIMEOUT(m_op->uploader.state(), State::Uploading, 10000);
        QVERIFY(!m_op->uploader.canCancel()); // too late: it is being sent
        m_sim->server.close();
        m_sim->server.dropConnections();
        QVERIFY(finished.wait(15000));
        QCOMPARE(finished.first().first().toBool(), false);
        QCOMPARE(m_op->uploader.state(), State::Failed);
        QVERIFY2(m_op->uploader.message().startsWith(QStringLiteral("Upload to EMU-101 failed")), qPrintable(m_op->uploader.message()));
        QCOMPARE(uploaded.count(), 0);
        QVERIFY(!m_states.contains(State::Done));
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Failed);
    }

    void cancelBeforeAnythingIsSent()
    {
        vehicle::Vehicle *v = emu();
        // While asking.
        mission::Route route = goodRoute();
        QVERIFY(m_op->uploader.start(route, v, true));
        QVERIFY(m_op->uploader.canCancel());
        m_op->uploader.cancel();
        QCOMPARE(m_op->uploader.state(), State::Cancelled);
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Cancelled);
        // While the server processes it: the answer that comes later changes nothing.
        QVERIFY(m_op->uploader.start(route, v));
        QCOMPARE(m_op->uploader.state(), State::Processing);
        m_op->uploader.cancel();
        QCOMPARE(m_op->uploader.state(), State::Cancelled);
        // While taking the lock: the lock is taken, nothing is sent, the lock is given back.
        m_states.clear();
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        bool cancelledWhileLocking = false;
        connect(&m_op->uploader, &MissionUploader::stateChanged, this, [&] {
            if (m_op->uploader.state() == State::Locking && m_op->uploader.canCancel()) {
                m_op->uploader.cancel();
                cancelledWhileLocking = !m_op->uploader.canCancel() && m_op->uploader.state() == State::Locking;
            }
        });
        QVERIFY(m_op->uploader.start(route, v));
        QVERIFY(finished.wait(10000));
        QVERIFY(cancelledWhileLocking); // the answer to the lock request was still to come
        QCOMPARE(m_op->uploader.state(), State::Cancelled);
        QVERIFY(!m_states.contains(State::Uploading));
        QVERIFY(simVehicle(v)->model().mission().empty());
        QVERIFY(v->mission().empty());
        QTRY_VERIFY(!m_sim->world.locks().holder(QStringLiteral("Vehicle"), v->id().toInt()));
    }

    void vciUploadVerifiedThenFlown()
    {
        sim::SimVciOptions options;
        options.id = QStringLiteral("vci-up");
        options.name = QStringLiteral("Sim VCI up");
        options.telemetryRate = 25;
        options.timeScale = 10;
        options.homeLatitude = 56.9500;
        options.homeLongitude = 24.1050;
        sim::SimVciVehicle simVehicle(options);
        sim::SimVciListener listener(&simVehicle);
        QVERIFY(listener.listen(0));
        QVERIFY(m_op->fleet.addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port())));
        QTRY_VERIFY_WITH_TIMEOUT(m_op->fleet.vehicle(QStringLiteral("VCI:vci-up")), 10000);
        vehicle::Vehicle *v = m_op->fleet.vehicle(QStringLiteral("VCI:vci-up"));
        QTRY_VERIFY_WITH_TIMEOUT(v->isConnected() && v->gpsFix() >= 3, 10000);

        mission::Route route = goodRoute();
        auto &second = std::get<mission::Waypoint>(route.segments[1]);
        second.acceptanceRadius = 3;
        second.actions = {mission::WaitAction{2.0, false}, mission::CameraTriggerAction{mission::TriggerState::SingleShot}};
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        QVERIFY(m_op->uploader.start(route, v));
        QVERIFY(finished.wait(15000));
        QVERIFY2(m_op->uploader.state() == State::Done, qPrintable(m_op->uploader.message()));
        // No lock on VCI; the mission was read back and matched before it counted as done.
        QCOMPARE(m_states, (QList<State>{State::Validating, State::Processing, State::Locking, State::Uploading, State::Verifying, State::Done}));
        const nlohmann::json held = *simVehicle.resource("/mission");
        QCOMPARE(held["waypoints"].size(), size_t(3));
        QCOMPARE(held["waypoints"][1]["acceptanceRadius"].get<double>(), 3.0);
        QCOMPARE(held["waypoints"][1]["actions"][0]["type"].get<std::string>(), std::string("wait"));
        QCOMPARE(held["waypoints"][1]["actions"][1]["state"].get<std::string>(), std::string("single"));
        QCOMPARE(v->mission().size(), size_t(3));
        QCOMPARE(v->mission()[1].actions.size(), size_t(2));
        QCOMPARE(lastLogged().command, QStringLiteral("upload \"Uploader test\""));
        QCOMPARE(lastLogged().status, vehicle::CommandLog::Status::Done);

        // Fly it through the command policy: arm, take off (the vehicle's own altitude), auto.
        client::CommandPolicy &policy = *m_op->fleet.commands();
        QTRY_VERIFY(!v->parameters().isEmpty());
        QCOMPARE(policy.takeoffAltitude(v), v->parameters().value(QStringLiteral("takeoff_altitude")).toDouble());
        QVERIFY(policy.needsConfirmation(client::CommandPolicy::Command::Auto, v));
        QVERIFY2(policy.confirmation(client::CommandPolicy::Command::Auto, v).contains(QLatin1String("3 waypoint(s)")), qPrintable(policy.confirmation(client::CommandPolicy::Command::Auto, v)));
        QSignalSpy commands(v, &vehicle::Vehicle::commandFinished);
        QVERIFY(policy.send(client::CommandPolicy::Command::Arm, v));
        QTRY_COMPARE(commands.count(), 1);
        QVERIFY2(commands.last().at(1).toBool(), qPrintable(commands.last().at(2).toString()));
        QVERIFY(policy.send(client::CommandPolicy::Command::TakeOff, v));
        QTRY_COMPARE(commands.count(), 2);
        QVERIFY2(commands.last().at(1).toBool(), qPrintable(commands.last().at(2).toString()));
        QVERIFY(policy.send(client::CommandPolicy::Command::Auto, v));
        QTRY_COMPARE(commands.count(), 3);
        QVERIFY2(commands.last().at(1).toBool(), qPrintable(commands.last().at(2).toString()));
        // The vehicle advances through the mission, waits at the second waypoint, and completes it.
        QTRY_VERIFY_WITH_TIMEOUT(v->missionCurrent() >= 1, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(v->missionCurrent() >= 2, 20000);
        QTRY_COMPARE_WITH_TIMEOUT(v->missionState(), QStringLiteral("complete"), 30000);
        QVERIFY(std::abs(v->position().latitude() - 56.9506) < 1e-4);

        // The command log has every command with its result, in order, with the vehicle.
        const vehicle::CommandLog &log = *m_op->fleet.commandLog();
        QStringList seen;
        for (int row = 0; row < log.count(); ++row) {
            if (log.at(row).vehicle == QLatin1String("Sim VCI up"))
                seen << log.at(row).command + QLatin1Char('=') + vehicle::CommandLog::statusText(log.at(row).status);
        }
        const QString takeoff = QStringLiteral("takeoff to %1 m=done").arg(policy.takeoffAltitude(v));
        QCOMPARE(seen, (QStringList{QStringLiteral("upload \"Uploader test\"=done"), QStringLiteral("arm=done"), takeoff,
                                    QStringLiteral("mode auto=done")}));
    }

    // A VCI vehicle flies heights above its home (the vehicle's own /telemetry/home): AGL ones go up
    // through the ground under them (from the server here), AMSL ones less the home's altitude; what has no VCI form is refused naming the waypoint, before
    // anything is sent.
    void vciHeightsAboveHomeAndRefusalNamesTheWaypoint()
    {
        sim::SimVciVehicle simVehicle(sim::SimVciOptions{});
        sim::SimVciListener listener(&simVehicle);
        QVERIFY(listener.listen(0));
        QVERIFY(m_op->fleet.addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port())));
        vehicle::Vehicle *v = m_op->fleet.vehicleAt(m_op->fleet.count() - 1);
        QTRY_VERIFY_WITH_TIMEOUT(v->isConnected(), 10000);
        const double homeAmsl = sim::SimVciOptions{}.groundElevation;
        QSignalSpy finished(&m_op->uploader, &MissionUploader::finished);
        // AGL: the ground under each waypoint comes from the server (asked while the upload waits).
        mission::Route route = goodRoute();
        QVERIFY(m_op->uploader.start(route, v));
        QVERIFY(finished.wait(10000));
        QCOMPARE(m_op->uploader.state(), State::Done);
        QVERIFY2(!m_op->uploader.message().contains(QLatin1String("Note:")), qPrintable(m_op->uploader.message()));
        const std::optional<double> ground = m_op->elevation.service()->groundAt(std::get<mission::Waypoint>(route.segments[1]).position);
        QVERIFY(ground);
        QCOMPARE(simVehicle.model().mission()[1].altitudeAgl, *ground + 35 - homeAmsl);

        for (auto &s : route.segments)
            std::get<mission::Waypoint>(s).altitudeType = mission::AltitudeType::Amsl; // one type: no mixed-type warning
        std::get<mission::Waypoint>(route.segments[1]).altitude = 60;
        QVERIFY(m_op->uploader.start(route, v));
        if (m_op->uploader.state() == State::AwaitingConfirmation) // AMSL altitudes cannot be checked: a warning
            m_op->uploader.confirm();
        QVERIFY(finished.wait(10000));
        QCOMPARE(m_op->uploader.state(), State::Done);
        QCOMPARE(simVehicle.model().mission().size(), route.segments.size());
        QCOMPARE(simVehicle.model().mission()[1].altitudeAgl, 60 - homeAmsl);

        // A wait for the operator cannot be released on a vehicle flying alone.
        std::get<mission::Waypoint>(route.segments[1]).actions = {mission::WaitAction{0, true}};
        QVERIFY(m_op->uploader.start(route, v));
        if (m_op->uploader.state() == State::AwaitingConfirmation)
            m_op->uploader.confirm();
        QVERIFY(finished.wait(10000));
        QCOMPARE(m_op->uploader.state(), State::Failed);
        QVERIFY2(m_op->uploader.message().contains(QLatin1String("Waypoint 2: a wait for the operator")), qPrintable(m_op->uploader.message()));
        QCOMPARE(simVehicle.model().mission()[1].altitudeAgl, 60 - homeAmsl);  // the mission before stays
    }
};

QTEST_MAIN(TestMissionUploader)
#include "tst_missionuploader.moc"
