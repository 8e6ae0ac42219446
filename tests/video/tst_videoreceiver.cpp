// The video receiver (core/video) against real peers on 127.0.0.1: sortie-sim's camera sending
// RTP/H.264 over UDP and serving RTSP, and a GStreamer MPEG-TS sender of the test's own. Frames
// arrive with the capture time the camera stamped into them; the stream stopping is "stalled" with
// the time of the last frame, and its coming back plays again without anyone asking; a flood of
// garbage and a truncated stream leave the receiver alive and saying so; a bad URL its error.
#include "FrameStamp.h"
#include "SimCamera.h"
#include "SimRtspServer.h"
#include "VideoReceiver.h"
#include "VideoRuntime.h"
#include "VideoTestSupport.h"

#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QSignalSpy>
#include <QTest>
#include <QUdpSocket>

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/video/video.h>

using namespace sortie;
using namespace sortie::video;
using State = VideoReceiver::State;

namespace {

constexpr int kWait = 20000;  // generous: the machine is shared, and x264 starts cold

sim::SimCameraFormat smallFormat()
{
    return sim::SimCameraFormat{640, 360, 30, 1500};
}

VideoReceiver::Options quickOptions()
{
    VideoReceiver::Options options;
    options.stallMs = 800;
    options.reconnectMs = 300;
    return options;
}

// Waits for `n` more frames and returns the last one's stamp (nullopt if one did not read back).
std::optional<quint64> waitForFrames(VideoReceiver &receiver, int n)
{
    const quint64 target = receiver.framesReceived() + quint64(n);
    if (!QTest::qWaitFor([&] { return receiver.framesReceived() >= target && receiver.state() == State::Playing; }, kWait))
        return std::nullopt;
    // A receiver that joined in the middle of a key frame decodes a partial picture until the next
    // one (a second: the camera's key-frame interval), and such a picture has no stamp (never a wrong
    // one): the next frames are tried, up to a second and a half of them.
    for (int attempt = 0; attempt < 45; ++attempt) {
        if (const auto stamp = FrameStamp::read(receiver.latestFrame().image))
            return stamp;
        const quint64 next = receiver.framesReceived() + 1;
        if (!QTest::qWaitFor([&] { return receiver.framesReceived() >= next; }, kWait))
            return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

class TestVideoReceiver : public QObject
{
    Q_OBJECT

    VideoRuntime m_runtime;  // GStreamer initialised once, by the test as by the client graph

private slots:
    void initTestCase()
    {
        QVERIFY2(m_runtime.isAvailable(), qPrintable(m_runtime.errorString()));
    }

    void rtpUdpFramesCarryTheirStamp()
    {
        const quint16 port = test::freeUdpPort();
        sim::SimCamera camera(QStringLiteral("vehicle/1"), smallFormat(), nullptr);
        QString error;
        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        VideoReceiver receiver(m_runtime, quickOptions());
        QSignalSpy frames(&receiver, &VideoReceiver::frameReady);
        const qint64 before = FrameStamp::nowMicros();
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:%1").arg(port));
        QCOMPARE(receiver.state(), State::Connecting);
        QVERIFY(receiver.statusText().contains(QLatin1String("Connecting")));
        const auto stamp = waitForFrames(receiver, 10);
        const VideoFrame frame = receiver.latestFrame();
        QVERIFY2(stamp, qPrintable(receiver.statusText()));
        QCOMPARE(frame.image.size(), QSize(640, 360));
        // The stamp is the camera's clock when it captured this frame: after the test began, before we got it.
        QVERIFY(qint64(*stamp) >= before);
        QVERIFY(qint64(*stamp) <= frame.receivedUs);
        QVERIFY(!frames.isEmpty());
        QVERIFY(!receiver.decoderName().isEmpty());
        QVERIFY2(receiver.statusText().contains(receiver.hardwareDecoding() ? QLatin1String("hardware") : QLatin1String("software")),
                 qPrintable(receiver.statusText()));
        QVERIFY(receiver.lastFrameTime().isValid());
        // The ground pattern under the stamp: fields of two greys, not a flat picture.
        QSet<int> greys;
        for (int x = 0; x < 640; x += 7)
            greys.insert(qGray(frame.image.pixel(x, 200)) / 16);
        QVERIFY2(greys.size() >= 3, "the picture is flat");
    }

    void stallsThenReconnectsByItself()
    {
        const quint16 port = test::freeUdpPort();
        sim::SimCamera camera(QStringLiteral("vehicle/1"), smallFormat(), nullptr);
        QString error;
        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        VideoReceiver receiver(m_runtime, quickOptions());
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:%1").arg(port));
        QVERIFY(waitForFrames(receiver, 5));

        camera.stopUdp();  // the encoder goes away
        QTRY_COMPARE_WITH_TIMEOUT(receiver.state(), State::Stalled, kWait);
        const QDateTime last = receiver.lastFrameTime();
        QVERIFY(last.isValid());
        QVERIFY2(receiver.statusText().contains(QStringLiteral("No video since %1").arg(last.toString(QStringLiteral("hh:mm:ss")))),
                 qPrintable(receiver.statusText()));
        const int attempts = receiver.attempts();
        QTRY_VERIFY_WITH_TIMEOUT(receiver.attempts() > attempts + 1, kWait);  // it keeps trying
        QCOMPARE(receiver.state(), State::Stalled);

        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));  // and comes back
        QVERIFY2(waitForFrames(receiver, 5), qPrintable(receiver.statusText()));
        QCOMPARE(receiver.state(), State::Playing);
        QVERIFY(receiver.lastFrameTime() > last);
    }

    void garbageAndTruncatedStreamsLeaveItAlive()
    {
        const quint16 port = test::freeUdpPort();
        sim::SimCamera camera(QStringLiteral("vehicle/1"), smallFormat(), nullptr);
        QString error;
        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        VideoReceiver receiver(m_runtime, quickOptions());
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:%1").arg(port));
        QVERIFY(waitForFrames(receiver, 5));

        // A flood of random datagrams to the port, among the camera's packets.
        QUdpSocket flood;
        QRandomGenerator random(35);
        for (int i = 0; i < 4000; ++i) {
            QByteArray junk(int(random.bounded(1, 1400)), Qt::Uninitialized);
            for (char &c : junk)
                c = char(random.bounded(256));
            flood.writeDatagram(junk, QHostAddress::LocalHost, port);
            if (i % 200 == 0)
                QTest::qWait(5);  // the event loop turns: the receiver's bus and hand-over go on
        }
        // Then the camera stops and only a truncated stream comes: RTP headers of the right payload
        // type and running sequence numbers whose H.264 is cut short or garbage.
        camera.stopUdp();
        for (int i = 0; i < 2000; ++i) {
            QByteArray packet(12 + int(random.bounded(0, 40)), '\0');
            packet[0] = char(0x80);
            packet[1] = char(96 | (i % 30 == 0 ? 0x80 : 0));
            packet[2] = char((i >> 8) & 0xff);
            packet[3] = char(i & 0xff);
            const quint32 ts = quint32(i / 3) * 3000;
            for (int b = 0; b < 4; ++b)
                packet[4 + b] = char(ts >> (24 - 8 * b));
            for (int b = 12; b < packet.size(); ++b)
                packet[b] = char(b == 12 ? (i % 2 ? 0x65 : 0x7c) : random.bounded(256));  // an IDR slice or an FU-A cut short
            flood.writeDatagram(packet, QHostAddress::LocalHost, port);
            if (i % 100 == 0)
                QTest::qWait(5);
        }
        QTRY_COMPARE_WITH_TIMEOUT(receiver.state(), State::Stalled, kWait);  // alive, and saying so
        QVERIFY(receiver.packetsRefused() > 0);  // the cut-short units never reached the depayloader
        QVERIFY(receiver.statusText().contains(QLatin1String("No video since")));

        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        const auto stamp = waitForFrames(receiver, 5);
        QVERIFY2(stamp, qPrintable(receiver.statusText()));
    }

    void badUrlGivesItsError()
    {
        VideoReceiver receiver(m_runtime, quickOptions());
        QSignalSpy changed(&receiver, &VideoReceiver::stateChanged);
        receiver.setUrl(QStringLiteral("http://camera/video.mjpg"));
        QCOMPARE(receiver.state(), State::Error);
        QVERIFY2(receiver.statusText().contains(QLatin1String("not a video URL")), qPrintable(receiver.statusText()));
        receiver.setUrl(QStringLiteral("udp://:0"));
        QCOMPARE(receiver.state(), State::Error);
        QVERIFY2(receiver.statusText().contains(QLatin1String("out of range")), qPrintable(receiver.statusText()));
        QCOMPARE(changed.count(), 2);  // the second error is a change too
        receiver.setUrl(QString());
        QCOMPARE(receiver.state(), State::Idle);
        QCOMPARE(receiver.statusText(), QStringLiteral("No video URL"));
    }

    void refusedRtspIsRetried()
    {
        VideoReceiver receiver(m_runtime, quickOptions());
        const quint16 port = test::freeUdpPort();  // nobody listens on this TCP port either, most likely
        receiver.setUrl(QStringLiteral("rtsp://127.0.0.1:%1/vehicle/1").arg(port));
        QTRY_VERIFY_WITH_TIMEOUT(!receiver.lastProblem().isEmpty(), kWait);
        QCOMPARE(receiver.state(), State::Connecting);
        QVERIFY2(receiver.statusText().contains(receiver.lastProblem()), qPrintable(receiver.statusText()));
    }

    void rtspFromTheSimulator()
    {
        sim::SimCamera camera(QStringLiteral("vehicle/1"), smallFormat(), nullptr);
        sim::SimRtspServer server;
        server.mount(camera.name(), &camera);
        QString error;
        QVERIFY2(server.listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
        QVERIFY(server.port() != 0);
        QCOMPARE(camera.consumers(), 0);  // nothing encoded until a client asks
        for (const QString &scheme : {QStringLiteral("rtsp"), QStringLiteral("rtspt")}) {
            VideoReceiver receiver(m_runtime, quickOptions());
            receiver.setUrl(server.url(camera.name()).replace(QLatin1String("rtsp://"), scheme + QStringLiteral("://")));
            const auto stamp = waitForFrames(receiver, 10);
            QVERIFY2(stamp, qPrintable(scheme + QLatin1String(": ") + receiver.statusText()));
            QVERIFY(qint64(*stamp) <= receiver.latestFrame().receivedUs);
            QVERIFY(receiver.sourceDescription().startsWith(QLatin1String("RTSP")));
        }
    }

    void recordsAsReceived()
    {
        const quint16 port = test::freeUdpPort();
        sim::SimCamera camera(QStringLiteral("vehicle/1"), smallFormat(), nullptr);
        QString error;
        QVERIFY2(camera.startUdp(QHostAddress::LocalHost, port, &error), qPrintable(error));
        QTemporaryDir dir;
        VideoReceiver receiver(m_runtime, quickOptions());
        receiver.setObjectName(QStringLiteral("EMU-101"));
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:%1").arg(port));
        QVERIFY(waitForFrames(receiver, 3));
        receiver.setRecordingFolder(dir.filePath(QStringLiteral("video")));
        QVERIFY(receiver.isRecording());
        const QString file = receiver.recordingFile();
        QVERIFY2(QFileInfo(file).fileName().startsWith(QLatin1String("EMU-101-")) && file.endsWith(QLatin1String("Z.mkv")), qPrintable(file));
        QVERIFY2(waitForFrames(receiver, 60), qPrintable(receiver.statusText()));  // two seconds of it, and it still plays
        receiver.setRecordingFolder(QString());
        QVERIFY(!receiver.isRecording());
        QVERIFY(QFileInfo(file).size() > 10000);

        // The file holds the camera's H.264 as it came: demuxed and decoded, its frames carry the stamps.
        GError *gerror = nullptr;
        const QByteArray launch = QStringLiteral("filesrc location=\"%1\" ! matroskademux ! video/x-h264 ! h264parse ! avdec_h264 "
                                                 "! videoconvert ! video/x-raw,format=BGRx ! appsink name=sink sync=false").arg(file).toUtf8();
        GstElement *player = gst_parse_launch(launch.constData(), &gerror);
        QVERIFY2(player && !gerror, gerror ? gerror->message : "no pipeline");
        GstElement *sink = gst_bin_get_by_name(GST_BIN(player), "sink");
        gst_element_set_state(player, GST_STATE_PLAYING);
        int stamped = 0, frames = 0;
        while (GstSample *sample = gst_app_sink_try_pull_sample(GST_APP_SINK(sink), 5 * GST_SECOND)) {
            GstVideoInfo info;
            GstVideoFrame frame;
            if (gst_video_info_from_caps(&info, gst_sample_get_caps(sample))
                && gst_video_frame_map(&frame, &info, gst_sample_get_buffer(sample), GST_MAP_READ)) {
                const QImage image(static_cast<const uchar *>(GST_VIDEO_FRAME_PLANE_DATA(&frame, 0)), GST_VIDEO_FRAME_WIDTH(&frame),
                                   GST_VIDEO_FRAME_HEIGHT(&frame), GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 0), QImage::Format_RGB32);
                stamped += FrameStamp::read(image).has_value();
                ++frames;
                gst_video_frame_unmap(&frame);
            }
            gst_sample_unref(sample);
        }
        gst_object_unref(sink);
        gst_element_set_state(player, GST_STATE_NULL);
        gst_object_unref(player);
        QVERIFY2(frames >= 30, qPrintable(QString::number(frames)));
        QVERIFY2(stamped >= frames * 9 / 10, qPrintable(QStringLiteral("%1 of %2").arg(stamped).arg(frames)));
    }

    void mpegTsOverUdp()
    {
        const quint16 port = test::freeUdpPort();
        GError *error = nullptr;
        const QByteArray launch = QStringLiteral("videotestsrc is-live=true pattern=ball ! video/x-raw,width=320,height=240,framerate=30/1 "
                                                 "! x264enc tune=zerolatency speed-preset=ultrafast key-int-max=15 ! mpegtsmux "
                                                 "! udpsink host=127.0.0.1 port=%1 sync=false")
                                      .arg(port)
                                      .toLatin1();
        GstElement *sender = gst_parse_launch(launch.constData(), &error);
        QVERIFY2(sender && !error, error ? error->message : "no pipeline");
        gst_element_set_state(sender, GST_STATE_PLAYING);
        const auto stop = qScopeGuard([sender] {
            gst_element_set_state(sender, GST_STATE_NULL);
            gst_object_unref(sender);
        });
        VideoReceiver receiver(m_runtime, quickOptions());
        receiver.setUrl(QStringLiteral("udp+ts://127.0.0.1:%1").arg(port));
        QVERIFY2(QTest::qWaitFor([&] { return receiver.framesReceived() >= 10; }, kWait), qPrintable(receiver.statusText()));
        QTRY_COMPARE_WITH_TIMEOUT(receiver.state(), State::Playing, kWait);
        QCOMPARE(receiver.frameSize(), QSize(320, 240));
        QVERIFY(!FrameStamp::read(receiver.latestFrame().image));  // a picture without a stamp reads as none
    }
};

QTEST_GUILESS_MAIN(TestVideoReceiver)
#include "tst_videoreceiver.moc"
