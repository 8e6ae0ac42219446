// RouteAutosave and AutosaveRecovery in one process, on a real temporary directory: a burst of
// edits is one write, the file holds working route, baseline and identity, a clean document
// removes it, unsaved edits outlive the instance, recovery lists exactly the edits and restores
// them as one undo step, a live instance's file is not offered, an unreadable file is kept aside
// and named, discard keeps one backup.
#include "AutosaveRecord.h"
#include "AutosaveRecovery.h"
#include "AutosaveTestRoute.h"
#include "AutosaveWriter.h"
#include "HciOrigin.h"
#include "RouteAutosave.h"

#include <QGeoCoordinate>
#include <QDir>
#include <QFile>
#include <QScopeGuard>
#include <QSemaphore>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <sys/stat.h>

using namespace sortie;
using client::AutosaveRecovery;
using client::AutosaveWriter;
using client::RouteAutosave;
using client::RouteDocument;

class TestRouteAutosave : public QObject
{
    Q_OBJECT

    static client::AutosaveRecord readFile(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            qFatal("cannot read %s", qPrintable(path));
        auto decoded = client::decodeAutosave(f.readAll());
        if (!decoded)
            qFatal("%s", qPrintable(decoded.error().toString()));
        return decoded.value();
    }

    // Leaves an autosave with the test edits in `dir`, as an instance that quit without saving does.
    static mission::Route leaveEdits(const QString &dir)
    {
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir);
        autosave.setServer(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
        doc.load(test::serverRoute());
        test::editRoute(doc);
        return doc.route();
    }

    // The same for a route from a file (no server identity), named `name`, with one waypoint added.
    static mission::Route leaveFileEdits(const QString &dir, const QString &name)
    {
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir);
        mission::Route route = test::serverRoute();
        route.origin = {};
        route.settings.name = name;
        doc.load(route);
        doc.editor()->addWaypoint(QGeoCoordinate(56.5, 24.5));
        return doc.route();
    }

