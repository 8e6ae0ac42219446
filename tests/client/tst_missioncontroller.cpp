// MissionController and RouteDocument against the simulated server: open a route, edit it, undo,
// save under a lock and see the change from a second session, a conflicting save, processing and
// uploading with progress, files.
#include "AutosaveRecord.h"
#include "ConnectionController.h"
#include "HciClient.h"
#include "HciReply.h"
#include "HciOrigin.h"
#include "HciRouteMapper.h"
#include "Messages.pb.h"
#include "MissionController.h"
#include "MissionFiles.h"
#include "RouteAutosave.h"
#include "SegmentParameters.h"
#include "SimFixture.h"
#include "SimVehicle.h"
#include "VehicleFleet.h"

#include <QFile>
#include <QGeoCoordinate>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie;
using client::MissionController;
namespace pb = com::ugcs::ucs::proto;

namespace {

// One logged-in operator: session, client and the controllers.
struct Operator
{
    Operator(const QString &address, const QString &user, const QString &password)
        : client(&session)
        , connection(&session)
        , missions(&client)
        , fleet(&client)
    {
        missions.preparation()->setFleet(&fleet);
        QSignalSpy ready(&connection, &client::ConnectionController::ready);
        connection.connectToServer(address, user, password);
        ok = ready.wait(10000);
    }
    hci::HciSession session;
    hci::HciClient client;
    client::ConnectionController connection;
    MissionController missions;
    client::VehicleFleet fleet;
    bool ok = false;
};

template<typename T>
T call(hci::HciReply *reply)
{
    reply->setAutoDelete(false);
    if (!reply->isFinished()) {
        QSignalSpy done(reply, &hci::HciReply::finished);
        done.wait(10000);
    }
    T response = reply->response<T>();
    delete reply;
    return response;
}

int routeRow(const client::ServerObjectListModel &routes, const QString &name)
{
    for (int row = 0; row < routes.count(); ++row) {
        if (routes.nameAt(row) == name)
            return row;
    }
    return -1;
}

const QString kDemoRoute = QStringLiteral("Riga port - 4 WP");

double altitudeAt(const client::RouteDocument &doc, int row)
{
    const auto *waypoint = mission::asWaypoint(doc.route().segments.at(size_t(row)));
    return waypoint ? waypoint->altitude : qQNaN();
}

double serverAltitude(const pb::Route &route, int row)
{
    auto imported = mission::routeFromHci(route);
    const auto *waypoint = imported ? mission::asWaypoint(imported->route.segments.at(size_t(row))) : nullptr;
    return waypoint ? waypoint->altitude : qQNaN();
}

} // namespace

class TestMissionController : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::SimFixture> m_sim;
    std::unique_ptr<Operator> m_alice;

    // The demo route's id once it is open, or -1.
    int openDemoRoute(Operator &op)
    {
        QDeadlineTimer deadline(10000);
        while (routeRow(*op.missions.routes(), kDemoRoute) < 0 && !deadline.hasExpired())
            QTest::qWait(10);
        const int id = op.missions.routes()->objectIdAt(routeRow(*op.missions.routes(), kDemoRoute));
        if (id < 0)
            return -1;
        op.missions.openRoute(id);
        while (op.missions.routeId() != id && !deadline.hasExpired())
            QTest::qWait(10);
        return op.missions.routeId() == id ? id : -1;
    }

