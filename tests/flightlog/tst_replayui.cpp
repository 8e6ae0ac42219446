// The replay in the fly view, offscreen: a log opened on the telemetry page shows its vehicles
// marked as a replay; Play moves the clock, a click on the timeline scrubs, the next-event button
// jumps to an event, and each time the vehicle is drawn on the map where the log says it was. The
// server's history of a vehicle chosen in the timeline's dialog, fetched from the simulator, replays
// with the vehicle drawn where the server had it.
#include "Airspace.h"
#include "ClientGraph.h"
#include "RouteEndurance.h"
#include "ComparisonController.h"
#include "ConnectionController.h"
#include "HciClient.h"
#include "HciServer.h"
#include "HciSession.h"
#include "FleetRoutes.h"
#include "FlightRecorder.h"
#include "RecordingSettings.h"
#include "ServerHistoryRequest.h"
#include "SimWorld.h"
#include "VehicleFleet.h"
#include "FlightLog.h"
#include "MissionFiles.h"
#include "FlightLogTestSupport.h"
#include "QuickScene.h"
#include "ReplayController.h"

#include <QDir>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <map>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// The telemetry page's properties: the client graph, as Main.qml hands it over.
QVariantMap telemetryPageProperties(client::ClientGraph &graph)
{
    return {{QStringLiteral("graph"), QVariant::fromValue(&graph)}};
}

} // namespace

