// "Never lose an edit" through the main window, offscreen: a previous run's unsaved edits are
// offered at start (the dialog lists the changes; Restore puts them on the map and in the table),
// and a version conflict shows both copies (the banner lists the differences, their route is a
// grey ghost on the map) until a button resolves it.
#include "AppSettings.h"
#include "AutosaveRecovery.h"
#include "ClientWindow.h"
#include "AutosaveTestRoute.h"
#include "ConnectionController.h"
#include "HciClient.h"
#include "HciReply.h"
#include "HciServer.h"
#include "Messages.pb.h"
#include "MissionController.h"
#include "PasswordVault.h"
#include "QuickScene.h"
#include "RouteAutosave.h"
#include "RouteLayer.h"
#include "SimWorld.h"
#include "SortieUi.h"

#include <QFile>
#include <QGeoCoordinate>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
namespace pb = com::ugcs::ucs::proto;

class TestRecoveryFlows : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_app; // the program's graph and window, against the simulator
    QQuickWindow *m_window = nullptr;

    template<typename T = QQuickItem>
    T *find(const char *name) const { return m_window->findChild<T *>(QString::fromLatin1(name)); }
    void click(const char *name)
    {
        QQuickItem *item = find(name);
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled() && item->width() > 0, name);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint());
    }

    // The client as the program starts it, recovering from `autosaves` (empty: a folder of its own).
    void showWindow(const QString &autosaves = {}, std::function<void(test::ClientWindow &)> beforeClient = {})
    {
        test::ClientWindow::Options options;
        options.vciVehicles = 0;
        options.autosaveDirectory = autosaves;
        options.beforeClient = std::move(beforeClient);
        m_app = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_app->isReady(), qPrintable(m_app->error()));
        m_window = m_app->window();
    }
    client::MissionController *missions() { return &m_app->missions(); }
    client::AutosaveRecovery *recovery() { return m_app->graph().recovery(); }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void cleanup()
    {
        m_window = nullptr;
        m_app.reset();
    }

    void restoreDialogShowsTheChangesAndRestores()
    {
        QTemporaryDir autosaves;
        mission::Route edited;
        { // a run that quit with unsaved edits
            client::RouteDocument doc;
            client::RouteAutosave autosave(&doc, autosaves.path());
            doc.load(test::serverRoute());
            test::editRoute(doc);
            edited = doc.route();
        }
        showWindow(autosaves.path());
        QObject *dialog = find<QObject>("restoreDialog");
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->property("visible").toBool());
        QQuickItem *changes = find("restoreChanges");
        QVERIFY(changes);
        QTRY_COMPARE(changes->property("count").toInt(), 3);
        click("restoreAutosaveButton");
        QTRY_VERIFY(!dialog->property("visible").toBool());
        QTRY_COMPARE(m_window->property("currentPage").toInt(), 1);
        auto *route = find<ui::RouteLayer>("routeLayer");
        QTRY_COMPARE(route->count(), 13);
        QTRY_COMPARE(find("waypointList")->property("count").toInt(), 13);
        QTRY_COMPARE(route->visibleWaypointCount(), 13); // fitted to the map
        QVERIFY(missions()->document()->route() == edited);
        QVERIFY(missions()->document()->isModified());
    }

    // An autosave that cannot be read is kept aside and the dialog says where, with nothing to
    // restore, until the operator has read it.
    void anUnreadableAutosaveIsSaidUntilRead()
    {
        QTemporaryDir autosaves;
        {
            client::RouteDocument doc;
            client::RouteAutosave autosave(&doc, autosaves.path());
            doc.load(test::serverRoute());
            test::editRoute(doc);
        }
        QFile file(client::AutosaveDirectory(autosaves.path()).filePath(1));
        QVERIFY(file.open(QIODevice::ReadWrite));
        QVERIFY(file.resize(file.size() / 2));  // as a cut-short write would leave it
        file.close();
        showWindow(autosaves.path());
        QVERIFY(!recovery()->isAvailable());
        QObject *dialog = find<QObject>("restoreDialog");
        QTRY_VERIFY(dialog->property("visible").toBool());
        QQuickItem *message = find("recoveryMessage");
        QTRY_VERIFY(message && message->isVisible());
        QVERIFY2(message->property("text").toString().contains(QStringLiteral("kept as")), qPrintable(message->property("text").toString()));
        QVERIFY(!find("restoreAutosaveButton")->isVisible());
        QVERIFY(!find("restoreChanges")->isVisible());
        click("acknowledgeRecoveryButton");
        QTRY_VERIFY(!dialog->property("visible").toBool());
        QVERIFY(recovery()->message().isEmpty());
    }

    void severalAutosavesInOneListAndAServerRouteWaitsForItsSession()
    {
        QTemporaryDir autosaves;
        QString server;
        mission::Route edited;
        showWindow(autosaves.path(), [&](test::ClientWindow &app) {
            server = QStringLiteral("127.0.0.1:%1").arg(app.server().port());
            { // a run that was editing a route of this server as admin
                client::RouteDocument doc;
                client::RouteAutosave autosave(&doc, autosaves.path());
                autosave.setServer(server, QStringLiteral("admin"));
                doc.load(test::serverRoute());
                test::editRoute(doc);
                edited = doc.route();
            }
            { // an older run editing a route from a file
                client::RouteDocument doc;
                client::RouteAutosave autosave(&doc, autosaves.path());
                mission::Route route = test::serverRoute();
                route.origin = {};
                route.settings.name = QStringLiteral("Field B");
                doc.load(route);
                doc.editor()->addWaypoint(QGeoCoordinate(56.5, 24.5));
            } // written once more as it goes
            QFile older(client::AutosaveDirectory(autosaves.path()).filePath(2));
            QVERIFY(older.open(QIODevice::ReadWrite));
            QVERIFY(older.setFileTime(QDateTime::currentDateTime().addSecs(-600), QFileDevice::FileModificationTime));
            older.close();
        }); // the client starts, as the program wires it: the recovery follows the session
        QObject *dialog = find<QObject>("restoreDialog");
        QTRY_VERIFY(dialog->property("visible").toBool());
        QTRY_COMPARE(find("autosaveList")->property("count").toInt(), 2);
        QVERIFY(find("autosaveList")->isVisible());
        // The newest, the server route's, is chosen: not restorable before signing in, and it says so.
        QTRY_COMPARE(find("restoreChanges")->property("count").toInt(), 3);
        QQuickItem *blocker = find("restoreBlocker");
        QTRY_VERIFY(blocker->isVisible());
        QVERIFY(blocker->property("text").toString().contains(QStringLiteral("Sign in to %1 as admin").arg(server)));
        QVERIFY(!find("restoreAutosaveButton")->isEnabled());
        if (qEnvironmentVariableIsSet("SORTIE_SHOTS"))
            m_window->grabWindow().save(qEnvironmentVariable("SORTIE_SHOTS") + QStringLiteral("/restore-list.png"));

        click("laterAutosaveButton"); // to sign in first
        QTRY_VERIFY(!dialog->property("visible").toBool());
        QSignalSpy ready(&m_app->connection(), &client::ConnectionController::ready);
        m_app->connection().connectToServer(server, QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
        QTRY_VERIFY(dialog->property("visible").toBool()); // offered again, now restorable
        QTRY_VERIFY(!blocker->isVisible());
        QCOMPARE(recovery()->currentRow(), 0);
        click("restoreAutosaveButton");
        QTRY_VERIFY(!dialog->property("visible").toBool());
        QTRY_COMPARE(m_window->property("currentPage").toInt(), 1);
        QVERIFY(missions()->document()->route() == edited);
        // The other stays on disk for the next start (beside this run's own autosave, in a slot of its own).
        QVERIFY(client::AutosaveDirectory(autosaves.path()).slotsWithFiles().contains(2));
        QVERIFY(!client::AutosaveDirectory(autosaves.path()).slotsWithFiles().contains(1));
    }

    void conflictShowsBothCopiesUntilAButtonResolvesIt()
    {
        showWindow();
        QSignalSpy ready(&m_app->connection(), &client::ConnectionController::ready);
        m_app->connection().connectToServer(QStringLiteral("127.0.0.1:%1").arg(m_app->server().port()), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
        QTRY_VERIFY(missions()->routes()->count() > 0);
        const int id = missions()->routes()->objectIdAt(0);
        missions()->openRoute(id);
        QTRY_COMPARE(missions()->routeId(), id);
        client::RouteDocument *doc = missions()->document();
        const int count = doc->model()->count();
        doc->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));

        // Someone else saves the route meanwhile, with a waypoint fewer.
        hci::HciSession other;
        hci::HciClient bob(&other);
        QSignalSpy otherReady(&other, &hci::HciSession::ready);
        other.open(QStringLiteral("127.0.0.1"), m_app->server().port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(otherReady.wait(10000));
        hci::HciReply *get = bob.getObject(hci::HciObjectType::Route, id);
        QSignalSpy got(get, &hci::HciReply::finished);
        QVERIFY(get->isFinished() || got.wait(10000));
        pb::Route theirs = get->response<pb::GetObjectResponse>().object().route();
        theirs.mutable_segments()->RemoveLast();
        hci::HciReply *put = bob.createOrUpdate(theirs);
        QSignalSpy stored(put, &hci::HciReply::finished);
        QVERIFY(put->isFinished() || stored.wait(10000));

        QTRY_VERIFY(find("conflictBanner")->isVisible());
        QTRY_COMPARE(find("conflictChanges")->property("count").toInt(), 2); // theirs lacks one, mine has one more
        auto *ghost = find<ui::RouteLayer>("theirRouteLayer");
        QVERIFY(ghost->isVisible());
        QCOMPARE(ghost->count(), count - 1);
        QCOMPARE(find<ui::RouteLayer>("routeLayer")->count(), count + 1);

        click("takeTheirsButton");
        QTRY_VERIFY(!find("conflictBanner")->isVisible());
        QVERIFY(!ghost->isVisible());
        QTRY_COMPARE(find<ui::RouteLayer>("routeLayer")->count(), count - 1);
        QVERIFY(!doc->isModified());
        doc->undo(); // mine again
        QCOMPARE(find<ui::RouteLayer>("routeLayer")->count(), count + 1);
        other.close();
    }
};

QTEST_MAIN(TestRecoveryFlows)
#include "tst_recoveryflows.moc"
