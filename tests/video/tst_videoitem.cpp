// The video view item offscreen (software scene graph): it draws the receiver's frames (the
// camera's stamp reads back from the drawn pixels), says "No video since …" over the dimmed last
// picture when the stream stops; and the client's own fly view shows the chosen vehicle's video
// from the URL the simulated vehicle publishes (video_stream_uri over HCI), or the operator's URL
// for that vehicle, remembered in the settings.
#include "ClientWindow.h"
#include "FrameStamp.h"
#include "QuickScene.h"
#include "SimCamera.h"
#include "SimCameraFleet.h"
#include "SimVehicle.h"
#include "SimWorld.h"
#include "VehicleFleet.h"
#include "VehicleVideo.h"
#include "VideoItem.h"
#include "VideoReceiver.h"
#include "VideoRuntime.h"
#include "VideoTestSupport.h"

#include <QDir>
#include <QFileInfo>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using State = video::VideoReceiver::State;

namespace {
constexpr int kWait = 20000;

QString screenshotDir()
{
    const QString dir = qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QDir::tempPath() + QStringLiteral("/sortie-screenshots"));
    QDir().mkpath(dir);
    return dir;
}
} // namespace

class TestVideoItem : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void drawsTheFramesAndSaysWhenTheyStop()
    {
        video::VideoRuntime runtime;
        const quint16 port = test::freeUdpPort();
        sim::SimCamera camera(QStringLiteral("vehicle/1"), sim::SimCameraFormat{640, 360, 30, 1500}, nullptr);
        QString error;
        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        video::VideoReceiver::Options options;
        options.stallMs = 800;
        video::VideoReceiver receiver(runtime, options);

        test::QuickScene scene("import Sortie.Ui\nVideoItem { objectName: \"video\"; width: 640; height: 360; compact: true }", QSize(640, 360));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *item = qobject_cast<ui::VideoItem *>(scene.root());  // the scene is the item
        QVERIFY(item);
        const QImage before = scene.grab();
        QCOMPARE(before.pixel(5, 5) & 0xffffff, 0u);  // black, with the words "No video for this vehicle" in the middle
        item->setReceiver(&receiver);
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:%1").arg(port));
        QTRY_VERIFY_WITH_TIMEOUT(item->framesShown() >= 10 && receiver.state() == State::Playing, kWait);

        // Drawn one to one: the camera's stamp reads back from the scene's own pixels.
        // (Joined in the middle of a key frame, the picture is partial until the next one, a second
        // later, and has no stamp: the next frames are tried, up to a second and a half of them.)
        QImage drawn;
        std::optional<quint64> stamp;
        for (int attempt = 0; attempt < 45 && !stamp; ++attempt) {
            const quint64 shown = item->framesShown();
            QTRY_VERIFY_WITH_TIMEOUT(item->framesShown() > shown, kWait);
            drawn = scene.grab().convertToFormat(QImage::Format_RGB32);
            stamp = video::FrameStamp::read(drawn);
        }
        drawn.save(screenshotDir() + QStringLiteral("/video-item.png"));
        QVERIFY2(stamp, "the drawn picture carries no stamp");
        QVERIFY(qint64(*stamp) <= video::FrameStamp::nowMicros());
        QVERIFY(test::distinctColours(drawn) > 16);  // the fields, not a blank rectangle
        const QRgb field = drawn.pixel(100, 200);
        QVERIFY2(qGreen(field) > qBlue(field), "the ground is green and brown");

        camera.stopUdp();
        QTRY_COMPARE_WITH_TIMEOUT(receiver.state(), State::Stalled, kWait);
        QVERIFY(receiver.statusText().startsWith(QLatin1String("No video since")));
        const QImage stalled = scene.grab().convertToFormat(QImage::Format_RGB32);
        stalled.save(screenshotDir() + QStringLiteral("/video-item-stalled.png"));
        QVERIFY2(qGray(stalled.pixel(100, 200)) < qGray(field), "the last picture is dimmed");
        // The words, light on a dark box in the middle.
        int light = 0;
        for (int x = 200; x < 440; ++x)
            light += qGray(stalled.pixel(x, 180)) > 200 || qGray(stalled.pixel(x, 176)) > 200 || qGray(stalled.pixel(x, 184)) > 200;
        QVERIFY2(light > 10, "no words over the stalled picture");
    }

    void theFlyViewShowsTheChosenVehiclesVideo()
    {
        test::ClientWindow app;
        QVERIFY2(app.isReady(), qPrintable(app.error()));
        // The simulated vehicles' cameras, as sortie --demo serves them: RTSP, in their telemetry.
        video::VideoRuntime runtime;
        sim::SimCameraOptions options;
        options.rtspPort = 0;
        options.format = sim::SimCameraFormat{640, 360, 30, 1500};
        sim::SimCameraFleet cameras(runtime, options, QHostAddress(QHostAddress::LocalHost));
        QString error;
        QVERIFY2(app.world().start(&error), qPrintable(error));
        for (size_t i = 0; i < app.world().vehicles().size(); ++i)
            cameras.addCamera(int(i) + 1, sim::poseOf(app.world().vehicles()[i]->model()));
        QVERIFY2(cameras.start(&error), qPrintable(error));
        for (size_t i = 0; i < app.world().vehicles().size(); ++i)
            app.world().vehicles()[i]->setVideoStreamUri(cameras.streamUri(int(i) + 1));

        QVERIFY(app.logIn());
        app.showPage(2);
        QTRY_VERIFY_WITH_TIMEOUT(app.fleet().rowCount() >= 3, kWait);
        QObject *layer = app.find<QObject>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        layer->setProperty("currentIndex", 0);
        vehicle::Vehicle *first = app.fleet().vehicleAt(0);
        QVERIFY(first);
        QTRY_VERIFY_WITH_TIMEOUT(!first->videoStreamUri().isEmpty(), kWait);  // from the vehicle's telemetry
        QVERIFY(first->videoStreamUri().startsWith(QLatin1String("rtsp://127.0.0.1:")));

        auto *item = app.find<ui::VideoItem>(QStringLiteral("videoItem"));
        QVERIFY(item);
        QTRY_VERIFY_WITH_TIMEOUT(item->receiver() != nullptr, kWait);
        QCOMPARE(item->receiver()->url(), first->videoStreamUri());
        QTRY_VERIFY_WITH_TIMEOUT(item->framesShown() >= 5, kWait);
        QTRY_VERIFY_WITH_TIMEOUT(video::FrameStamp::read(item->currentFrame().image).has_value(), kWait);  // past a partial key frame
        QVERIFY(item->isVisible() && item->width() > 100);
        const QImage window = app.window()->grabWindow();
        window.save(screenshotDir() + QStringLiteral("/fly-video.png"));
        const QRectF area = item->mapRectToScene(QRectF(0, 0, item->width(), item->height()));
        QVERIFY(test::distinctColours(window.copy(area.toAlignedRect()).convertToFormat(QImage::Format_RGB32)) > 16);

        // Swapped: the video in the map's place, the map in the corner.
        QObject *swap = app.find<QObject>(QStringLiteral("videoSwapButton"));
        QVERIFY(swap);
        QMetaObject::invokeMethod(swap, "clicked");
        QTRY_VERIFY_WITH_TIMEOUT(item->width() > 500, 5000);
        QTest::qWait(200);
        app.window()->grabWindow().save(screenshotDir() + QStringLiteral("/fly-video-swapped.png"));
        QMetaObject::invokeMethod(swap, "clicked");

        // The operator's URL for this vehicle overrides the vehicle's own, and is remembered.
        video::VehicleVideo *videos = app.graph().video();
        QVERIFY(videos);
        // Recorded beside the flight logs, as received (Record in the panel).
        QVERIFY(videos->canRecord());
        QObject *record = app.find<QObject>(QStringLiteral("videoRecordButton"));
        QVERIFY(record && record->property("visible").toBool());
        videos->setRecording(first, true);
        QVERIFY(item->receiver()->isRecording());
        QVERIFY(record->property("checked").toBool());
        const QString recording = item->receiver()->recordingFile();
        QVERIFY2(recording.contains(QLatin1String("/flightlogs/video/")), qPrintable(recording));
        const quint64 before = item->framesShown();
        QTRY_VERIFY_WITH_TIMEOUT(item->framesShown() > before + 15, kWait);
        videos->setRecording(first, false);
        QVERIFY(!record->property("checked").toBool());
        QVERIFY(QFileInfo(recording).size() > 1000);
        const QString manual = cameras.rtspUrl(2);
        videos->setManualUrl(first, manual);
        QCOMPARE(item->receiver()->url(), manual);
        QCOMPARE(app.storage().value(QStringLiteral("video/url/%1").arg(first->id())).toString(), manual);
        const quint64 shown = item->framesShown();
        QTRY_VERIFY_WITH_TIMEOUT(item->framesShown() > shown + 3, kWait);
        videos->setManualUrl(first, QString());  // back to the vehicle's own
        QCOMPARE(item->receiver()->url(), first->videoStreamUri());
        QVERIFY(!app.storage().contains(QStringLiteral("video/url/%1").arg(first->id())));
    }
};

QTEST_MAIN(TestVideoItem)
#include "tst_videoitem.moc"
