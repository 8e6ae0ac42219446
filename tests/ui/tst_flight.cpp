// The whole flight from the client's windows, offscreen against the embedded simulator, once for an
// HCI vehicle (through the simulated UgCS server) and once for a VCI vehicle (direct): plan (the
// demo route), upload with progress, arm, take off, auto; the live view frames the vehicles, draws
// the route, rings the active waypoint as it advances ("waypoint n of m"), and the instruments move
// (attitude, heading compass with the bearing to home, flight time, distance to home); pause,
// resume, return home, land. The VCI flight first has its upload refused for a waypoint made
// invalid in the table, with the reason shown, then fixed and sent. Every command goes through the
// buttons and the confirmation dialog, as an operator gives it; both flights share the steps below.
#include "AttitudeIndicator.h"
#include "ClientWindow.h"
#include "FlightPlanLayer.h"
#include "FlightStatus.h"
#include "HeadingCompass.h"
#include "MapView.h"
#include "QuickScene.h"
#include "RouteModel.h"
#include "SimVciVehicle.h"
#include "VehicleLayer.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

// A step of a flight: stops the test where the step failed.
#define STEP(call)                                                                                                     \
    do {                                                                                                               \
        call;                                                                                                          \
        if (QTest::currentTestFailed())                                                                                \
            return;                                                                                                    \
    } while (false)