private slots:
    void aBurstOfEditsIsOneWriteOfEverythingNeededToRestore()
    {
        QTemporaryDir dir;
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir.path());
        QVERIFY2(autosave.isActive(), qPrintable(autosave.error()));
        autosave.setServer(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
        autosave.setDelay(50);
        const mission::Route loaded = test::serverRoute();
        doc.load(loaded);
        QSignalSpy written(&autosave, &RouteAutosave::written);
        test::editRoute(doc);
        QVERIFY(!QFile::exists(autosave.filePath())); // not before the burst is over
        QVERIFY(written.wait(5000));
        QVERIFY(!written.wait(300));
        QCOMPARE(written.count(), 1);
        QCOMPARE(written.first().first().toString(), autosave.filePath());

        const client::AutosaveRecord record = readFile(autosave.filePath());
        QVERIFY(record.working == doc.route());
        QVERIFY(record.baseline == loaded);
        QCOMPARE(record.routeId, 42);
        QCOMPARE(record.routeVersion, 3);
        QCOMPARE(record.server, QStringLiteral("127.0.0.1:3334"));
        QCOMPARE(record.user, QStringLiteral("admin"));
        QVERIFY(qAbs(record.savedAt.secsTo(QDateTime::currentDateTimeUtc())) < 3600);
        QVERIFY(record.working.origin && hciRoute(record.working.origin)->id() == 42);
        // No temporary file is left behind by the atomic write.
        QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("*.json*")}, QDir::Files),
                 QStringList{QFileInfo(autosave.filePath()).fileName()});
    }

    void aCleanDocumentHasNoAutosave()
    {
        QTemporaryDir dir;
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir.path());
        doc.load(test::serverRoute());
        doc.editor()->addWaypoint(QGeoCoordinate(56.0, 24.0));
        QVERIFY(autosave.writeNow());
        QVERIFY(QFile::exists(autosave.filePath()));
        QSignalSpy removed(&autosave, &RouteAutosave::removed);
        doc.undo(); // back to the saved state
        QVERIFY(removed.wait(5000)); // removed on the writer's thread
        QVERIFY(!QFile::exists(autosave.filePath()));
        doc.redo();
        QVERIFY(autosave.writeNow());
        doc.markSaved(); // saved to the server: the baseline moves
        autosave.waitForWriter();
        QVERIFY(!QFile::exists(autosave.filePath()));
        doc.editor()->addWaypoint(QGeoCoordinate(56.1, 24.1));
        QVERIFY(autosave.writeNow());
        QCOMPARE(int(readFile(autosave.filePath()).baseline.segments.size()), 13);
        doc.load(test::serverRoute()); // another route opened
        autosave.waitForWriter();
        QVERIFY(!QFile::exists(autosave.filePath()));
    }

    // Issue 36: autosaves took the umask (0644 files, 0755 folders): another local user read the routes.
    void filesArePrivate()
    {
        QTemporaryDir dir;
        const QString folder = QDir(dir.path()).filePath(QStringLiteral("made/autosave"));
        const mode_t before = ::umask(022); // the common default, which would leave them readable
        const auto restore = qScopeGuard([before] { ::umask(before); });
        RouteDocument doc;
        RouteAutosave autosave(&doc, folder);
        QVERIFY2(autosave.isActive(), qPrintable(autosave.error()));
        doc.load(test::serverRoute());
        test::editRoute(doc);
        QVERIFY(autosave.writeNow());
        const auto others = QFileDevice::ReadGroup | QFileDevice::WriteGroup | QFileDevice::ExeGroup | QFileDevice::ReadOther
                          | QFileDevice::WriteOther | QFileDevice::ExeOther;
        QCOMPARE(QFileInfo(autosave.filePath()).permissions() & others, QFileDevice::Permissions());
        QCOMPARE(QFileInfo(folder).permissions() & others, QFileDevice::Permissions());
        QCOMPARE(QFileInfo(QFileInfo(folder).path()).permissions() & others, QFileDevice::Permissions());
        // And again after the next write replaced the file.
        doc.editor()->addWaypoint(QGeoCoordinate(56.5, 24.5));
        QVERIFY(autosave.writeNow());
        QCOMPARE(QFileInfo(autosave.filePath()).permissions() & others, QFileDevice::Permissions());
    }

    void theFileIsEncodedAndWrittenOffTheGuiThread()
    {
        // Declared before the autosave: its destructor writes the pending edits once more and the
        // lambdas below still run then.
        QThread *encodedOn = nullptr;
        QThread *emittedOn = nullptr;
        QTemporaryDir dir;
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir.path());
        autosave.setDelay(0);
        doc.load(test::serverRoute());
        // Direct connections run where the writer emits: the thread that encoded and wrote.
        connect(autosave.writer(), &AutosaveWriter::written, autosave.writer(),
                [&encodedOn] { encodedOn = QThread::currentThread(); }, Qt::DirectConnection);
        connect(&autosave, &RouteAutosave::written, this, [&emittedOn] { emittedOn = QThread::currentThread(); });
        QSignalSpy written(&autosave, &RouteAutosave::written);
        test::editRoute(doc);
        QVERIFY(written.wait(5000));
        autosave.waitForWriter(); // the writer emits to RouteAutosave first, then to the lambda
        QVERIFY(encodedOn);
        QVERIFY(encodedOn != QThread::currentThread());
        QCOMPARE(encodedOn, autosave.writer()->thread());
        QCOMPARE(emittedOn, QThread::currentThread()); // the signal reaches the GUI thread
        QVERIFY(readFile(autosave.filePath()).working == doc.route());
    }

    void aLateWriteDoesNotBringBackTheFileOfACleanDocument()
    {
        QSemaphore gate;     // before the autosave: its writer thread may still touch them while it ends
        QSemaphore holding;
        QTemporaryDir dir;
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir.path());
        autosave.setDelay(0);
        doc.load(test::serverRoute());
        autosave.waitForWriter();
        // Hold the writer, so the write below is still pending when the document becomes clean.
        QMetaObject::invokeMethod(autosave.writer(), [&] { holding.release(); gate.acquire(); }, Qt::QueuedConnection);
        QVERIFY(holding.tryAcquire(1, 5000));
        const auto letGo = qScopeGuard([&gate] { gate.release(); }); // a failed check must not leave it held
        QSignalSpy written(&autosave, &RouteAutosave::written);
        QSignalSpy removed(&autosave, &RouteAutosave::removed);
        doc.editor()->addWaypoint(QGeoCoordinate(56.0, 24.0));
        QTRY_VERIFY(!autosave.isBatching()); // the timer fired: the write waits
        QCOMPARE(autosave.writer()->queued(), 1);
        doc.undo(); // clean again: the removal is queued behind the write
        gate.release();
        autosave.waitForWriter();
        QCoreApplication::processEvents(); // deliver what the writer emitted
        QVERIFY(!QFile::exists(autosave.filePath()));
        QCOMPARE(written.count(), 0); // the waiting write was dropped: the file was going anyway

        // The same with the write already done: the removal follows it.
        doc.redo();
        QVERIFY(autosave.writeNow());
        QVERIFY(QFile::exists(autosave.filePath()));
        doc.undo();
        QVERIFY(removed.wait(5000));
        autosave.waitForWriter();
        QVERIFY(!QFile::exists(autosave.filePath()));
    }

    void theNewestSnapshotWinsWhenWritesQueueUp()
    {
        QSemaphore gate;     // before the autosave: its writer thread may still touch them while it ends
        QSemaphore holding;
        QTemporaryDir dir;
        RouteDocument doc;
        RouteAutosave autosave(&doc, dir.path());
        autosave.setDelay(0);
        doc.load(test::serverRoute());
        autosave.waitForWriter();
        QMetaObject::invokeMethod(autosave.writer(), [&] { holding.release(); gate.acquire(); }, Qt::QueuedConnection);
        QVERIFY(holding.tryAcquire(1, 5000));
        const auto letGo = qScopeGuard([&gate] { gate.release(); }); // a failed check must not leave it held
        QSignalSpy written(&autosave, &RouteAutosave::written);
        doc.editor()->addWaypoint(QGeoCoordinate(56.0, 24.0));
        QTRY_VERIFY(!autosave.isBatching());
        QCOMPARE(autosave.writer()->queued(), 1);
        doc.editor()->addWaypoint(QGeoCoordinate(56.1, 24.1));
        QVERIFY(autosave.isBatching());
        QTRY_VERIFY(!autosave.isBatching());
        QCOMPARE(autosave.writer()->queued(), 1); // replaced, not appended
        gate.release();
        QVERIFY(written.wait(5000));
        autosave.waitForWriter();
        QCoreApplication::processEvents();
        QCOMPARE(written.count(), 1);
        QVERIFY(readFile(autosave.filePath()).working == doc.route());
        QCOMPARE(int(doc.route().segments.size()), 14);
    }

    void unsavedEditsOutliveTheInstanceAndAreRestoredAsOneStep()
    {
        QTemporaryDir dir;
        const mission::Route edited = leaveEdits(dir.path());
        QCOMPARE(client::AutosaveDirectory(dir.path()).slotsWithFiles(), QList<int>{1});

        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QVERIFY(recovery.isAvailable());
        const double altitude = std::get<mission::Waypoint>(test::serverRoute().segments[2]).altitude;
        QCOMPARE(recovery.changes(), (QStringList{QStringLiteral("WP 2 moved 33 m"),
                                                  QStringLiteral("altitude of WP 3 %1 → 100 m").arg(altitude),
                                                  QStringLiteral("WP 13 added")}));
        QVERIFY(recovery.summary().startsWith(QStringLiteral("3 changes: WP 2 moved 33 m")));
        QCOMPARE(recovery.routeName(), QStringLiteral("Autosave sample"));
        QCOMPARE(recovery.origin(), QStringLiteral("route 42, version 3, on 127.0.0.1:3334 as admin"));

        // This instance's own autosave takes another slot and leaves the offered file alone.
        RouteAutosave mine(&doc, dir.path());
        QCOMPARE(mine.slot(), 2);

        // Saving the restored edits updates route 42 on that server: restored only when signed in there.
        QVERIFY(recovery.restoreBlocker().contains(QStringLiteral("Sign in to 127.0.0.1:3334 as admin")));
        QVERIFY(!recovery.restore());
        recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
        QVERIFY(recovery.restoreBlocker().isEmpty());

        QSignalSpy restored(&recovery, &AutosaveRecovery::restored);
        QVERIFY(recovery.restore());
        QCOMPARE(restored.count(), 1);
        QVERIFY(doc.route() == edited);
        QVERIFY(doc.isModified());
        QCOMPARE(doc.undoText(), QStringLiteral("Restore autosaved edits"));
        QCOMPARE(hciRoute(doc.route().origin)->id(), 42); // saving goes to the same server route
        doc.undo();
        QVERIFY(doc.route() == test::serverRoute());
        doc.redo();
        QVERIFY(!recovery.isAvailable());
        QVERIFY(QFile::exists(client::AutosaveDirectory(dir.path()).discardedPath()));
        QVERIFY(!QFile::exists(client::AutosaveDirectory(dir.path()).filePath(1)));
    }

    void severalLeftoversAreOfferedInOneListNewestFirst()
    {
        QTemporaryDir dir;
        const mission::Route serverEdits = leaveEdits(dir.path()); // slot 1
        const mission::Route fileEdits = leaveFileEdits(dir.path(), QStringLiteral("Field B")); // slot 2
        client::AutosaveDirectory directory(dir.path());
        QFile older(directory.filePath(1));
        QVERIFY(older.open(QIODevice::ReadWrite));
        QVERIFY(older.setFileTime(QDateTime::currentDateTime().addSecs(-600), QFileDevice::FileModificationTime));
        older.close();

        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QVERIFY(recovery.isAvailable());
        QCOMPARE(recovery.count(), 2);
        QCOMPARE(recovery.rowCount(), 2);
        auto role = [&recovery](int row, int role) { return recovery.data(recovery.index(row), role); };
        QCOMPARE(role(0, AutosaveRecovery::RouteNameRole).toString(), QStringLiteral("Field B"));
        QCOMPARE(role(0, AutosaveRecovery::FileNameRole).toString(), directory.filePath(2));
        QCOMPARE(role(0, AutosaveRecovery::OriginRole).toString(), QString());
        QCOMPARE(role(0, AutosaveRecovery::RestoreBlockerRole).toString(), QString()); // a file's route: no session needed
        QCOMPARE(role(1, AutosaveRecovery::RouteNameRole).toString(), QStringLiteral("Autosave sample"));
        QCOMPARE(role(1, AutosaveRecovery::OriginRole).toString(), QStringLiteral("route 42, version 3, on 127.0.0.1:3334 as admin"));
        QVERIFY(role(1, AutosaveRecovery::SummaryRole).toString().startsWith(QStringLiteral("3 changes")));
        QVERIFY(!role(1, AutosaveRecovery::RestoreBlockerRole).toString().isEmpty());

        // The current row is the one the details show and the buttons act on.
        QCOMPARE(recovery.currentRow(), 0);
        QCOMPARE(recovery.changes(), QStringList{QStringLiteral("WP 13 added")});
        recovery.setCurrentRow(1);
        QCOMPARE(recovery.changes().size(), 3);
        recovery.discard(); // the server route's edits: kept as the discarded backup
        QCOMPARE(recovery.count(), 1);
        QCOMPARE(recovery.currentRow(), 0);
        QCOMPARE(recovery.routeName(), QStringLiteral("Field B"));
        QVERIFY(client::decodeAutosave([&] {
                    QFile f(directory.discardedPath());
                    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
                }()).value().working == serverEdits);
        QVERIFY(recovery.restore());
        QVERIFY(doc.route() == fileEdits);
        QVERIFY(!recovery.isAvailable());
        QVERIFY(directory.slotsWithFiles().isEmpty());
    }

    void afterARestoreTheOthersWaitForTheNextStart()
    {
        QTemporaryDir dir;
        leaveFileEdits(dir.path(), QStringLiteral("Field A"));
        leaveFileEdits(dir.path(), QStringLiteral("Field B"));
        {
            RouteDocument doc;
            AutosaveRecovery recovery(&doc, dir.path());
            QCOMPARE(recovery.count(), 2);
            QVERIFY(recovery.restore());
            QCOMPARE(recovery.count(), 0); // another restore would replace the route just restored
            // The dialog said the others are kept: nothing more to read after the restore.
            QVERIFY2(recovery.message().isEmpty(), qPrintable(recovery.message()));
        }
        RouteDocument next;
        AutosaveRecovery recovery(&next, dir.path());
        QCOMPARE(recovery.count(), 1);
    }

    void aSessionOnAnotherServerOrAsAnotherUserCannotRestoreAndIsToldWhatToDo()
    {
        QTemporaryDir dir;
        const mission::Route edited = leaveEdits(dir.path()); // route 42 on 127.0.0.1:3334 as admin
        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QSignalSpy changed(&recovery, &AutosaveRecovery::changed);
        QSignalSpy rowsChanged(&recovery, &AutosaveRecovery::dataChanged);

        recovery.setSession(QStringLiteral("10.0.0.7:3334"), QStringLiteral("admin"));
        QVERIFY(changed.count() > 0);
        QCOMPARE(rowsChanged.count(), 1);
        const QString blocker = recovery.restoreBlocker();
        QVERIFY2(blocker.contains(QStringLiteral("route 42 on 127.0.0.1:3334 as admin")), qPrintable(blocker));
        QVERIFY2(blocker.contains(QStringLiteral("signed in to 10.0.0.7:3334 as admin")), qPrintable(blocker));
        QVERIFY2(blocker.contains(QStringLiteral("Sign out and sign in to 127.0.0.1:3334 as admin")), qPrintable(blocker));
        QCOMPARE(recovery.data(recovery.index(0), AutosaveRecovery::RestoreBlockerRole).toString(), blocker);
        QVERIFY(!recovery.restore());
        QVERIFY(recovery.message().contains(blocker));
        QVERIFY(!doc.isModified());
        QVERIFY(doc.route().segments.empty());

        recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("operator"));
        QVERIFY(recovery.restoreBlocker().contains(QStringLiteral("signed in to 127.0.0.1:3334 as operator")));
        QVERIFY(!recovery.restore());

        // Unsaved edits of the route open now are not replaced either.
        recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
        doc.load(test::serverRoute());
        doc.editor()->addWaypoint(QGeoCoordinate(56.0, 24.0));
        QVERIFY(recovery.restoreBlocker().contains(QStringLiteral("unsaved edits")));
        QVERIFY(!recovery.restore());
        doc.undo();
        QVERIFY(recovery.restoreBlocker().isEmpty());
        QVERIFY(recovery.restore());
        QVERIFY(doc.route() == edited);
    }

    void laterHidesTheOfferUntilTheSessionChanges()
    {
        QTemporaryDir dir;
        leaveEdits(dir.path());
        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QVERIFY(recovery.isAvailable());
        recovery.postpone(); // to sign in first
        QVERIFY(!recovery.isAvailable());
        QCOMPARE(recovery.count(), 1); // still held, not discarded
        recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
        QVERIFY(recovery.isAvailable());
        QVERIFY(recovery.restore());
    }

    void aLiveInstancesAutosaveIsNotOffered()
    {
        QTemporaryDir dir;
        RouteDocument live;
        RouteAutosave autosave(&live, dir.path());
        live.load(test::serverRoute());
        test::editRoute(live);
        QVERIFY(autosave.writeNow());
        RouteDocument other;
        AutosaveRecovery recovery(&other, dir.path());
        QVERIFY(!recovery.isAvailable());
        QVERIFY(recovery.message().isEmpty());
        QVERIFY(QFile::exists(autosave.filePath()));
    }

    void anUnreadableFileIsKeptAsideAndNamed()
    {
        QTemporaryDir dir;
        leaveEdits(dir.path());
        client::AutosaveDirectory directory(dir.path());
        QFile file(directory.filePath(1));
        QVERIFY(file.open(QIODevice::ReadWrite));
        const QByteArray whole = file.readAll();
        file.resize(whole.size() / 2); // as a write cut short would leave it, were it not atomic
        file.close();

        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QVERIFY(!recovery.isAvailable());
        QVERIFY2(recovery.message().contains(directory.filePath(1)), qPrintable(recovery.message()));
        QVERIFY2(recovery.message().contains(QStringLiteral("kept as")), qPrintable(recovery.message()));
        const QStringList aside = QDir(dir.path()).entryList({QStringLiteral("autosave-1.unreadable-*.json")}, QDir::Files);
        QCOMPARE(aside.size(), 1);
        QFile kept(QDir(dir.path()).filePath(aside.first()));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), whole.left(whole.size() / 2)); // never deleted, not altered
        QVERIFY(recovery.message().contains(aside.first()));
    }

    void discardKeepsOneBackup()
    {
        QTemporaryDir dir;
        leaveEdits(dir.path());
        RouteDocument doc;
        AutosaveRecovery recovery(&doc, dir.path());
        QVERIFY(recovery.isAvailable());
        recovery.discard();
        QVERIFY(!recovery.isAvailable());
        QVERIFY(!doc.isModified());
        client::AutosaveDirectory directory(dir.path());
        QVERIFY(directory.slotsWithFiles().isEmpty());
        QVERIFY(client::decodeAutosave([&] {
                    QFile f(directory.discardedPath());
                    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
                }()).ok());
    }

    void decodeErrorsSayWhere()
    {
        QCOMPARE(client::decodeAutosave("{\"format\": \"sortie-mission\"}").error().jsonPath, QStringLiteral("/format"));
        client::AutosaveRecord record;
        record.working = test::serverRoute();
        record.baseline = record.working;
        record.savedAt = QDateTime::currentDateTimeUtc();
        QByteArray data = client::encodeAutosave(record);
        QVERIFY(client::decodeAutosave(data).ok());
        data.replace("\"schemaVersion\"", "\"schemaVersio\"");
        const auto broken = client::decodeAutosave(data);
        QVERIFY(!broken.ok());
        QVERIFY2(broken.error().jsonPath.startsWith(QStringLiteral("/working")), qPrintable(broken.error().toString()));
    }
};

QTEST_GUILESS_MAIN(TestRouteAutosave)
#include "tst_routeautosave.moc"