class TestReplayUi : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void openPlayScrubJump()
    {
        QTemporaryDir dir;
        const QString path = test::recordTwoFlights(dir.path());
        QSettings storage(QDir(dir.path()).filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        client::ClientGraph graph(&storage, {});
        flightlog::ReplayController &replay = graph.replay();
        flightlog::ComparisonController &comparison = graph.comparison();
        test::QuickScene scene(test::kTelemetryPageQml, QSize(1280, 800), telemetryPageProperties(graph));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        QVERIFY(scene.find<QQuickItem>(QStringLiteral("openLogButton")));
        auto *banner = scene.find<QQuickItem>(QStringLiteral("replayBanner"));
        QVERIFY(banner && !banner->isVisible());

        // Open: the replayed vehicles take the map, under a banner that says so.
        QVERIFY(replay.open(path));
        auto *loading = scene.find<QQuickItem>(QStringLiteral("historyLoadingLabel"));
        QVERIFY(loading && loading->isVisible()); // no event has run: the histories cannot be in yet
        QTRY_VERIFY(banner->isVisible());
        auto *layer = scene.find<QQuickItem>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        QTRY_COMPARE(layer->property("count").toInt(), 2);
        auto *list = scene.find<QQuickItem>(QStringLiteral("vehicleList"));
        QVERIFY(list);
        QObject *map = scene.root()->property("map").value<QObject *>();
        QVERIFY(map);
        const int a = replay.log()->vehicleIndex(QStringLiteral("EMU-101"));
        // Centre the map on the flight so the vehicle is in view.
        QMetaObject::invokeMethod(map, "fitBounds", Q_ARG(double, 56.9495), Q_ARG(double, 24.0995), Q_ARG(double, 56.9515), Q_ARG(double, 24.1025), Q_ARG(qreal, 40));

        auto expectOnMap = [&](qint64 time) {
            const auto state = replay.log()->stateAt(a, time);
            double lat = 0, lon = 0;
            for (const auto &u : state) {
                if (u.field == vehicle::TelemetryField::Latitude)
                    lat = u.value;
                if (u.field == vehicle::TelemetryField::Longitude)
                    lon = u.value;
            }
            QPointF expected;
            QMetaObject::invokeMethod(map, "fromCoordinate", Q_RETURN_ARG(QPointF, expected), Q_ARG(QGeoCoordinate, QGeoCoordinate(lat, lon)));
            QPointF drawn;
            QMetaObject::invokeMethod(layer, "vehiclePosition", Q_RETURN_ARG(QPointF, drawn), Q_ARG(int, a));
            return QLineF(expected, drawn).length();
        };
        QTRY_VERIFY2(expectOnMap(replay.position()) < 1.5, "the vehicle is not drawn where the log has it at the start");
        // The plots' histories fill in the background; the timeline says so until they are in.
        QTRY_VERIFY(replay.isHistoryLoaded());
        QTRY_VERIFY(!loading->isVisible());

        // Play: the clock moves; pause stops it.
        auto *play = scene.find<QQuickItem>(QStringLiteral("playButton"));
        QVERIFY(play && play->isVisible());
        const qint64 before = replay.position();
        scene.grab(); // lays the timeline out (polish) before finding where its buttons are
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(play).toPoint());
        QVERIFY2(replay.isPlaying(), qPrintable(QStringLiteral("play at %1,%2 in %3x%4; picked: %5").arg(test::sceneCentre(play).x()).arg(test::sceneCentre(play).y())
                                                  .arg(scene.view().width()).arg(scene.view().height())
                                                  .arg(scene.root()->childAt(test::sceneCentre(play).x(), test::sceneCentre(play).y()) ? scene.root()->childAt(test::sceneCentre(play).x(), test::sceneCentre(play).y())->metaObject()->className() : "none")));
        QTRY_VERIFY(replay.position() > before + 200);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(play).toPoint());
        QVERIFY(!replay.isPlaying());
        QTRY_VERIFY(expectOnMap(replay.position()) < 1.5);

        // Scrub: a click at three quarters of the timeline.
        auto *slider = scene.find<QQuickItem>(QStringLiteral("timelineSlider"));
        QVERIFY(slider && slider->isVisible());
        const double left = slider->property("leftPadding").toDouble();
        const double usable = slider->property("availableWidth").toDouble();
        const QPointF at = slider->mapToScene(QPointF(left + 0.75 * usable, slider->height() / 2));
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, at.toPoint());
        QTRY_VERIFY2(std::fabs(replay.progress() - 0.75) < 0.03, qPrintable(QStringLiteral("%1 after a click at %2,%3 in %4x%5").arg(replay.progress()).arg(at.x()).arg(at.y()).arg(scene.view().width()).arg(scene.view().height())));
        QTRY_VERIFY(expectOnMap(replay.position()) < 1.5);

        // Jump back to the first event, then on to the next one.
        replay.seek(replay.start());
        auto *next = scene.find<QQuickItem>(QStringLiteral("nextEventButton"));
        QVERIFY(next && next->isVisible());
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(next).toPoint());
        const int first = replay.events()->nextAfter(replay.start());
        QVERIFY(first >= 0);
        QTRY_COMPARE(replay.position(), replay.events()->eventAt(first)->time);
        QTRY_VERIFY(expectOnMap(replay.position()) < 1.5);
        auto *label = scene.find<QQuickItem>(QStringLiteral("positionLabel"));
        QVERIFY(label && label->property("text").toString().contains(QStringLiteral("UTC")));

        // Compare with the plan: a table of legs and the track coloured on the map.
        mission::Mission plan;
        plan.routes.push_back(test::routeThrough(test::kLegs, 20, QStringLiteral("Box")));
        const QString routeFile = dir.filePath(QStringLiteral("box.sortie"));
        QVERIFY(mission::formats::saveMission(plan, routeFile, {0, mission::ValidationOverride::AcceptErrors, {}}));
        auto *compareButton = scene.find<QQuickItem>(QStringLiteral("compareButton"));
        QVERIFY(compareButton && compareButton->isVisible());
        QVERIFY(!comparison.compare(routeFile, -1)); // two vehicles: which one?
        QVERIFY(!comparison.errorString().isEmpty());
        QVERIFY2(comparison.compare(QUrl::fromLocalFile(routeFile).toString(), a), qPrintable(comparison.errorString()));
        auto *deviation = scene.find<QQuickItem>(QStringLiteral("deviationLayer"));
        QVERIFY(deviation && deviation->isVisible());
        QTRY_VERIFY(deviation->property("count").toInt() > 100);
        auto *table = scene.find<QQuickItem>(QStringLiteral("comparisonTable"));
        QTRY_VERIFY(table && table->isVisible());
        QCOMPARE(table->property("count").toInt(), 3);
        auto *summary = scene.find<QQuickItem>(QStringLiteral("comparisonSummary"));
        QVERIFY2(summary->property("text").toString().contains(QStringLiteral("4 of 4 waypoints reached")), qPrintable(summary->property("text").toString()));
        // The track is drawn in the colour of "fine" on the map.
        const QImage shot = scene.grab();
        QPointF onTrack;
        QMetaObject::invokeMethod(map, "fromCoordinate", Q_RETURN_ARG(QPointF, onTrack),
                                  Q_ARG(QGeoCoordinate, QGeoCoordinate((test::kLegs[1].latitude + test::kLegs[2].latitude) / 2,
                                                                       (test::kLegs[1].longitude + test::kLegs[2].longitude) / 2)));
        const QPoint pixel = deviation->mapToScene(onTrack).toPoint();
        QVERIFY2(test::colourDistance(shot.pixel(pixel), qRgb(0x43, 0xa0, 0x47)) < 40, qPrintable(QColor(shot.pixel(pixel)).name()));

        // Back to live: the banner goes, the replayed vehicles with it.
        auto *close = scene.find<QQuickItem>(QStringLiteral("closeLogButton"));
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(close).toPoint());
        QTRY_VERIFY(!banner->isVisible());
        QVERIFY(!replay.isActive());
    }

    // The flight-log settings dialog: the folder and what it holds, the limits in force; a refused
    // change says why, an accepted one is saved and in force in the running recorder.
    void recordingSettingsDialog()
    {
        QTemporaryDir dir;
        QSettings storage(QDir(dir.path()).filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        flightlog::FlightRecorder recorder({QDir(dir.path()).filePath(QStringLiteral("logs/now.sortielog")), {}, 100});
        flightlog::RecordingSettings settings(&storage, &recorder);
        QVERIFY(recorder.start());
        test::QuickScene scene(R"(
            import QtQuick
            import Sortie.Ui
            Item {
                id: root
                required property RecordingSettings settings
                property alias dialog: dialog
                FlightLogSettingsDialog { id: dialog; settings: root.settings }
            }
        )", QSize(900, 600), {{QStringLiteral("settings"), QVariant::fromValue(&settings)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *dialog = scene.root()->property("dialog").value<QObject *>();
        QVERIFY(dialog);
        QMetaObject::invokeMethod(dialog, "open");
        QTRY_VERIFY(dialog->property("opened").toBool());
        auto *folder = scene.find<QQuickItem>(QStringLiteral("logFolderField"));
        auto *size = scene.find<QQuickItem>(QStringLiteral("logFolderSize"));
        auto *current = scene.find<QQuickItem>(QStringLiteral("currentLogLabel"));
        auto *fileBox = scene.find<QQuickItem>(QStringLiteral("maxFileBox"));
        auto *folderBox = scene.find<QQuickItem>(QStringLiteral("maxFolderBox"));
        auto *apply = scene.find<QQuickItem>(QStringLiteral("applyLogSettingsButton"));
        auto *error = scene.find<QQuickItem>(QStringLiteral("logSettingsError"));
        auto *inForce = scene.find<QQuickItem>(QStringLiteral("logSettingsInForce"));
        QVERIFY(folder && size && current && fileBox && folderBox && apply && error && inForce);
        QCOMPARE(folder->property("text").toString(), QDir::toNativeSeparators(QDir(dir.path()).filePath(QStringLiteral("logs"))));
        QVERIFY2(size->property("text").toString().contains(QStringLiteral("in 1 log")), qPrintable(size->property("text").toString()));
        QCOMPARE(current->property("text").toString(), QStringLiteral("now.sortielog"));
        QCOMPARE(fileBox->property("value").toInt(), 256);
        QCOMPARE(folderBox->property("value").toInt(), 4096);
        QCOMPARE(inForce->property("text").toString(), QStringLiteral("In force: a log up to 256 MB; the folder up to 4096 MB."));

        // A folder smaller than a log: refused with the reason, nothing saved.
        fileBox->setProperty("value", 100);
        folderBox->setProperty("value", 50);
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(apply).toPoint());
        QTRY_VERIFY(error->isVisible());
        QVERIFY2(error->property("text").toString().contains(QStringLiteral("at least one whole log")), qPrintable(error->property("text").toString()));
        QVERIFY(!storage.contains(QStringLiteral("flightlog/maxFileMB")));
        QCOMPARE(recorder.limits().maxFileBytes, qint64(256) << 20);
        // A good change: in force at once, saved, the error gone.
        folderBox->setProperty("value", 0);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(apply).toPoint());
        QTRY_VERIFY(!error->isVisible());
        QCOMPARE(recorder.limits().maxFileBytes, qint64(100) << 20);
        QCOMPARE(recorder.limits().maxFolderBytes, qint64(0));
        QCOMPARE(storage.value(QStringLiteral("flightlog/maxFileMB")).toInt(), 100);
        QCOMPARE(storage.value(QStringLiteral("flightlog/maxFolderMB")).toInt(), 0);
        QCOMPARE(inForce->property("text").toString(), QStringLiteral("In force: a log up to 100 MB; the folder without limit."));
        recorder.stop();
    }

    void serverHistoryFromTheDialog()
    {
        sim::SimWorld::Config config;
        config.telemetryRateHz = 20;
        config.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true}};
        sim::SimWorld world(config);
        sim::HciServer server(world);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        QTemporaryDir dir;
        QSettings storage(QDir(dir.path()).filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        client::ClientGraph graph(&storage, {});
        client::ConnectionController &connection = graph.connection();
        client::VehicleFleet &fleet = *graph.fleet();
        flightlog::ReplayController &replay = graph.replay();
        flightlog::ServerHistoryRequest &history = graph.serverHistory();
        QVERIFY(connection.connectToServer(QStringLiteral("127.0.0.1:%1").arg(server.port()), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        vehicle::Vehicle *live = nullptr;
        for (int row = 0; row < fleet.count(); ++row)
            if (fleet.vehicleAt(row)->name() == QLatin1String("EMU-102"))
                live = fleet.vehicleAt(row);
        QVERIFY(live);
        // Fly a little: take off and climb, remembering what the live link said when (each field has
        // its own times).
        std::map<vehicle::TelemetryField, std::vector<vehicle::TelemetrySample>> seen;
        connect(live->link(), &vehicle::VehicleLink::telemetryReceived, this, [&seen](const vehicle::TelemetryBatch &batch) {
            for (const auto &u : batch)
                seen[u.field].push_back({u.time, u.value});
        });
        // The live value of a field at a time: its last sample at or before it.
        auto liveAt = [&seen](vehicle::TelemetryField field, qint64 time) {
            double value = qQNaN();
            for (const auto &sample : seen[field])
                if (sample.time <= time)
                    value = sample.value;
            return value;
        };
        QTRY_VERIFY_WITH_TIMEOUT(live->position().isValid(), 10000);
        live->arm();
        QTRY_VERIFY_WITH_TIMEOUT(live->armed(), 10000);
        live->takeoff(10);
        QTRY_VERIFY_WITH_TIMEOUT(live->altitudeAgl() > 4, 15000);

        test::QuickScene scene(test::kTelemetryPageQml, QSize(1280, 800), telemetryPageProperties(graph));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        scene.grab();
        auto *button = scene.find<QQuickItem>(QStringLiteral("serverHistoryButton"));
        QVERIFY(button && button->isVisible());
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(button).toPoint());
        auto *dialog = scene.find<QObject>(QStringLiteral("serverHistoryDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->property("opened").toBool());
        // The server's vehicles, the last hour; the vehicle chosen in the list.
        QCOMPARE(history.vehicleNames().size(), 3);
        QVERIFY(history.canFetch());
        auto *vehicles = scene.find<QQuickItem>(QStringLiteral("historyVehicleBox"));
        QVERIFY(vehicles);
        QCOMPARE(vehicles->property("count").toInt(), 3);
        const int row = int(history.vehicleNames().indexOf(QStringLiteral("EMU-102")));
        QMetaObject::invokeMethod(vehicles, "activated", Q_ARG(int, row));
        QCOMPARE(history.vehicleIndex(), row);
        // A start after the end is refused in the dialog before anything is sent.
        auto *from = scene.find<QQuickItem>(QStringLiteral("historyFromField"));
        auto *to = scene.find<QQuickItem>(QStringLiteral("historyToField"));
        QVERIFY(from && to);
        QCOMPARE(from->property("text").toString(), history.fromText());
        const QString toText = history.toText();
        history.setFromText(toText);
        auto *problem = scene.find<QQuickItem>(QStringLiteral("historyProblem"));
        auto *fetch = scene.find<QQuickItem>(QStringLiteral("historyFetchButton"));
        QVERIFY(problem && fetch);
        QTRY_VERIFY(problem->isVisible());
        QCOMPARE(problem->property("text").toString(), QStringLiteral("The start must be before the end."));
        QVERIFY(!fetch->isEnabled());
        history.chooseLastHour();
        QTRY_VERIFY(fetch->isEnabled());
        QVERIFY(!problem->isVisible());

        // Fetch: progress while pages arrive, then the replay opens and the dialog closes.
        QSignalSpy progress(&history, &flightlog::ServerHistoryRequest::progressChanged);
        QSignalSpy opened(&history, &flightlog::ServerHistoryRequest::opened);
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(fetch).toPoint());
        QVERIFY(history.isBusy());
        QVERIFY2(opened.wait(15000), qPrintable(history.errorString()));
        QVERIFY(progress.count() >= 1);
        QTRY_VERIFY(!dialog->property("visible").toBool());
        QVERIFY(replay.isActive());
        QCOMPARE(replay.fleet()->count(), 1);
        vehicle::Vehicle *replayed = replay.fleet()->vehicleAt(0);
        QCOMPARE(replayed->name(), QStringLiteral("EMU-102"));
        auto *banner = scene.find<QQuickItem>(QStringLiteral("replayBanner"));
        QTRY_VERIFY(banner && banner->isVisible());

        // Where the server had it at the end of the range, up in the air, drawn there.
        const qint64 at = replay.end();
        const QGeoCoordinate where(liveAt(vehicle::TelemetryField::Latitude, at), liveAt(vehicle::TelemetryField::Longitude, at));
        const double agl = liveAt(vehicle::TelemetryField::AltitudeAgl, at);
        QVERIFY2(agl > 4, qPrintable(QString::number(agl))); // the range ends after the climb
        replay.seek(at);
        QVERIFY2(std::fabs(replayed->position().latitude() - where.latitude()) < 1e-6, qPrintable(QString::number(replayed->position().latitude() - where.latitude())));
        QVERIFY(std::fabs(replayed->position().longitude() - where.longitude()) < 1e-6);
        QVERIFY2(std::fabs(replayed->altitudeAgl() - agl) < 0.01, qPrintable(QStringLiteral("%1 %2").arg(replayed->altitudeAgl()).arg(agl)));
        QObject *map = scene.root()->property("map").value<QObject *>();
        auto *layer = scene.find<QQuickItem>(QStringLiteral("vehicleLayer"));
        QVERIFY(map && layer);
        QTRY_COMPARE(layer->property("count").toInt(), 1);
        QMetaObject::invokeMethod(map, "fitBounds", Q_ARG(double, where.latitude() - 0.001), Q_ARG(double, where.longitude() - 0.001),
                                  Q_ARG(double, where.latitude() + 0.001), Q_ARG(double, where.longitude() + 0.001), Q_ARG(qreal, 40));
        auto offMap = [&] {
            QPointF expected, drawn;
            QMetaObject::invokeMethod(map, "fromCoordinate", Q_RETURN_ARG(QPointF, expected), Q_ARG(QGeoCoordinate, where));
            QMetaObject::invokeMethod(layer, "vehiclePosition", Q_RETURN_ARG(QPointF, drawn), Q_ARG(int, 0));
            return QLineF(expected, drawn).length();
        };
        QTRY_VERIFY2(offMap() < 1.5, "the replayed vehicle is not drawn where the server had it");
    }
};

QTEST_MAIN(TestReplayUi)
#include "tst_replayui.moc"