private slots:
    void init()
    {
        m_sim = std::make_unique<test::SimFixture>();
        m_alice = std::make_unique<Operator>(m_sim->address(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(m_alice->ok);
    }

    void cleanup()
    {
        m_alice.reset();
        m_sim.reset();
    }

    void listsRoutesAndVehicles()
    {
        QTRY_VERIFY(routeRow(*m_alice->missions.routes(), kDemoRoute) >= 0);
        QTRY_COMPARE(m_alice->missions.vehicles()->count(), 3);
        QCOMPARE(m_alice->missions.vehicles()->nameAt(0), QStringLiteral("EMU-101"));
        QTRY_COMPARE(m_alice->fleet.count(), 3); // the upload's chooser
    }

    void editUndoSaveAndSeeItFromASecondSession()
    {
        // Nothing open and nothing edited: Save means nothing.
        QVERIFY(!m_alice->missions.canSave());
        QSignalSpy canSave(&m_alice->missions, &client::MissionController::canSaveChanged);
        const int id = openDemoRoute(*m_alice);
        QVERIFY(m_alice->missions.canSave());
        QVERIFY(!canSave.isEmpty());
        QVERIFY(id > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        QCOMPARE(doc->model()->count(), 4);
        QCOMPARE(m_alice->missions.routeName(), kDemoRoute);
        QVERIFY(!doc->isModified());

        QCOMPARE(doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820)), 4);
        QCOMPARE(doc->selectedRows(), QList<int>{4});
        QCOMPARE(doc->editor()->insertWaypoint(1, QGeoCoordinate(56.9770, 24.0745)), 1);
        QCOMPARE(doc->selectedRows(), QList<int>{1});
        QVERIFY(doc->editor()->moveWaypoints({2}, {QGeoCoordinate(56.9785, 24.0770)}));
        QCOMPARE(doc->model()->count(), 6);
        doc->selectRows({5});
        doc->editor()->removeRows(doc->selectedRows());
        QCOMPARE(doc->model()->count(), 5);
        QVERIFY(doc->isModified());
        doc->undo(); // the removal
        QCOMPARE(doc->model()->count(), 6);
        doc->undo(); // the move
        QVERIFY(std::abs(doc->model()->index(2).data(mission::RouteModel::LatitudeRole).toDouble() - 56.97800) < 1e-9);
        doc->redo();
        QVERIFY(std::abs(doc->model()->index(2).data(mission::RouteModel::LatitudeRole).toDouble() - 56.9785) < 1e-9);

        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        m_alice->missions.save();
        QVERIFY(saved.wait(10000));
        QCOMPARE(saved.first().first().toInt(), 2);
        QVERIFY(!doc->isModified());
        QVERIFY2(m_alice->missions.message().startsWith(QStringLiteral("Saved")), qPrintable(m_alice->missions.message()));

        // Bob sees Alice's route as she saved it.
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        const pb::Route theirs = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        QCOMPARE(theirs.version(), 2);
        QCOMPARE(theirs.segments_size(), 6);
        const auto route = mission::routeFromHci(theirs);
        QVERIFY(route);
        QVERIFY(std::abs(std::get<mission::Waypoint>(route->route.segments[2]).position.latitude - 56.9785) < 1e-9);
        // The lock was released after the save: Bob can take it.
        auto *lock = bob.client.acquireLock(hci::HciObjectType::Route, id);
        lock->setAutoDelete(false);
        QSignalSpy locked(lock, &hci::HciReply::finished);
        QVERIFY(lock->isFinished() || locked.wait(10000));
        QVERIFY2(lock->isOk(), qPrintable(lock->error().message()));
        delete lock;
    }

    // Issue 36: Open over unsaved edits threw them away without a word.
    void openingOverUnsavedEditsAsksAndDiscardIsUndoable()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        MissionController &missions = m_alice->missions;
        client::RouteDocument *doc = missions.document();
        QTemporaryDir folder;
        client::RouteAutosave autosave(doc, folder.path());
        QVERIFY(autosave.isActive());
        QCOMPARE(altitudeAt(*doc, 0), 40.0);
        QVERIFY(doc->editor()->setAltitude({0}, 77));
        QVERIFY(autosave.writeNow());

        // Open again: a question, and nothing else happens.
        QSignalSpy opened(&missions, &MissionController::routeOpened);
        missions.openRoute(id);
        QVERIFY(missions.isAskingToOpen());
        QVERIFY2(missions.openQuestion().contains(QStringLiteral("unsaved edits")), qPrintable(missions.openQuestion()));
        QVERIFY(!missions.isBusy()); // nothing was asked of the server
        missions.cancelOpen();
        QVERIFY(!missions.isAskingToOpen());
        QCOMPARE(altitudeAt(*doc, 0), 77.0);
        QVERIFY(doc->isModified());

        // Discard: the server's copy, clean, and the edits one undo step away.
        missions.openRoute(id);
        QVERIFY(missions.isAskingToOpen());
        missions.discardThenOpen();
        QVERIFY(!missions.isAskingToOpen());
        QVERIFY(opened.wait(10000));
        QCOMPARE(altitudeAt(*doc, 0), 40.0);
        QVERIFY(!doc->isModified());
        QVERIFY(doc->canUndo());
        QVERIFY2(missions.message().contains(QStringLiteral("Undo brings back")), qPrintable(missions.message()));
        autosave.waitForWriter();
        QVERIFY(!QFile::exists(autosave.filePath())); // clean: nothing to autosave

        doc->undo();
        QCOMPARE(altitudeAt(*doc, 0), 77.0);
        QVERIFY(doc->isModified());
        QCOMPARE(missions.routeId(), id);
        // The autosave has them again, against the route as it was opened.
        QVERIFY(autosave.writeNow());
        QFile file(autosave.filePath());
        QVERIFY(file.open(QIODevice::ReadOnly));
        auto record = client::decodeAutosave(file.readAll());
        QVERIFY2(record, record ? "" : qPrintable(record.error().toString()));
        QCOMPARE(mission::asWaypoint(record->working.segments.at(0))->altitude, 77.0);
        QCOMPARE(mission::asWaypoint(record->baseline.segments.at(0))->altitude, 40.0);
        QCOMPARE(record->routeId, id);
    }

    void saveThenOpenOpensOnceSaved()
    {
        const int first = openDemoRoute(*m_alice);
        QVERIFY(first > 0);
        MissionController &missions = m_alice->missions;
        // A second route on the server, to open over the first one's edits.
        pb::Route copy = call<pb::GetObjectResponse>(m_alice->client.getObject(hci::HciObjectType::Route, first)).object().route();
        copy.clear_id();
        copy.clear_version();
        for (auto &segment : *copy.mutable_segments())
            segment.clear_id();
        copy.set_name("Second route");
        const int second = call<pb::CreateOrUpdateObjectResponse>(m_alice->client.createOrUpdate(copy)).object().route().id();
        QVERIFY(second > 0 && second != first);
        QTRY_VERIFY(missions.routes()->rowOf(second) >= 0);

        client::RouteDocument *doc = missions.document();
        QVERIFY(doc->editor()->setAltitude({0}, 77));
        missions.openRoute(second);
        QVERIFY(missions.isAskingToOpen());
        QVERIFY2(missions.openQuestion().contains(QStringLiteral("\"Second route\"")), qPrintable(missions.openQuestion()));
        QSignalSpy saved(&missions, &MissionController::saved);
        QSignalSpy opened(&missions, &MissionController::routeOpened);
        missions.saveThenOpen();
        QVERIFY(opened.wait(10000));
        QCOMPARE(saved.count(), 1);
        QCOMPARE(missions.routeId(), second);
        QCOMPARE(missions.routeName(), QStringLiteral("Second route"));
        QVERIFY(!doc->isModified());
        const pb::Route stored = call<pb::GetObjectResponse>(m_alice->client.getObject(hci::HciObjectType::Route, first)).object().route();
        QCOMPARE(serverAltitude(stored, 0), 77.0);
    }

    void saveThatFailsDoesNotOpen()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        MissionController &missions = m_alice->missions;
        client::RouteDocument *doc = missions.document();
        QVERIFY(doc->editor()->setAltitude({0}, 77));
        // Bob holds the route's lock: the save is refused, and the open that was to follow waits.
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        hci::HciReply *locked = bob.client.acquireLock(hci::HciObjectType::Route, id);
        QSignalSpy lockDone(locked, &hci::HciReply::finished);
        QVERIFY(lockDone.wait(10000));
        QVERIFY(locked->isOk());

        missions.openRoute(id);
        QVERIFY(missions.isAskingToOpen());
        QSignalSpy opened(&missions, &MissionController::routeOpened);
        missions.saveThenOpen();
        QTRY_VERIFY_WITH_TIMEOUT(missions.message().startsWith(QStringLiteral("Not saved")), 10000);
        QVERIFY2(missions.message().contains(QStringLiteral("locked")), qPrintable(missions.message()));
        QTRY_VERIFY(!missions.isBusy());
        QCOMPARE(opened.count(), 0);
        QCOMPARE(altitudeAt(*doc, 0), 77.0);
        QVERIFY(doc->isModified());
        QVERIFY(!missions.isAskingToOpen());
    }

    // Issue 36: a successful save reloaded the server's copy and lost an edit made meanwhile.
    void anEditMadeWhileSavingIsKept()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        MissionController &missions = m_alice->missions;
        client::RouteDocument *doc = missions.document();
        QVERIFY(doc->editor()->setAltitude({0}, 77));
        QSignalSpy saved(&missions, &MissionController::saved);
        missions.save();
        // The save is on its way (nothing of it can be answered before the event loop runs).
        QVERIFY(missions.isBusy());
        QVERIFY(doc->editor()->setAltitude({1}, 66));
        QCOMPARE(doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820)), 4);
        QVERIFY(saved.wait(10000));
        QTRY_VERIFY(!missions.isBusy());

        // The server has what was sent; the document keeps the later edits, unsaved.
        const pb::Route stored = call<pb::GetObjectResponse>(m_alice->client.getObject(hci::HciObjectType::Route, id)).object().route();
        QCOMPARE(serverAltitude(stored, 0), 77.0);
        QCOMPARE(serverAltitude(stored, 1), 50.0);
        QCOMPARE(stored.segments_size(), 4);
        QCOMPARE(altitudeAt(*doc, 0), 77.0);
        QCOMPARE(altitudeAt(*doc, 1), 66.0);
        QCOMPARE(doc->model()->count(), 5);
        QVERIFY(doc->isModified());
        QVERIFY2(missions.message().contains(QStringLiteral("kept, not saved yet")), qPrintable(missions.message()));
        QCOMPARE(hciRoute(doc->route().origin)->version(), stored.version());
        // Undo goes back to what the server has.
        doc->undo();
        QVERIFY(!doc->isModified());
        QCOMPARE(altitudeAt(*doc, 1), 50.0);
        doc->redo();
        QCOMPARE(altitudeAt(*doc, 1), 66.0);

        // Saving them is an ordinary save, not a conflict with ourselves; the segments the server
        // already knew keep their ids.
        missions.save();
        QVERIFY(saved.wait(10000));
        QVERIFY(!missions.hasConflict());
        QVERIFY(!doc->isModified());
        const pb::Route again = call<pb::GetObjectResponse>(m_alice->client.getObject(hci::HciObjectType::Route, id)).object().route();
        QCOMPARE(serverAltitude(again, 1), 66.0);
        QCOMPARE(again.segments_size(), 5);
        QCOMPARE(again.version(), stored.version() + 1);
        for (int i = 2; i < 4; ++i)
            QCOMPARE(again.segments(i).id(), stored.segments(i).id());
    }

    void followsTheServerWhenNothingIsEdited()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        pb::Route theirs = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        theirs.set_name("Renamed by Bob");
        call<pb::CreateOrUpdateObjectResponse>(bob.client.createOrUpdate(theirs));
        QTRY_COMPARE(m_alice->missions.routeName(), QStringLiteral("Renamed by Bob"));
        QVERIFY(!m_alice->missions.hasConflict());
    }

    void conflictingSaveOffersAChoice()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));

        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        pb::Route theirs = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        theirs.set_safealtitude(45);
        call<pb::CreateOrUpdateObjectResponse>(bob.client.createOrUpdate(theirs));

        // Alice learns of it at once, and her edits are still there.
        QTRY_VERIFY(m_alice->missions.hasConflict());
        QVERIFY2(m_alice->missions.conflictText().contains(QStringLiteral("version 2")), qPrintable(m_alice->missions.conflictText()));
        QCOMPARE(doc->model()->count(), 5);
        // She sees both: how the copies differ, who changed what, their route for the map.
        const client::RouteConflict *conflict = m_alice->missions.conflictDetails();
        const QString safe = QString::number(m_alice->missions.document()->route().settings.safeAltitude);
        QCOMPARE(conflict->changes(), (QStringList{QStringLiteral("safe altitude 45 → %1 m").arg(safe), QStringLiteral("WP 5 added")}));
        QVERIFY2(conflict->yourEdits() == QStringList{QStringLiteral("WP 5 added")}, qPrintable(conflict->yourEdits().join(" / ")));
        QCOMPARE(conflict->theirEdits(), QStringList{QStringLiteral("safe altitude %1 → 45 m").arg(safe)});
        QCOMPARE(conflict->yourVersion(), 1);
        QCOMPARE(conflict->theirVersion(), 2);
        QVERIFY(conflict->theirSaveTime().isValid());
        QCOMPARE(const_cast<client::RouteConflict *>(conflict)->theirModel()->count(), 4);
        QCOMPARE(conflict->theirRoute().settings.safeAltitude, 45.0);

        // Saving does not overwrite Bob's copy behind anyone's back...
        m_alice->missions.save();
        QTRY_VERIFY(!m_alice->missions.isBusy());
        QCOMPARE(call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route().segments_size(), 4);
        // ...until she chooses to keep hers.
        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        m_alice->missions.keepMine();
        QVERIFY(saved.wait(10000));
        QVERIFY(!m_alice->missions.hasConflict());
        const pb::Route now = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        QCOMPARE(now.segments_size(), 5);
        QCOMPARE(now.version(), 3);
    }

    void takeTheirsIsUndoable()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        const mission::Route mine = doc->route();
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        pb::Route theirs = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        theirs.set_name("Bob's");
        call<pb::CreateOrUpdateObjectResponse>(bob.client.createOrUpdate(theirs));
        QTRY_VERIFY(m_alice->missions.hasConflict());
        QCOMPARE(m_alice->missions.conflictDetails()->changes(),
                 (QStringList{QStringLiteral("name \"Bob's\" → \"%1\"").arg(kDemoRoute), QStringLiteral("WP 5 added")}));
        m_alice->missions.takeTheirs();
        QVERIFY(!m_alice->missions.hasConflict());
        QCOMPARE(m_alice->missions.conflictDetails()->theirModel()->count(), 0); // the ghost is gone
        QCOMPARE(doc->model()->count(), 4);
        QCOMPARE(m_alice->missions.routeName(), QStringLiteral("Bob's"));
        QVERIFY(!doc->isModified());
        QCOMPARE(hciRoute(doc->route().origin)->version(), 2);
        // Nothing of hers is lost: undo brings her edits back, unsaved.
        doc->undo();
        QVERIFY(doc->route() == mine);
        QVERIFY(doc->isModified());
    }

    void editsSurviveAServerRestartAndSaveAfterIt()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        m_alice->session.reconnectPolicy().setDelays(std::chrono::milliseconds(50), std::chrono::milliseconds(300));
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        doc->editor()->setAltitude({1, 2}, 66);
        const mission::Route edited = doc->route();
        const int steps = doc->undoStack()->count();
        const quint16 port = m_sim->server.port();

        m_sim->server.close(); // stops listening and drops every connection
        QTRY_VERIFY(!m_alice->session.isReady());
        QVERIFY(doc->route() == edited);
        QVERIFY(m_sim->server.listen(QHostAddress::LocalHost, port));
        QTRY_VERIFY_WITH_TIMEOUT(m_alice->session.isReady(), 15000);
        QVERIFY(doc->route() == edited);
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(doc->isModified());

        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        m_alice->missions.save();
        QVERIFY2(saved.wait(10000), qPrintable(m_alice->missions.message()));
        QCOMPARE(saved.first().first().toInt(), 2);
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        const auto route = mission::routeFromHci(call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route());
        QVERIFY(route);
        QVERIFY(route->route == edited);
    }

    void areaScan()
    {
        const int id = openDemoRoute(*m_alice);
        QVERIFY(id > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        const QList<QGeoCoordinate> corners{QGeoCoordinate(56.9740, 24.0800), QGeoCoordinate(56.9770, 24.0800),
                                            QGeoCoordinate(56.9770, 24.0870), QGeoCoordinate(56.9740, 24.0870)};
        QCOMPARE(doc->editor()->addAreaScan(corners.mid(0, 2)), -1); // two corners enclose nothing
        QVERIFY(!doc->message().isEmpty());
        const int row = doc->editor()->addAreaScan(corners);
        QCOMPARE(row, 4);
        QCOMPARE(doc->currentRow(), 4);
        QCOMPARE(doc->scanPolygon().size(), 4);
        const int pathBefore = int(doc->scanPath().size());
        QVERIFY2(pathBefore >= 4, qPrintable(QString::number(pathBefore)));
        QVERIFY(doc->scanProblem().isEmpty());
        QCOMPARE(mission::parameterValue(doc->model()->segment(row), QStringLiteral("overlapSide"), doc->editor()->catalog()).toDouble(), 65.0);

        // More side overlap: transects closer together, so more of them.
        QVERIFY(doc->editor()->setParameter({row}, QStringLiteral("overlapSide"), 85.0));
        QCOMPARE(mission::parameterValue(doc->model()->segment(row), QStringLiteral("overlapSide"), doc->editor()->catalog()).toDouble(), 85.0);
        QVERIFY(doc->scanPath().size() > pathBefore);
        QVERIFY(!doc->editor()->setParameter({row}, QStringLiteral("overlapForward"), 120.0));
        QVERIFY(doc->message().contains(QStringLiteral("overlapForward")));
        doc->undo();
        QCOMPARE(int(doc->scanPath().size()), pathBefore);
        doc->redo();

        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        m_alice->missions.save();
        QVERIFY(saved.wait(10000));
        Operator bob(m_sim->address(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QVERIFY(bob.ok);
        const pb::Route theirs = call<pb::GetObjectResponse>(bob.client.getObject(hci::HciObjectType::Route, id)).object().route();
        QCOMPARE(theirs.segments_size(), 5);
        const auto route = mission::routeFromHci(theirs);
        QVERIFY(route);
        QVERIFY(std::holds_alternative<mission::AreaScan>(route->route.segments[4]));
        QCOMPARE(std::get<mission::AreaScan>(route->route.segments[4]).parameters.sideOverlapPercent, 85.0);
    }

    void processAndUploadWithProgress()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        QTRY_COMPARE(m_alice->fleet.count(), 3);
        const QString emu = m_alice->fleet.index(0).data(client::VehicleFleet::VehicleIdRole).toString();
        QCOMPARE(emu.left(4), QStringLiteral("HCI:"));
        client::RoutePreparation *preparation = m_alice->missions.preparation();
        preparation->process();
        QVERIFY2(preparation->message().startsWith(QStringLiteral("Choose the vehicle")), qPrintable(preparation->message()));
        preparation->setVehicleId(emu);
        preparation->process();
        QVERIFY(preparation->isProcessing());
        QTRY_VERIFY_WITH_TIMEOUT(!preparation->isProcessing(), 10000);
        QVERIFY2(preparation->message().startsWith(QStringLiteral("Processed for EMU-101: ")), qPrintable(preparation->message()));
        const int previewed = preparation->previewCount();
        QVERIFY(previewed >= 4);
        QList<int> progress;
        connect(preparation->uploader(), &client::MissionUploader::progressChanged, this, [&] {
            if (preparation->uploader()->progressMaximum() > 0)
                progress.append(preparation->uploader()->progressValue());
        });
        QSignalSpy uploaded(preparation, &client::RoutePreparation::uploaded);
        preparation->upload();
        QVERIFY(uploaded.wait(15000));
        QCOMPARE(uploaded.first().first().toString(), emu);
        QVERIFY2(progress.size() >= 3, qPrintable(QString::number(progress.size())));
        QVERIFY(std::is_sorted(progress.begin(), progress.end()));
        QVERIFY2(preparation->message().startsWith(QStringLiteral("Uploaded to EMU-101: ")), qPrintable(preparation->message()));
        const int emuId = emu.mid(4).toInt();
        // The preview was what flies: the same points went up.
        QCOMPARE(int(m_sim->world.vehicle(emuId)->model().mission().size()), previewed);
        // What the vehicle holds is what the fly view draws.
        QCOMPARE(m_alice->fleet.vehicle(emu)->mission().size(), m_sim->world.vehicle(emuId)->model().mission().size());
        // The upload is in the command log, done.
        const vehicle::CommandLog &log = *m_alice->fleet.commandLog();
        QVERIFY(log.count() >= 1);
        QCOMPARE(log.at(log.count() - 1).vehicle, QStringLiteral("EMU-101"));
        QVERIFY(log.at(log.count() - 1).command.startsWith(QLatin1String("upload")));
        QCOMPARE(log.at(log.count() - 1).status, vehicle::CommandLog::Status::Done);
    }

    void saveAndUploadAnsweringTheUnsavedQuestion()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        QTRY_COMPARE(m_alice->fleet.count(), 3);
        const QString emu = m_alice->fleet.index(1).data(client::VehicleFleet::VehicleIdRole).toString();
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        QVERIFY(doc->isModified());
        client::RoutePreparation *preparation = m_alice->missions.preparation();
        QSignalSpy uploaded(preparation, &client::RoutePreparation::uploaded);
        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        preparation->setVehicleId(emu);
        preparation->upload();
        client::MissionUploader *uploader = preparation->uploader();
        QCOMPARE(uploader->state(), client::MissionUploader::State::AwaitingConfirmation);
        QVERIFY(uploader->hasUnsavedEdits());
        QVERIFY2(uploader->question().contains(QLatin1String("not saved")), qPrintable(uploader->question()));
        QVERIFY(!m_alice->missions.isBusy()); // asking holds nothing: saving is possible
        preparation->saveAndUpload();
        QVERIFY(uploaded.wait(15000));
        QCOMPARE(saved.count(), 1);
        QVERIFY(!doc->isModified());
        QVERIFY(std::abs(m_sim->world.vehicle(emu.mid(4).toInt())->model().mission().back().longitude - 24.0820) < 1e-9);
    }

    void saveAndUploadRefuseAValidationError()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        QTRY_COMPARE(m_alice->fleet.count(), 3);
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->setAltitude({2}, 900); // above the route's maximum: an error
        QSignalSpy saved(&m_alice->missions, &MissionController::saved);
        m_alice->missions.save();
        QVERIFY2(m_alice->missions.message().startsWith(QStringLiteral("Not saved: Waypoint 3: ")), qPrintable(m_alice->missions.message()));
        const QString emu = m_alice->fleet.index(0).data(client::VehicleFleet::VehicleIdRole).toString();
        client::RoutePreparation *preparation = m_alice->missions.preparation();
        preparation->setVehicleId(emu);
        preparation->upload();
        client::MissionUploader *uploader = preparation->uploader();
        QCOMPARE(uploader->state(), client::MissionUploader::State::Failed);
        QCOMPARE(uploader->culprit(), 2);
        QVERIFY2(preparation->message().startsWith(QStringLiteral("Not uploaded: Waypoint 3: ")), qPrintable(preparation->message()));
        QTest::qWait(50);
        QCOMPARE(saved.count(), 0);
        QVERIFY(m_sim->world.vehicle(emu.mid(4).toInt())->model().mission().empty());
    }

    void processReportsTheServersProblems()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->setAltitude({1}, 500); // above the route's maximum
        QTRY_COMPARE(m_alice->fleet.count(), 3);
        client::RoutePreparation *preparation = m_alice->missions.preparation();
        preparation->setVehicleId(m_alice->fleet.index(0).data(client::VehicleFleet::VehicleIdRole).toString());
        QSignalSpy previews(preparation, &client::RoutePreparation::previewChanged);
        preparation->process();
        QVERIFY(previews.wait(10000));
        QCOMPARE(preparation->previewCount(), -1); // nothing the vehicle could fly
        QVERIFY(!preparation->notices().isEmpty());
        QVERIFY2(preparation->notices().join(' ').contains(QStringLiteral("altitude")), qPrintable(preparation->notices().join(' ')));
        QVERIFY2(preparation->message().startsWith(QStringLiteral("Not processed for EMU-101: ")), qPrintable(preparation->message()));
    }

    void filesRoundTrip()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        QTemporaryDir dir;
        const QUrl file = QUrl::fromLocalFile(dir.filePath(QStringLiteral("port.sortie")));
        QVERIFY2(doc->exportFile(file), qPrintable(doc->message()));
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        doc->editor()->addWaypoint(QGeoCoordinate(56.9795, 24.0830));
        QCOMPARE(doc->model()->count(), 6);
        QVERIFY2(doc->importFile(file), qPrintable(doc->message()));
        QCOMPARE(doc->model()->count(), 4);
        QCOMPARE(m_alice->missions.routeName(), kDemoRoute);
        doc->undo(); // an import is one undo step
        QCOMPARE(doc->model()->count(), 6);

        QFile broken(dir.filePath(QStringLiteral("broken.plan")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{ \"fileType\": \"Plan\", ");
        broken.close();
        // A file of several routes: the editor takes the first and says so.
        mission::Mission two;
        two.routes = {doc->model()->route(), doc->model()->route()};
        two.routes[0].settings.name = QStringLiteral("first");
        const QString twoPath = dir.filePath(QStringLiteral("two.sortie"));
        QVERIFY(mission::formats::saveMission(two, twoPath, {std::nullopt, mission::ValidationOverride::AcceptErrors, {}}).ok());
        QVERIFY2(doc->importFile(QUrl::fromLocalFile(twoPath)), qPrintable(doc->message()));
        QVERIFY2(doc->message().contains(QStringLiteral("holds 2 routes; this is the first (\"first\")")), qPrintable(doc->message()));
        doc->undo();

        QVERIFY(!doc->importFile(QUrl::fromLocalFile(broken.fileName())));
        QVERIFY2(doc->message().contains(QStringLiteral("broken.plan")), qPrintable(doc->message()));
        QCOMPARE(doc->model()->count(), 6); // nothing lost
    }

    void editsSurviveADroppedConnection()
    {
        QVERIFY(openDemoRoute(*m_alice) > 0);
        client::RouteDocument *doc = m_alice->missions.document();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        m_sim->server.close();
        m_sim->server.dropConnections();
        QTRY_VERIFY(!m_alice->session.isReady());
        m_alice->missions.save();
        QVERIFY2(m_alice->missions.message().startsWith(QStringLiteral("Not connected")), qPrintable(m_alice->missions.message()));
        QCOMPARE(doc->model()->count(), 5);
        QVERIFY(doc->isModified());
    }
};

QTEST_GUILESS_MAIN(TestMissionController)
#include "tst_missioncontroller.moc"
