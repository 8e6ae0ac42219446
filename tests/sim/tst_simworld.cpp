// The simulator's parts on their own: the versioned object store and its JSON file (with errors that
// name the JSON path), accounts, locks, incremental telemetry batches and history, vehicle commands.
#include "FlightModel.h"
#include "Messages.pb.h"
#include "SimCommands.h"
#include "SimLockTable.h"
#include "SimObjectStore.h"
#include "SimStoreFile.h"
#include "SimTelemetry.h"
#include "SimUsers.h"
#include "SimVehicle.h"
#include "SimWorld.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::sim;
namespace pb = com::ugcs::ucs::proto;

namespace {

pb::DomainObjectWrapper mission(const char *name)
{
    pb::DomainObjectWrapper w;
    w.mutable_mission()->set_name(name);
    return w;
}

void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

} // namespace

class TestSimWorld : public QObject
{
    Q_OBJECT

private slots:
    void storeVersionsEverySave()
    {
        SimObjectStore store;
        QSignalSpy changes(&store, &SimObjectStore::changed);
        const auto created = store.save(QStringLiteral("Mission"), mission("A"), 1000);
        QVERIFY(created.created);
        const int id = created.object->mission().id();
        QCOMPARE(created.object->mission().version(), 1);
        QCOMPARE(created.object->mission().creationtime(), 1000);
        QVERIFY(!created.object->mission().uuid().empty());

        pb::DomainObjectWrapper edit = *created.object;
        edit.mutable_mission()->set_name("B");
        const auto updated = store.save(QStringLiteral("Mission"), edit, 2000);
        QVERIFY(!updated.created);
        QCOMPARE(updated.object->mission().version(), 2);
        QCOMPARE(updated.object->mission().creationtime(), 1000);

        const auto stale = store.save(QStringLiteral("Mission"), edit, 3000); // still says version 1
        QVERIFY(!stale.object);
        QVERIFY(stale.error.contains(QLatin1String("server version 2, yours 1")));
        QVERIFY(!store.save(QStringLiteral("Route"), edit, 0).error.isEmpty()); // wrapper holds no Route

        pb::DomainObjectWrapper ghost = mission("ghost");
        ghost.mutable_mission()->set_id(4242);
        QVERIFY(store.save(QStringLiteral("Mission"), ghost, 0).error.contains(QLatin1String("does not exist")));

        int version = 0;
        QVERIFY(store.remove(QStringLiteral("Mission"), id, &version));
        QCOMPARE(version, 2);
        QVERIFY(!store.remove(QStringLiteral("Mission"), id));
        QCOMPARE(changes.size(), 3);
        QCOMPARE(changes.at(2).at(0).toInt(), int(pb::MT_DELETE));
    }

