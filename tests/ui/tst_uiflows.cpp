// Real flows through the main window against the embedded simulator, driven by simulated mouse
// and keys offscreen: log in (bad password, then good), open a route, add, move and delete
// waypoints on the map and in the table, undo, save and see the server's copy change from a
// second session, draw an area scan, upload with the progress bar moving.
#include "AppSettings.h"
#include "ClientWindow.h"
#include "ConnectionController.h"
#include "HciClient.h"
#include "HciReply.h"
#include "HciServer.h"
#include "MapView.h"
#include "Messages.pb.h"
#include "MissionController.h"
#include "QuickScene.h"
#include "RouteLayer.h"
#include "SimVciListener.h"
#include "VehicleFleet.h"
#include "VehicleLayer.h"
#include "TelemetryPlot.h"
#include "SortieUi.h"

#include <QDir>

#include <algorithm>
#include <functional>
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
using ui::MapView;
using ui::RouteLayer;

namespace {
// QTest::keyClicks takes widgets only: one key at a time for a QWindow.
void typeText(QWindow *window, const QString &text)
{
    for (QChar c : text)
        QTest::keyClick(window, c.toLatin1());
}

// The item a left press at scenePos reaches first, as Qt Quick picks it: the top-most visible and
// enabled item there that takes the button (children in stacking order, the last drawn first).
QQuickItem *pressTarget(QQuickItem *item, const QPointF &scenePos)
{
    if (!item->isVisible() || !item->isEnabled())
        return nullptr;
    const bool inside = item->contains(item->mapFromScene(scenePos));
    if (item->clip() && !inside)
        return nullptr;
    QList<QQuickItem *> children = item->childItems();
    std::stable_sort(children.begin(), children.end(), [](QQuickItem *a, QQuickItem *b) { return a->z() < b->z(); });
    for (auto it = children.crbegin(); it != children.crend(); ++it)
        if (QQuickItem *target = pressTarget(*it, scenePos))
            return target;
    return inside && (item->acceptedMouseButtons() & Qt::LeftButton) ? item : nullptr;
}
} // namespace