class TestFlight : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    QPoint centreOf(QQuickItem *item) const
    {
        return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
    }
    void click(const char *name)
    {
        auto *item = m_client->find(QString::fromLatin1(name));
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled(), name);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(item));
    }
    void confirm(const QString &mentioning)
    {
        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QVERIFY2(dialog->property("text").toString().contains(mentioning), qPrintable(dialog->property("text").toString()));
        QMetaObject::invokeMethod(dialog, "accept");
        QTRY_VERIFY(!dialog->property("opened").toBool());
    }
    QString text(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("text").toString(); }

    void start(test::ClientWindow::Options options)
    {
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->logIn());
        QTRY_COMPARE(m_client->window()->property("currentPage").toInt(), 1); // on to the mission
        QVERIFY(m_client->openDemoRoute());
    }

    int rowOf(const QString &protocol, int nth = 0) const
    {
        for (int r = 0; r < m_client->fleet().count(); ++r)
            if (m_client->fleet().vehicleAt(r)->protocol() == protocol && nth-- == 0)
                return r;
        return -1;
    }

    // Types into the waypoint table's cell, as an operator does: click, select all, type, Return.
    void typeInTable(int row, const char *role, const QString &value)
    {
        QQuickItem *cell = m_client->waypointCell(row, QString::fromLatin1(role));
        QVERIFY2(cell, role);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(cell));
        QTRY_VERIFY(cell->hasActiveFocus());
        QTest::keyClick(m_client->window(), Qt::Key_A, Qt::ControlModifier);
        for (QChar c : value)
            QTest::keyClick(m_client->window(), c.toLatin1());
        QTest::keyClick(m_client->window(), Qt::Key_Return);
    }

    // Chooses the fleet's row in the upload chooser and presses Upload; `activities` gets each
    // stage shown above the progress bar, `values` what the bar shows while it has a scale.
    void pressUpload(int row, QStringList *activities, QList<double> *values)
    {
        QObject *vehicles = m_client->find<QObject>(QStringLiteral("vehiclePicker"));
        QTRY_COMPARE(vehicles->property("count").toInt(), m_client->fleet().count());
        vehicles->setProperty("currentIndex", row); // the chooser lists the fleet, in its order
        QObject *bar = m_client->find<QObject>(QStringLiteral("progressBar"));
        client::MissionUploader *uploader = m_client->missions().preparation()->uploader();
        connect(uploader, &client::MissionUploader::progressChanged, bar, [values, bar] {
            if (bar->property("to").toDouble() > 1)
                values->append(bar->property("value").toDouble());
        });
        connect(uploader, &client::MissionUploader::stateChanged, bar, [activities, uploader] {
            if (uploader->isBusy() && !uploader->isAsking() && (activities->isEmpty() || activities->back() != uploader->activity()))
                activities->append(uploader->activity());
        });
        click("uploadButton");
    }

    // The fly view, framed on every vehicle; the row chosen in the list is centred and its
    // instruments fill in. Returns its FlightStatus through `status`.
    void chooseInFlyView(int row, ui::FlightStatus **status)
    {
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        auto *map = m_client->page("telemetryPage")->property("map").value<ui::MapView *>();
        const int count = m_client->fleet().count();
        QTRY_COMPARE_WITH_TIMEOUT(layer->positionedCount(), count, 10000);
        QTRY_VERIFY(map->zoomLevel() > 12); // not the world at zoom 2
        for (int r = 0; r < count; ++r)
            QVERIFY(QRectF(0, 0, map->width(), map->height()).contains(layer->vehiclePosition(r)));
        auto *list = m_client->find(QStringLiteral("vehicleList"));
        QQuickItem *delegate = nullptr;
        QMetaObject::invokeMethod(list, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, delegate), Q_ARG(int, row));
        QVERIFY(delegate);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(delegate));
        QTRY_COMPARE(layer->currentIndex(), row);
        const QPointF centre(map->width() / 2, map->height() / 2);
        QTRY_VERIFY((layer->vehiclePosition(row) - centre).manhattanLength() < 3);
        QTRY_VERIFY(text("value_batteryVoltage").endsWith(QStringLiteral(" V")));
        *status = m_client->find<QObject>(QStringLiteral("instrumentPanel"))->property("status").value<ui::FlightStatus *>();
        QVERIFY(*status);
        QCOMPARE(text("value_armedTime"), QStringLiteral("—")); // not armed: no flight time, not 0:00
        // The uploaded route is drawn under it, nothing flown yet.
        auto *plans = m_client->find<ui::FlightPlanLayer>(QStringLiteral("flightPlanLayer"));
        QTRY_VERIFY(plans->waypointCount(row) >= 4);
        QCOMPARE(text("value_mission"), QStringLiteral("%1 waypoints on board").arg(plans->waypointCount(row)));
    }

    void armAndTakeOff(vehicle::Vehicle *v, ui::FlightStatus *status)
    {
        // The pre-flight checklist passes once the vehicle's slower telemetry (GPS, battery) is in.
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, v).isEmpty(), 10000);
        click("armButton");
        confirm(v->name());
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
        click("takeoffButton");
        confirm(v->name());
        QTRY_VERIFY_WITH_TIMEOUT(v->altitudeAgl() > 5, 30000);
        QTRY_VERIFY(std::isfinite(status->flightSeconds()));
        QTRY_VERIFY(text("value_armedTime") != QStringLiteral("—"));
    }

    // Auto: it flies the route; the compass turns, home falls behind, the attitude moves.
    void flyTheRoute(vehicle::Vehicle *v, ui::FlightStatus *status)
    {
        auto *compass = m_client->find<ui::HeadingCompass>(QStringLiteral("headingCompass"));
        auto *attitude = m_client->find<ui::AttitudeIndicator>(QStringLiteral("attitudeIndicator"));
        QVERIFY(compass && attitude);
        click("autoButton");
        confirm(QStringLiteral("Start the mission on %1").arg(v->name()));
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("auto"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(status->distanceToHome() > 15, 30000);
        QVERIFY(std::isfinite(compass->heading()));
        QVERIFY(std::isfinite(compass->bearingToHome()));
        QVERIFY(attitude->hasAttitude());
        QVERIFY(text("value_home") != QStringLiteral("—"));
    }

    // The active waypoint advances on the map and in the instruments, with less of the route left.
    void activeWaypointAdvances(int row, ui::FlightStatus *status)
    {
        auto *plans = m_client->find<ui::FlightPlanLayer>(QStringLiteral("flightPlanLayer"));
        const int count = plans->waypointCount(row);
        QTRY_VERIFY_WITH_TIMEOUT(status->missionFlying(), 20000);
        const int first = status->activeWaypoint();
        QCOMPARE(status->waypointCount(), count);
        QCOMPARE(plans->activeWaypoint(row), first); // the map rings the waypoint it flies to
        QTRY_COMPARE(text("value_mission"), QStringLiteral("waypoint %1 of %2").arg(first + 1).arg(count));
        QVERIFY(std::isfinite(status->distanceLeft()) && std::isfinite(status->timeLeft()));
        const double left = status->distanceLeft();
        QTRY_VERIFY_WITH_TIMEOUT(status->activeWaypoint() > first, 60000);
        const int next = status->activeWaypoint();
        QCOMPARE(plans->activeWaypoint(row), next);
        QTRY_COMPARE(text("value_mission"), QStringLiteral("waypoint %1 of %2").arg(next + 1).arg(count));
        QVERIFY2(status->distanceLeft() < left, qPrintable(QStringLiteral("%1 m left, was %2 m").arg(status->distanceLeft()).arg(left)));
    }

    // Follow keeps it in the middle; pause and resume; home, then land where it is: the commands
    // that make it safer go at once (CommandPolicy), no dialog.
    void followPauseResumeHomeLand(int row, vehicle::Vehicle *v)
    {
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        auto *map = m_client->page("telemetryPage")->property("map").value<ui::MapView *>();
        click("followButton");
        QVERIFY(layer->follow());
        const QRectF middle(map->width() / 4, map->height() / 4, map->width() / 2, map->height() / 2);
        QTRY_VERIFY(middle.contains(layer->vehiclePosition(row)));

        click("pauseButton");
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("hold"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(v->groundSpeed() < 0.5, 20000);
        click("resumeButton"); // resuming starts the mission again: asked like Auto
        confirm(QStringLiteral("Start the mission on %1").arg(v->name()));
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("auto"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(v->groundSpeed() > 1, 20000);

        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        click("homeButton");
        QVERIFY(!dialog->property("opened").toBool());
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("return_home"), 10000);
        click("landButton");
        QVERIFY(!dialog->property("opened").toBool());
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("land"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(v->verticalSpeed() < -0.2, 20000);
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }
    void cleanup() { m_client.reset(); }

    void flyTheDemoRouteOnAnHciVehicle()
    {
        STEP(start({}));
        const int row = rowOf(QStringLiteral("HCI"));
        QVERIFY(row >= 0);
        vehicle::Vehicle *emu = m_client->fleet().vehicleAt(row);
        QCOMPARE(emu->name(), QStringLiteral("EMU-101"));

        // Upload, the progress bar moving with the server's steps.
        QStringList activities;
        QList<double> values;
        QSignalSpy uploaded(m_client->missions().preparation(), &client::RoutePreparation::uploaded);
        STEP(pressUpload(row, &activities, &values));
        QVERIFY(uploaded.wait(20000));
        QVERIFY2(values.size() >= 3 && values.last() > values.first(), qPrintable(QString::number(values.size())));

        ui::FlightStatus *status = nullptr;
        STEP(chooseInFlyView(row, &status));
        STEP(armAndTakeOff(emu, status));
        STEP(flyTheRoute(emu, status));
        QTest::qWait(150); // let the trail and the instruments draw once more for the picture
        m_client->window()->grabWindow().save(
            QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("fly.png")));
        // The server's RoutePass tells where it is in the route.
        STEP(activeWaypointAdvances(row, status));
        STEP(followPauseResumeHomeLand(row, emu));
    }

    // Two vehicles ticked in the fly view's list: the bar says it commands them, Arm asks once
    // naming both, and both arm; the third, unticked, does not.
    void commandTwoTickedVehiclesAtOnce()
    {
        STEP(start({}));
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *list = m_client->find(QStringLiteral("vehicleList"));
        QTRY_COMPARE_WITH_TIMEOUT(list->property("count").toInt(), 3, 10000);
        const auto tick = [&](int row) {
            QQuickItem *delegate = nullptr;
            QMetaObject::invokeMethod(list, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, delegate), Q_ARG(int, row));
            QVERIFY(delegate);
            QQuickItem *box = nullptr;
            for (QQuickItem *child : delegate->childItems())
                if (child->objectName() == QStringLiteral("vehicleTick"))
                    box = child;
            QVERIFY(box && box->isVisible());
            // The list lays out its rows on the next frame (the page has just been shown, the
            // vehicles have just arrived): click where the box is drawn, not where it was.
            QVERIFY(test::waitForFrame(m_client->window()));
            const QPoint at = centreOf(box);
            QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, at);
            QTRY_VERIFY2(box->property("checked").toBool(),
                         qPrintable(QStringLiteral("row %1: clicked at %2,%3; the box is now at %4,%5")
                                        .arg(row).arg(at.x()).arg(at.y()).arg(centreOf(box).x()).arg(centreOf(box).y())));
        };
        STEP(tick(0));
        STEP(tick(2));
        vehicle::Vehicle *first = m_client->fleet().vehicleAt(0);
        vehicle::Vehicle *third = m_client->fleet().vehicleAt(2);
        QTRY_VERIFY(m_client->find(QStringLiteral("groupHeader"))->isVisible());
        QCOMPARE(text("groupTargets"), QStringLiteral("To 2 ticked vehicles: %1, %2").arg(first->name(), third->name()));
        for (int r = 0; r < 3; ++r)
            QTRY_COMPARE_WITH_TIMEOUT(m_client->fleet().vehicleAt(r)->linkState(), vehicle::VehicleLink::State::Connected, 10000);
        // The pre-flight checklist passes once the vehicle's slower telemetry (GPS, battery) is in.
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, first).isEmpty(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, third).isEmpty(), 10000);
        click("armButton");
        confirm(QStringLiteral("Arm 2 vehicles: %1, %2?").arg(first->name(), third->name()));
        QTRY_VERIFY_WITH_TIMEOUT(first->armed() && third->armed(), 10000);
        QTRY_VERIFY2(text("commandResult").contains(QStringLiteral("2 of 2")), qPrintable(text("commandResult")));
        QVERIFY(!m_client->fleet().vehicleAt(1)->armed());
        m_client->window()->grabWindow().save(
            QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("fly-group.png")));
        click("groupClearButton");
        QTRY_VERIFY(!m_client->find(QStringLiteral("groupHeader"))->isVisible());
    }

    void flyTheDemoRouteOnAVciVehicle()
    {
        test::ClientWindow::Options options;
        options.vciHome = QGeoCoordinate(56.9758, 24.0745); // beside the demo route's first waypoint
        options.vciTimeScale = 4;                            // its legs in seconds rather than a minute
        STEP(start(options));
        QVERIFY(m_client->addVciVehicles());
        const int row = rowOf(QStringLiteral("VCI"));
        QVERIFY(row >= 0);
        vehicle::Vehicle *vci = m_client->fleet().vehicleAt(row);
        const sim::SimVciVehicle &simulated = *m_client->vci().vehicles().front();
        auto *model = m_client->missions().document()->model();

        // Waypoint 2 typed 500 m high, above the route's 120 m: the upload is refused, saying why.
        const double altitude = model->index(1).data(mission::RouteModel::AltitudeRole).toDouble();
        STEP(typeInTable(1, "altitude", QStringLiteral("500")));
        QTRY_COMPARE(model->index(1).data(mission::RouteModel::AltitudeRole).toDouble(), 500.0);
        QStringList activities;
        QList<double> values;
        STEP(pressUpload(row, &activities, &values));
        QTRY_VERIFY2(text("preparationMessage").startsWith(QStringLiteral("Not uploaded: ")), qPrintable(text("preparationMessage")));
        QVERIFY2(text("preparationMessage").contains(QStringLiteral("the route's limit is 120 m above it")), qPrintable(text("preparationMessage")));
        QVERIFY(vci->mission().empty());
        QVERIFY(simulated.model().mission().empty()); // nothing reached the vehicle

        // Fixed in the table; the edits are unsaved, so the upload asks first: save and upload.
        STEP(typeInTable(1, "altitude", QString::number(altitude)));
        QTRY_COMPARE(model->index(1).data(mission::RouteModel::AltitudeRole).toDouble(), altitude);
        activities.clear();
        QSignalSpy uploaded(m_client->missions().preparation(), &client::RoutePreparation::uploaded);
        STEP(pressUpload(row, &activities, &values));
        QObject *question = m_client->find<QObject>(QStringLiteral("uploadQuestion"));
        QTRY_VERIFY(question->property("opened").toBool());
        QVERIFY2(text("uploadQuestionText").contains(vci->name()), qPrintable(text("uploadQuestionText")));
        click("saveAndUploadButton");
        QVERIFY(uploaded.wait(20000));
        // The stages shown while it went: prepared for the vehicle, sent, read back and compared.
        for (const QString &stage : {QStringLiteral("Uploading to %1"), QStringLiteral("Reading the mission back from %1")})
            QVERIFY2(activities.contains(stage.arg(vci->name())), qPrintable(activities.join(QStringLiteral(" | "))));
        QTRY_VERIFY2(text("preparationMessage").startsWith(QStringLiteral("Uploaded to %1").arg(vci->name())), qPrintable(text("preparationMessage")));
        QCOMPARE(simulated.model().mission().size(), vci->mission().size());

        ui::FlightStatus *status = nullptr;
        STEP(chooseInFlyView(row, &status));
        STEP(armAndTakeOff(vci, status));
        STEP(flyTheRoute(vci, status));
        STEP(activeWaypointAdvances(row, status));
        STEP(followPauseResumeHomeLand(row, vci));
    }
};

QTEST_MAIN(TestFlight)
#include "tst_flight.moc"