    void storeFileRoundTrips()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("store.json"));
        SimObjectStore store;
        const int id = store.save(QStringLiteral("Mission"), mission("Kept"), 5).object->mission().id();
        QString error;
        QVERIFY2(SimStoreFile::save(path, store, &error), qPrintable(error));

        SimObjectStore loaded;
        QVERIFY2(SimStoreFile::load(path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.find(QStringLiteral("Mission"), id)->mission().name(), std::string("Kept"));
        QCOMPARE(loaded.nextId(), store.nextId()); // new objects never reuse an id
        QVERIFY(QFile(path).open(QIODevice::ReadOnly));
    }

    void badStoreFilesNameTheProblem()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.json"));
        SimObjectStore store;
        QString error;
        writeFile(path, "{\"format\": \"sortie-sim-store\", \"objects\": [");
        QVERIFY(!SimStoreFile::load(path, store, &error));
        QVERIFY2(error.startsWith(path) && error.contains(QLatin1String("not valid JSON")), qPrintable(error));

        writeFile(path, R"({"format": "sortie-sim-store", "objects": [{"type": "Mission", "object": {"mission": {"id": 3}}},
                            {"type": "Mission", "object": {"mission": {"id": "x"}}}]})");
        QVERIFY(!SimStoreFile::load(path, store, &error));
        QVERIFY2(error.contains(QLatin1String("objects[1].object")), qPrintable(error));

        writeFile(path, R"({"format": "sortie-sim-store", "objects": [{"type": "Mission", "object": {"route": {"id": 3}}}]})");
        QVERIFY(!SimStoreFile::load(path, store, &error));
        QVERIFY2(error.contains(QLatin1String("objects[0].object: holds no Mission")), qPrintable(error));

        writeFile(path, R"({"format": "something-else"})");
        QVERIFY(!SimStoreFile::load(path, store, &error));
        QVERIFY(error.contains(QLatin1String("format")));
    }

    void worldPersistsAcrossRestarts()
    {
        QTemporaryDir dir;
        SimWorld::Config config;
        config.storePath = dir.filePath(QStringLiteral("world.json"));
        config.telemetryRateHz = 0;
        int routeCount = 0, vehicleId = 0, missionId = 0;
        {
            SimWorld world(config);
            QVERIFY(world.start());
            vehicleId = world.vehicles().front()->id();
            missionId = world.store().save(QStringLiteral("Mission"), mission("Saved"), SimWorld::now()).object->mission().id();
            routeCount = int(world.store().list(QStringLiteral("Route")).size());
        }
        SimWorld again(config);
        QVERIFY(again.start());
        QCOMPARE(again.store().find(QStringLiteral("Mission"), missionId)->mission().name(), std::string("Saved"));
        QCOMPARE(int(again.store().list(QStringLiteral("Route")).size()), routeCount); // the demo route is not added twice
        QCOMPARE(again.vehicles().front()->id(), vehicleId);
        QCOMPARE(int(again.store().list(QStringLiteral("Vehicle")).size()), 3);
    }

    void accountsAndLocks()
    {
        QCOMPARE(SimUsers::parse(QStringLiteral("ops:pa:ss"))->password, QStringLiteral("pa:ss"));
        QVERIFY(!SimUsers::parse(QStringLiteral("nocolon")));
        const SimUsers users;
        QVERIFY(users.authenticate(QStringLiteral("admin"), QStringLiteral("admin")));
        QVERIFY(!users.authenticate(QStringLiteral("admin"), QStringLiteral("Admin")));

        SimLockTable locks;
        QSignalSpy changes(&locks, &SimLockTable::lockChanged);
        const SimLockTable::Owner alice{1, 1, QStringLiteral("alice")}, bob{2, 2, QStringLiteral("bob")};
        QVERIFY(!locks.acquire(QStringLiteral("Vehicle"), 5, alice).isError());
        QVERIFY(!locks.acquire(QStringLiteral("Vehicle"), 5, alice).isError()); // again: still hers
        const sortie::hci::HciError taken = locks.acquire(QStringLiteral("Vehicle"), 5, bob);
        QCOMPARE(taken.kind(), sortie::hci::HciError::Kind::Server);
        QVERIFY(taken.message().contains(QLatin1String("'alice'")));
        QVERIFY(!locks.release(QStringLiteral("Vehicle"), 5, bob.clientId, true).isError()); // not his: quietly nothing
        const sortie::hci::HciError notHis = locks.release(QStringLiteral("Vehicle"), 5, bob.clientId, false);
        QCOMPARE(notHis.kind(), sortie::hci::HciError::Kind::Server);
        QVERIFY(notHis.message().contains(QLatin1String("only they can release it")));
        QVERIFY(!locks.mayModify(QStringLiteral("Vehicle"), 5, bob.clientId));
        locks.releaseAll(alice.clientId);
        QVERIFY(locks.mayModify(QStringLiteral("Vehicle"), 5, bob.clientId));
        QCOMPARE(changes.size(), 2);
    }

    void telemetryBatchesAreIncremental()
    {
        SimTelemetry telemetry(10);
        FlightModel model(56.9762, 24.0730, 10);
        pb::TelemetryEvent first, second, third;
        telemetry.record(1000, model.state(), &first);
        telemetry.record(1100, model.state(), &second);
        model.arm();
        telemetry.record(1200, model.state(), &third);
        QCOMPARE(first.telemetry_size(), SimTelemetry::kFieldCount); // everything at first
        QCOMPARE(second.telemetry_size(), 9);                          // then only the fast fields
        QCOMPARE(third.telemetry_size(), SimTelemetry::kFieldCount);  // arming changes the slow ones
        const auto &lat = first.telemetry(0);
        QCOMPARE(lat.telemetryfield().code(), std::string("latitude"));
        QCOMPARE(lat.telemetryfield().semantic(), pb::S_LATITUDE);
        QVERIFY(std::abs(lat.value().doublevalue() - 56.9762 * 3.14159265358979323846 / 180) < 1e-12);
        QCOMPARE(lat.time(), 1000);

        pb::GetTelemetryResponse history;
        telemetry.history(1050, 5000, 1000, &history);
        QCOMPARE(history.telemetry_size(), 2 * SimTelemetry::kFieldCount);
        QVERIFY(!history.has_nexttelemetrytime());
        history.Clear();
        telemetry.history(0, 5000, SimTelemetry::kFieldCount, &history);
        QCOMPARE(history.nexttelemetrytime(), 1100);
    }

    void commandsFollowTheVehicleState()
    {
        FlightModel model(56.9762, 24.0730, 10);
        pb::Vehicle ref;
        ref.set_id(3);
        auto available = [&](const char *code) {
            for (const auto &d : SimCommands::definitions(ref, model))
                if (d.code() == code)
                    return d.available();
            return false;
        };
        QVERIFY(available("arm"));
        QVERIFY(!available("land_command"));
        const quint32 before = SimCommands::availability(model);
        pb::Command arm;
        arm.set_code("arm");
        QCOMPARE(SimCommands::execute(model, arm).status, int(pb::CS_SUCCEEDED));
        QVERIFY(SimCommands::availability(model) != before);
        QVERIFY(!available("arm"));
        QCOMPARE(SimCommands::execute(model, arm).status, int(pb::CS_FAILED)); // already armed
        pb::Command go;
        go.set_code("waypoint");
        QCOMPARE(SimCommands::execute(model, go).status, int(pb::CS_REJECTED)); // no coordinates
    }
};

QTEST_MAIN(TestSimWorld)
#include "tst_simworld.moc"