class TestUiFlows : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_app; // the program's graph and window, against the simulator
    QQuickWindow *m_window = nullptr;

    // By objectName, through QObject children and the item tree (a Repeater's delegates are only in the latter).
    static QQuickItem *findItem(QQuickItem *root, const QString &name)
    {
        for (QQuickItem *child : root->childItems()) {
            if (child->objectName() == name)
                return child;
            if (QQuickItem *found = findItem(child, name))
                return found;
        }
        return nullptr;
    }
    template<typename T = QQuickItem>
    T *find(const char *name) const
    {
        T *found = m_window->findChild<T *>(QString::fromLatin1(name));
        if (!found)
            found = qobject_cast<T *>(findItem(m_window->contentItem(), QString::fromLatin1(name)));
        if (!found)
            qWarning("no item named %s", name);
        return found;
    }
    QPoint centreOf(QQuickItem *item) const
    {
        return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
    }
    void click(const char *name)
    {
        QQuickItem *item = find(name);
        QVERIFY(item);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled(), name);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centreOf(item));
    }
    void type(const char *field, const QString &text)
    {
        QQuickItem *item = find(field);
        QVERIFY(item);
        QTRY_VERIFY2(item->isVisible() && item->width() > 0 && QRect(QPoint(), m_window->size()).contains(centreOf(item)), field);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centreOf(item));
        QTRY_VERIFY(item->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        typeText(m_window, text);
    }
    QString text(const char *name) const { return find<QObject>(name)->property("text").toString(); }
    MapView *missionMap() const { return m_window->property("missionPage").value<QObject *>()->property("map").value<MapView *>(); }
    RouteLayer *routeLayer() const { return find<RouteLayer>("routeLayer"); }

    void logIn(const QString &password)
    {
        QTest::keyClick(m_window, Qt::Key_1, Qt::ControlModifier);
        type("serverField", QStringLiteral("127.0.0.1:%1").arg(m_app->server().port()));
        type("userField", QStringLiteral("admin"));
        type("passwordField", password);
        click("connectButton");
    }

    void openDemoRoute()
    {
        logIn(QStringLiteral("admin"));
        QTRY_COMPARE(m_window->property("currentPage").toInt(), 1);
        QObject *picker = find<QObject>("routePicker");
        QTRY_VERIFY(picker->property("count").toInt() > 0);
        QTRY_VERIFY(!m_app->missions().isBusy()); // the lists have arrived and will not be reset under us
        // The keyboard way: focus the picker, Down picks the first route.
        find("routePicker")->forceActiveFocus(Qt::TabFocusReason);
        QTRY_VERIFY(find("routePicker")->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_Down);
        QTRY_COMPARE(picker->property("currentIndex").toInt(), 0);
        // Tab to the Open button and press it with the space bar.
        QTest::keyClick(m_window, Qt::Key_Tab);
        QTRY_VERIFY(find("openRouteButton")->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_Space);
        QTRY_VERIFY2(routeLayer()->count() == 4, qPrintable(m_app->missions().message() + QStringLiteral(" / picker value ")
                                                             + picker->property("currentValue").toString()));
        QTRY_COMPARE(routeLayer()->visibleWaypointCount(), 4); // fitted to the map
    }

    pb::Route serverCopy(int routeId)
    {
        hci::HciSession other;
        hci::HciClient client(&other);
        QSignalSpy ready(&other, &hci::HciSession::ready);
        other.open(QStringLiteral("127.0.0.1"), m_app->server().port(), QStringLiteral("admin"), QStringLiteral("admin"));
        if (!ready.wait(10000))
            return {};
        hci::HciReply *reply = client.getObject(hci::HciObjectType::Route, routeId);
        reply->setAutoDelete(false);
        QSignalSpy done(reply, &hci::HciReply::finished);
        if (!reply->isFinished())
            done.wait(10000);
        pb::Route route = reply->response<pb::GetObjectResponse>().object().route();
        delete reply;
        other.close();
        return route;
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void init()
    {
        test::ClientWindow::Options options;
        options.uploadStepMs = 40;
        options.activate = true;
        m_app = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_app->isReady(), qPrintable(m_app->error()));
        m_window = m_app->window();
    }

    void cleanup()
    {
        m_window = nullptr;
        m_app.reset();
    }

    void badPasswordThenGood()
    {
        logIn(QStringLiteral("wrong"));
        QTRY_VERIFY(text("loginMessage").startsWith(QStringLiteral("Wrong user name or password")));
        QCOMPARE(text("connectionStateLabel"), QStringLiteral("Disconnected"));
        QVERIFY(!text("loginMessage").contains(QStringLiteral("wrong")));
        m_window->grabWindow().save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("login-error.png")));

        logIn(QStringLiteral("admin"));
        QTRY_VERIFY(text("connectionStateLabel").startsWith(QStringLiteral("Ready")));
        QVERIFY(text("connectionStateLabel").contains(QStringLiteral("admin at 127.0.0.1")));
        QCOMPARE(m_window->property("currentPage").toInt(), 1); // on to the mission
        QCOMPARE(m_app->settings().lastUser(), QStringLiteral("admin"));
    }

    void editOnTheMapUndoAndSave()
    {
        openDemoRoute();
        const int routeId = m_app->missions().routeId();
        MapView *map = missionMap();
        RouteLayer *route = routeLayer();

        // Click on empty map: a waypoint is added there.
        const QPointF empty = route->waypointPosition(0) + QPointF(0, 120);
        QVERIFY(route->waypointAt(empty) < 0 && route->legAt(empty) < 0);
        const QPoint at = map->mapToScene(empty).toPoint();
        const QGeoCoordinate where = map->toCoordinate(map->mapFromScene(at));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, at);
        QTRY_COMPARE(route->count(), 5);
        QVERIFY(std::abs(m_app->missions().document()->model()->index(4).data(mission::RouteModel::LatitudeRole).toDouble() - where.latitude()) < 1e-7);

        // Drag waypoint 2 by (30, 20) pixels.
        const QPoint from = map->mapToScene(route->waypointPosition(1)).toPoint();
        const QGeoCoordinate dropped = map->toCoordinate(route->waypointPosition(1) + QPointF(30, 20));
        QTest::mousePress(m_window, Qt::LeftButton, {}, from);
        QTest::mouseMove(m_window, from + QPoint(10, 7));
        QTest::mouseMove(m_window, from + QPoint(30, 20));
        QTest::mouseRelease(m_window, Qt::LeftButton, {}, from + QPoint(30, 20));
        const QModelIndex second = m_app->missions().document()->model()->index(1);
        QTRY_VERIFY(std::abs(second.data(mission::RouteModel::LatitudeRole).toDouble() - dropped.latitude()) < 1e-7);

        // Del removes the selected waypoint (the one just dragged); Ctrl+Z brings it back.
        QCOMPARE(m_app->missions().document()->selectedRows(), QList<int>{1});
        QTest::keyClick(m_window, Qt::Key_Delete);
        QTRY_COMPARE(route->count(), 4);
        QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
        QTRY_COMPARE(route->count(), 5);

        // In the table: the first row's altitude, typed in place.
        QQuickItem *list = find("waypointList");
        QVERIFY(list);
        QTRY_VERIFY(list->property("count").toInt() == 5);
        QList<QQuickItem *> cells;
        std::function<void(QQuickItem *)> collect = [&](QQuickItem *item) {
            if (item->property("role").toString() == QLatin1String("altitude") && item->isVisible())
                cells.append(item);
            for (QQuickItem *child : item->childItems())
                collect(child);
        };
        collect(list);
        QVERIFY(!cells.isEmpty());
        std::sort(cells.begin(), cells.end(), [](QQuickItem *a, QQuickItem *b) { return a->mapToScene({0, 0}).y() < b->mapToScene({0, 0}).y(); });
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centreOf(cells.first()));
        QTRY_VERIFY(cells.first()->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        typeText(m_window, QStringLiteral("77"));
        QTest::keyClick(m_window, Qt::Key_Return);
        QTRY_COMPARE(m_app->missions().document()->model()->index(0).data(mission::RouteModel::AltitudeRole).toDouble(), 77.0);

        // Ctrl+S saves under the lock; a second session sees the server's copy changed.
        missionMap()->forceActiveFocus();
        QSignalSpy saved(&m_app->missions(), &client::MissionController::saved);
        QTest::keyClick(m_window, Qt::Key_S, Qt::ControlModifier);
        QVERIFY(saved.wait(10000));
        const pb::Route copy = serverCopy(routeId);
        QCOMPARE(copy.segments_size(), 5);
        QCOMPARE(copy.version(), 2);
        QTRY_VERIFY(text("missionMessage").contains(QStringLiteral("Saved")));
    }

    // Issue 36: Open over unsaved edits threw them away without a word. Now it asks: Cancel keeps
    // them, Discard opens the server's copy with the edits one Undo away, Save saves and opens.
    void openOverUnsavedEditsAsks()
    {
        openDemoRoute();
        const int routeId = m_app->missions().routeId();
        RouteLayer *route = routeLayer();
        const QPoint at = missionMap()->mapToScene(route->waypointPosition(0) + QPointF(0, 120)).toPoint();
        QTest::mouseClick(m_window, Qt::LeftButton, {}, at);
        QTRY_COMPARE(route->count(), 5);

        QObject *question = find<QObject>("openQuestion");
        QVERIFY(question);
        QVERIFY(!question->property("opened").toBool());
        click("openRouteButton");
        QTRY_VERIFY(question->property("opened").toBool());
        QVERIFY2(text("openQuestionText").contains(QStringLiteral("unsaved edits")), qPrintable(text("openQuestionText")));
        click("cancelOpenButton");
        QTRY_VERIFY(!question->property("visible").toBool());
        QCOMPARE(route->count(), 5);
        QVERIFY(m_app->missions().document()->isModified());

        click("openRouteButton");
        QTRY_VERIFY(question->property("opened").toBool());
        click("discardThenOpenButton");
        QTRY_VERIFY(!question->property("visible").toBool());
        QTRY_COMPARE(route->count(), 4);
        QVERIFY(!m_app->missions().document()->isModified());
        click("undoButton");
        QTRY_COMPARE(route->count(), 5);
        QVERIFY(m_app->missions().document()->isModified());

        QSignalSpy saved(&m_app->missions(), &client::MissionController::saved);
        QSignalSpy opened(&m_app->missions(), &client::MissionController::routeOpened);
        click("openRouteButton");
        QTRY_VERIFY(question->property("opened").toBool());
        click("saveThenOpenButton");
        QVERIFY(opened.wait(10000));
        QCOMPARE(saved.count(), 1);
        QCOMPARE(route->count(), 5);
        QVERIFY(!m_app->missions().document()->isModified());
        QCOMPARE(serverCopy(routeId).segments_size(), 5);
    }

    // The route's server zone checks: shown as the server sent them (the demo route checks
    // aerodrome zones only), a click is one undo step, and the save carries it to the server.
    void serverZoneChecksInTheRoutePanel()
    {
        openDemoRoute();
        const int routeId = m_app->missions().routeId();
        QTRY_VERIFY(find<QObject>("checkAerodromeNfz")->property("checked").toBool());
        QVERIFY(!find<QObject>("checkCustomNfz")->property("checked").toBool());
        click("nfzChecksButton");
        click("checkCustomNfz");
        QTRY_VERIFY(m_app->missions().document()->model()->checkCustomNfz());
        QVERIFY(find<QObject>("checkCustomNfz")->property("checked").toBool());
        missionMap()->forceActiveFocus();
        QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(!find<QObject>("checkCustomNfz")->property("checked").toBool());
        click("nfzChecksButton");
        click("checkCustomNfz");
        QTRY_VERIFY(m_app->missions().document()->model()->checkCustomNfz());
        missionMap()->forceActiveFocus();
        QSignalSpy saved(&m_app->missions(), &client::MissionController::saved);
        QTest::keyClick(m_window, Qt::Key_S, Qt::ControlModifier);
        QVERIFY(saved.wait(10000));
        const pb::Route copy = serverCopy(routeId);
        QVERIFY(copy.checkcustomnfz());
        QVERIFY(copy.checkaerodromenfz());
    }

    void areaScanOnTheMap()
    {
        openDemoRoute();
        MapView *map = missionMap();
        click("scanToolButton");
        // A clear stretch of the map below the route (it is fitted the same way every time), above
        // the terrain profile.
        const QPointF base(450, map->height() - 150);
        for (const QPointF &corner : {QPointF(0, 0), QPointF(160, 0), QPointF(160, 110), QPointF(0, 110)}) {
            QVERIFY(routeLayer()->waypointAt(base + corner) < 0 && routeLayer()->legAt(base + corner) < 0);
            QTest::mouseClick(m_window, Qt::LeftButton, {}, map->mapToScene(base + corner).toPoint());
        }
        QQuickItem *draft = find("scanDraftLayer");
        QTRY_COMPARE(draft->property("vertexCount").toInt(), 4);
        click("finishScanButton");
        QTRY_COMPARE(routeLayer()->count(), 5);
        QQuickItem *area = find("areaLayer");
        QTRY_COMPARE(area->property("vertexCount").toInt(), 4);
        QVERIFY(area->property("transectPointCount").toInt() >= 4);
        client::RouteDocument *doc = m_app->missions().document();
        QCOMPARE(doc->model()->index(4).data(mission::RouteModel::KindRole).toString(), QStringLiteral("areaScan"));
        QCOMPARE(doc->currentRow(), 4);

        // Its corners are handles now: drag the third one out; the path follows and it is one undo step.
        const int stepsBefore = doc->undoStack()->count();
        const int pathBefore = area->property("transectPointCount").toInt();
        const QPoint corner = map->mapToScene(base + QPointF(160, 110)).toPoint();
        const QGeoCoordinate dropped = map->toCoordinate(base + QPointF(160, 110) + QPointF(60, 40));
        QTest::mousePress(m_window, Qt::LeftButton, {}, corner);
        for (int i = 1; i <= 6; ++i)
            QTest::mouseMove(m_window, corner + QPoint(10 * i, 40 * i / 6));
        QTest::mouseRelease(m_window, Qt::LeftButton, {}, corner + QPoint(60, 40));
        const auto polygonOf = [doc] { return std::get<mission::AreaScan>(doc->model()->segment(4)).polygon; };
        QTRY_VERIFY(std::abs(polygonOf()[2].latitude - dropped.latitude()) < 1e-6);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 1);
        // The path is planned again off the drag (coalesced): wait for it.
        QTRY_VERIFY(area->property("transectPointCount").toInt() >= pathBefore);

        // The side overlap typed in the editor; then undo both.
        type("segment_overlapSide", QStringLiteral("80"));
        QTest::keyClick(m_window, Qt::Key_Return);
        QTRY_COMPARE(std::get<mission::AreaScan>(doc->model()->segment(4)).parameters.sideOverlapPercent, 80.0);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 2);
        doc->undo();
        doc->undo();
        QVERIFY(std::abs(polygonOf()[2].latitude - map->toCoordinate(base + QPointF(160, 110)).latitude()) < 1e-6);
        doc->redo();
        QTest::qWait(150);
        m_window->grabWindow().save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("mission.png")));
    }

    void uploadMovesTheProgressBar()
    {
        openDemoRoute();
        QObject *vehicles = find<QObject>("vehiclePicker");
        QTRY_VERIFY(vehicles->property("count").toInt() == 3);
        vehicles->setProperty("currentIndex", 0);
        QObject *bar = find<QObject>("progressBar");
        QList<double> values;
        // The bar's binding runs first (it was connected at load): read what it shows.
        connect(m_app->missions().preparation()->uploader(), &client::MissionUploader::progressChanged, bar, [&values, bar] {
            if (bar->property("to").toDouble() > 1)
                values.append(bar->property("value").toDouble());
        });
        QSignalSpy uploaded(m_app->missions().preparation(), &client::RoutePreparation::uploaded);
        click("uploadButton");
        QVERIFY(uploaded.wait(20000));
        QVERIFY2(values.size() >= 3, qPrintable(QString::number(values.size())));
        QVERIFY(values.last() > values.first());
        QTRY_VERIFY2(text("preparationMessage").startsWith(QStringLiteral("Uploaded to EMU-101: ")), qPrintable(text("preparationMessage")));
    }
    // The demo route to a VCI vehicle: planned in the client, its heights made relative to the
    // vehicle's home through the ground the program's terrain (the server's) gives, so the result has
    // no note of heights flown above home. (Without a terrain source it has: tst_vciterrain.)
    void uploadToAVciVehicleFliesOverTheGround()
    {
        openDemoRoute();
        QVERIFY(m_app->fleet().addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(m_app->vci().listeners().front()->port())));
        QObject *vehicles = find<QObject>("vehiclePicker");
        QTRY_COMPARE(vehicles->property("count").toInt(), 4);
        QTRY_COMPARE_WITH_TIMEOUT(m_app->fleet().index(3).data(client::VehicleFleet::LinkStateRole).toString(), QStringLiteral("Connected"), 10000);
        vehicles->setProperty("currentIndex", 3);
        QSignalSpy uploaded(m_app->missions().preparation(), &client::RoutePreparation::uploaded);
        click("uploadButton");
        QVERIFY2(uploaded.wait(20000), qPrintable(text("preparationMessage")));
        QTRY_VERIFY2(text("preparationMessage").startsWith(QStringLiteral("Uploaded to ")), qPrintable(text("preparationMessage")));
        QVERIFY2(!text("preparationMessage").contains(QStringLiteral("as a height above home")), qPrintable(text("preparationMessage")));
        if (qEnvironmentVariableIsSet("SORTIE_SCREENSHOT_DIR"))
            m_window->grabWindow().save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR")).filePath(QStringLiteral("vci-upload.png")));
    }

    void actionsAtAWaypoint()
    {
        openDemoRoute();
        MapView *map = missionMap();
        client::RouteDocument *doc = m_app->missions().document();
        // Click waypoint 2 on the map: its action editor appears, empty.
        QTest::mouseClick(m_window, Qt::LeftButton, {}, map->mapToScene(routeLayer()->waypointPosition(1)).toPoint());
        QTRY_COMPARE(doc->currentRow(), 1);
        QTRY_VERIFY(find("actionEditor")->isVisible());
        QCOMPARE(find<QObject>("actionEditor")->property("title").toString(), QStringLiteral("Actions at waypoint 2"));
        const auto actionsOf = [doc] { return std::get<mission::Waypoint>(doc->model()->segment(1)).actions; };
        const size_t before = actionsOf().size();

        // Pick "Photos by distance" with the keyboard and add it.
        QQuickItem *picker = find("actionKindPicker");
        picker->forceActiveFocus(Qt::TabFocusReason);
        QTRY_VERIFY(picker->hasActiveFocus());
        const QList<mission::ActionKindChoice> kinds = doc->actionEditor()->kindChoices();
        QCOMPARE(picker->property("model").toStringList(), doc->actionEditor()->kindLabels());
        int wanted = -1;
        for (int i = 0; i < kinds.size(); ++i)
            if (kinds[i].kind == QStringLiteral("cameraSeriesByDistance"))
                wanted = i;
        QVERIFY(wanted >= 0);
        while (picker->property("currentIndex").toInt() < wanted)
            QTest::keyClick(m_window, Qt::Key_Down);
        QCOMPARE(picker->property("currentIndex").toInt(), wanted);
        click("addActionButton");
        QTRY_COMPARE(actionsOf().size(), before + 1);
        const int added = int(before);

        // Its distance typed in its field: the table says so, and it is one undo step.
        const QByteArray fieldName = "action_" + QByteArray::number(added) + "_intervalMeters";
        type(fieldName.constData(), QStringLiteral("25"));
        QTest::keyClick(m_window, Qt::Key_Return);
        QTRY_COMPARE(std::get<mission::CameraSeriesByDistanceAction>(actionsOf()[size_t(added)]).intervalMeters, 25.0);
        QTRY_VERIFY(doc->model()->index(1).data(mission::RouteModel::ActionsSummaryRole).toString().contains(QStringLiteral("Photo every 25 m")));
        // A value out of range is refused on screen and changes nothing.
        type(fieldName.constData(), QStringLiteral("-5"));
        QTest::keyClick(m_window, Qt::Key_Return);
        QTRY_VERIFY(!text("actionProblem").isEmpty());
        QCOMPARE(std::get<mission::CameraSeriesByDistanceAction>(actionsOf()[size_t(added)]).intervalMeters, 25.0);
        doc->undo();
        QCOMPARE(std::get<mission::CameraSeriesByDistanceAction>(actionsOf()[size_t(added)]).intervalMeters, 10.0);
        click(("removeAction_" + QByteArray::number(added)).constData());
        QTRY_COMPARE(actionsOf().size(), before);

        // An action's fields are in their places the moment it is added, before a frame is drawn:
        // a click at a field's centre reaches that field (they stood on top of one another at the
        // editor's corner until the next frame, and a quick click landed in the last one).
        QVERIFY(doc->actionEditor()->add(QStringLiteral("cameraSeriesByDistance")));
        for (const char *name : {"_intervalMeters", "_shots", "_startDelaySeconds"}) {
            QQuickItem *field = find(("action_" + QByteArray::number(added) + name).constData());
            QVERIFY(field);
            QQuickItem *target = pressTarget(m_window->contentItem(), field->mapToScene(QPointF(field->width() / 2, field->height() / 2)));
            QQuickItem *named = target;
            while (named && named->objectName().isEmpty())
                named = named->parentItem();
            QVERIFY2(target == field || field->isAncestorOf(target),
                     qPrintable(QStringLiteral("a click at the centre of %1 reaches %2").arg(field->objectName(), named ? named->objectName() : QStringLiteral("nothing"))));
        }
        doc->actionEditor()->remove(added);
        QTRY_COMPARE(actionsOf().size(), before);

        // A choice shows the action's value worded, and a choice made sends that choice's value.
        QVERIFY(doc->actionEditor()->add(QStringLiteral("cameraTrigger")));
        QQuickItem *state = nullptr;
        QTRY_VERIFY((state = find(("action_" + QByteArray::number(added) + "_state_choice").constData())));
        QVERIFY(state->isVisible());
        const QStringList texts = state->property("model").toStringList();
        const int shown = state->property("currentIndex").toInt();
        QVERIFY2(shown >= 0 && shown < texts.size(), qPrintable(texts.join(QLatin1Char('|'))));
        QCOMPARE(state->property("currentText").toString(), texts[shown]);
        int recording = -1;
        for (const mission::ActionFieldRow &row : doc->actionEditor()->fieldsOf(added))
            if (row.name == QStringLiteral("state"))
                recording = int(row.choiceValues.indexOf(QStringLiteral("startRecording")));
        QVERIFY(recording >= 0 && recording < texts.size());
        QCOMPARE(texts[recording], QStringLiteral("Start video"));
        QVERIFY(QMetaObject::invokeMethod(state, "activated", Q_ARG(int, recording)));
        QTRY_COMPARE(std::get<mission::CameraTriggerAction>(actionsOf()[size_t(added)]).state, mission::TriggerState::StartRecording);
        QTRY_COMPARE(state->property("currentIndex").toInt(), recording);
        doc->actionEditor()->remove(added);
        QTRY_COMPARE(actionsOf().size(), before);
    }

    void liveTelemetryAndCommands()
    {
        logIn(QStringLiteral("admin"));
        QTRY_COMPARE(m_window->property("currentPage").toInt(), 1);
        QTest::keyClick(m_window, Qt::Key_3, Qt::ControlModifier);
        auto *layer = find<ui::VehicleLayer>("vehicleLayer");
        QTRY_COMPARE_WITH_TIMEOUT(layer->count(), 3, 10000);

        // A VCI vehicle, added by its address, beside the server's.
        type("vciAddressField", QStringLiteral("tcp://127.0.0.1:%1").arg(m_app->vci().listeners().front()->port()));
        click("vciConnectButton");
        QTRY_COMPARE(layer->count(), 4);
        QCOMPARE(m_app->fleet().index(3).data(client::VehicleFleet::ProtocolRole).toString(), QStringLiteral("VCI"));
        QTRY_COMPARE_WITH_TIMEOUT(m_app->fleet().index(3).data(client::VehicleFleet::LinkStateRole).toString(), QStringLiteral("Connected"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!layer->vehiclePosition(3).isNull(), 10000);

        // Choose EMU-101 on the map; its instruments fill in.
        MapView *map = m_window->property("telemetryPage").value<QObject *>()->property("map").value<MapView *>();
        QTRY_VERIFY_WITH_TIMEOUT(!layer->vehiclePosition(0).isNull(), 10000);
        map->setCenter(m_app->fleet().vehicleAt(0)->position());
        map->setZoomLevel(17); // EMU-101 on its own under the cursor
        QTest::mouseClick(m_window, Qt::LeftButton, {}, map->mapToScene(layer->vehiclePosition(0)).toPoint());
        QTRY_COMPARE(layer->currentIndex(), 0);
        QTRY_VERIFY(text("value_altitudeAgl") != QStringLiteral("—"));
        QVERIFY(find("instrument_altitudeAgl")->opacity() > 0.9);

        // Arm asks first; then take off, and the altitude climbs on the instruments and the plot.
        auto confirmYes = [this] {
            QObject *dialog = find<QObject>("commandConfirmDialog");
            QTRY_VERIFY(dialog->property("opened").toBool());
            QMetaObject::invokeMethod(dialog, "accept");
        };
        // The pre-flight checklist passes once the vehicle's slower telemetry (GPS, battery) is in.
        QTRY_VERIFY_WITH_TIMEOUT(m_app->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, m_app->fleet().vehicleAt(0)).isEmpty(), 10000);
        click("armButton");
        QObject *dialog = find<QObject>("commandConfirmDialog");
        QTRY_VERIFY(dialog->property("opened").toBool());
        QVERIFY(dialog->property("text").toString().contains(QStringLiteral("EMU-101")));
        QTest::keyClick(m_window, Qt::Key_Escape); // "no": nothing is sent
        QTRY_VERIFY(!dialog->property("opened").toBool());
        QVERIFY(!m_app->fleet().vehicleAt(0)->armed());
        click("armButton");
        confirmYes();
        QTRY_VERIFY_WITH_TIMEOUT(m_app->fleet().vehicleAt(0)->armed(), 10000);
        QTRY_VERIFY(text("commandResult").contains(QStringLiteral("done")));
        QTRY_COMPARE(text("value_armed"), QStringLiteral("ARMED")); // at the vehicle's notify rate
        click("takeoffButton");
        confirmYes();
        QTRY_VERIFY_WITH_TIMEOUT(m_app->fleet().vehicleAt(0)->altitudeAgl() > 3, 20000);
        auto *plot = find<ui::TelemetryPlot>("telemetryPlot");
        QTRY_VERIFY(plot->sampleCount() > 5);
        QTest::qWait(200);
        m_window->grabWindow().save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("telemetry.png")));
    }
};

QTEST_MAIN(TestUiFlows)
#include "tst_uiflows.moc"
