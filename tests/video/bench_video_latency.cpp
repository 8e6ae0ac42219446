// bench_video_latency: glass-to-glass latency of live video over loopback (docs/video.md,
// docs/performance.md "Video"). sortie-sim (a process of its own, one vehicle) draws 1280x720 at
// 30 fps, stamps each picture with its capture time (FrameStamp) and encodes it with x264
// (zerolatency, ultrafast); the client's VideoReceiver receives it over RTP/UDP, then over RTSP, and
// each frame is taken on the main thread as the fly view's VideoItem takes it (frameReady →
// latestFrame); latency = the time it was taken − its stamp. Beside it, the reference: the same
// GStreamer elements with no hand-over (a fakesink's handoff reads the stamp on the streaming
// thread), and gst-launch-1.0 running that pipeline for its CPU. Reports p50/p95/p99, frames lost
// (gaps in the stamps), frames replaced before they were taken, unreadable stamps and the CPU of
// the receiving process (% of one core).
//   bench_video_latency [--seconds S] [--width W --height H]
#include "FrameStamp.h"
#include "ProcessStats.h"
#include "VideoReceiver.h"
#include "VideoRuntime.h"
#include "VideoTestSupport.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QMutex>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

#include <gst/gst.h>
#include <gst/video/video.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace sortie;

namespace {

int g_seconds = 15;
int g_width = 1280, g_height = 720;
constexpr int kFps = 30;

struct Figures
{
    std::vector<double> latencyMs;
    quint64 frames = 0, unreadable = 0, lost = 0, replaced = 0;
    double cpuPercent = 0;
    qint64 lastStamp = 0;

    void add(qint64 stamp, qint64 nowUs)
    {
        latencyMs.push_back((nowUs - stamp) / 1000.0);
        if (lastStamp)
            lost += quint64(std::max<qint64>(0, std::llround(double(stamp - lastStamp) * kFps / 1e6) - 1));
        lastStamp = stamp;
    }
    double percentile(double p)
    {
        if (latencyMs.empty())
            return NAN;
        std::sort(latencyMs.begin(), latencyMs.end());
        return latencyMs[std::min(latencyMs.size() - 1, size_t(p / 100.0 * double(latencyMs.size())))];
    }
    void print(const char *name)
    {
        const double p50 = percentile(50), p95 = percentile(95), p99 = percentile(99);
        std::printf("%-34s frames %5llu  latency ms p50 %6.1f p95 %6.1f p99 %6.1f  lost %4llu  replaced %4llu  unreadable %3llu  cpu %5.1f %%\n", name,
                    (unsigned long long)frames, p50, p95, p99, (unsigned long long)lost, (unsigned long long)replaced,
                    (unsigned long long)unreadable, cpuPercent);
        std::fflush(stdout);
    }
};

// Runs the event loop as the program does (QTest::qWait would sleep in 10 ms slices between events).
void runFor(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// sortie-sim with one vehicle's camera; returns its URL for `kind` ("rtsp" or "udp").
QString startSim(QProcess &sim, const QString &kind, quint16 udpPort)
{
    QStringList args{QStringLiteral("--port"), QStringLiteral("0"), QStringLiteral("--hci-vehicles"), QStringLiteral("1"),
                     QStringLiteral("--camera-size"), QStringLiteral("%1x%2").arg(g_width).arg(g_height)};
    if (kind == QLatin1String("rtsp"))
        args << QStringLiteral("--rtsp-port") << QStringLiteral("0");
    else
        args << QStringLiteral("--camera-udp") << QStringLiteral("127.0.0.1:%1").arg(udpPort);
    sim.setProcessChannelMode(QProcess::MergedChannels);
    sim.start(QStringLiteral(SORTIE_SIM_PROGRAM), args);
    QDeadlineTimer deadline(20000);
    QByteArray out;
    while (!deadline.hasExpired() && sim.state() != QProcess::NotRunning) {
        sim.waitForReadyRead(100);
        out += sim.readAll();
        if (out.contains("camera 1")) {
            if (kind == QLatin1String("rtsp"))
                return QRegularExpression(QStringLiteral("(rtsp://\\S+/vehicle/1)")).match(QString::fromUtf8(out)).captured(1);
            return QStringLiteral("udp://127.0.0.1:%1").arg(udpPort);
        }
    }
    std::fprintf(stderr, "sortie-sim did not start: %s\n", out.constData());
    return {};
}

// The client: VideoReceiver, frames taken on the main thread as the VideoItem takes them.
Figures runClient(video::VideoRuntime &runtime, const QString &url)
{
    Figures f;
    video::VideoReceiver receiver(runtime);
    QObject::connect(&receiver, &video::VideoReceiver::frameReady, [&] {
        const video::VideoFrame frame = receiver.latestFrame();
        const qint64 now = video::FrameStamp::nowMicros();
        ++f.frames;
        if (const auto stamp = video::FrameStamp::read(frame.image))
            f.add(qint64(*stamp), now);
        else
            ++f.unreadable;
    });
    receiver.setUrl(url);
    if (!QTest::qWaitFor([&] { return receiver.state() == video::VideoReceiver::State::Playing; }, 20000)) {
        std::fprintf(stderr, "no video from %s: %s\n", qPrintable(url), qPrintable(receiver.statusText()));
        return f;
    }
    runFor(2000);  // the encoder and the decoder warm up
    f = Figures{};
    const quint64 replacedBefore = receiver.framesDropped();
    const double cpu0 = test::ProcessStats::of().cpuSeconds;
    QElapsedTimer wall;
    wall.start();
    runFor(g_seconds * 1000);
    f.cpuPercent = 100.0 * (test::ProcessStats::of().cpuSeconds - cpu0) / (wall.elapsed() / 1000.0);
    f.replaced = receiver.framesDropped() - replacedBefore;
    return f;
}

// The reference: the same elements, the stamp read in a fakesink's handoff (no hand-over).
struct Reference
{
    QMutex mutex;
    Figures f;
    bool counting = false;
};

void onHandoff(GstElement *, GstBuffer *buffer, GstPad *pad, gpointer data)
{
    auto *ref = static_cast<Reference *>(data);
    const qint64 now = video::FrameStamp::nowMicros();
    GstCaps *caps = gst_pad_get_current_caps(pad);
    GstVideoInfo info;
    const bool ok = caps && gst_video_info_from_caps(&info, caps);
    if (caps)
        gst_caps_unref(caps);
    GstVideoFrame frame;
    if (!ok || !gst_video_frame_map(&frame, &info, buffer, GST_MAP_READ))
        return;
    const QImage image(static_cast<const uchar *>(GST_VIDEO_FRAME_PLANE_DATA(&frame, 0)), GST_VIDEO_FRAME_WIDTH(&frame), GST_VIDEO_FRAME_HEIGHT(&frame),
                       GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 0), QImage::Format_RGB32);
    const auto stamp = video::FrameStamp::read(image);
    gst_video_frame_unmap(&frame);
    QMutexLocker lock(&ref->mutex);
    if (!ref->counting)
        return;
    ++ref->f.frames;
    if (stamp)
        ref->f.add(qint64(*stamp), now);
    else
        ++ref->f.unreadable;
}

QString referencePipeline(const QString &url)
{
    const QString tail = QStringLiteral("videoconvert ! video/x-raw,format=BGRx ! fakesink name=sink sync=false");
    if (url.startsWith(QLatin1String("rtsp")))
        return QStringLiteral("rtspsrc location=%1 latency=100 drop-on-latency=true ! rtph264depay ! h264parse ! avdec_h264 output-corrupt=false ! %2").arg(url, tail);
    const int port = url.section(QLatin1Char(':'), -1).toInt();
    return QStringLiteral("udpsrc port=%1 caps=\"application/x-rtp,media=video,clock-rate=90000,encoding-name=H264,payload=96\" "
                          "! rtpjitterbuffer latency=100 drop-on-latency=true ! rtph264depay ! h264parse ! avdec_h264 output-corrupt=false ! %2")
        .arg(port)
        .arg(tail);
}

Figures runReference(const QString &url)
{
    Reference ref;
    GError *error = nullptr;
    GstElement *pipeline = gst_parse_launch(referencePipeline(url).toLatin1().constData(), &error);
    if (!pipeline || error) {
        std::fprintf(stderr, "reference pipeline: %s\n", error ? error->message : "?");
        return {};
    }
    GstElement *sink = gst_bin_get_by_name(GST_BIN(pipeline), "sink");
    g_object_set(sink, "signal-handoffs", TRUE, nullptr);
    g_signal_connect(sink, "handoff", G_CALLBACK(onHandoff), &ref);
    gst_object_unref(sink);
    gst_element_set_state(pipeline, GST_STATE_PLAYING);
    QTest::qWait(3000);
    {
        QMutexLocker lock(&ref.mutex);
        ref.counting = true;
    }
    const double cpu0 = test::ProcessStats::of().cpuSeconds;
    QElapsedTimer wall;
    wall.start();
    QTest::qWait(g_seconds * 1000);
    const double cpu = 100.0 * (test::ProcessStats::of().cpuSeconds - cpu0) / (wall.elapsed() / 1000.0);
    gst_element_set_state(pipeline, GST_STATE_NULL);
    gst_object_unref(pipeline);
    QMutexLocker lock(&ref.mutex);
    ref.f.cpuPercent = cpu;
    return ref.f;
}

// gst-launch-1.0 itself on the same pipeline (fakesink): its CPU, as the operator's reference.
double gstLaunchCpu(const QString &url)
{
    QProcess launch;
    QStringList args{QStringLiteral("-q")};
    args << QProcess::splitCommand(referencePipeline(url));
    launch.start(QStringLiteral("gst-launch-1.0"), args);
    if (!launch.waitForStarted(5000))
        return NAN;
    QTest::qWait(3000);
    const double cpu0 = test::ProcessStats::of(launch.processId()).cpuSeconds;
    QElapsedTimer wall;
    wall.start();
    QTest::qWait(g_seconds * 1000);
    const double cpu = 100.0 * (test::ProcessStats::of(launch.processId()).cpuSeconds - cpu0) / (wall.elapsed() / 1000.0);
    launch.terminate();
    if (!launch.waitForFinished(3000))
        launch.kill();
    return cpu;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--seconds"))
            g_seconds = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--width"))
            g_width = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--height"))
            g_height = args[i + 1].toInt();
    }
    video::VideoRuntime runtime;
    if (!runtime.isAvailable()) {
        std::fprintf(stderr, "%s\n", qPrintable(runtime.errorString()));
        return 1;
    }
    std::printf("bench_video_latency: %dx%d at %d fps from sortie-sim over loopback, %d s per run, %s\n", g_width, g_height, kFps, g_seconds,
                qPrintable(runtime.version()));
    for (const QString kind : {QStringLiteral("udp"), QStringLiteral("rtsp")}) {
        QProcess sim;
        const QString url = startSim(sim, kind, test::freeUdpPort());
        if (url.isEmpty())
            return 1;
        const QByteArray label = (kind == QLatin1String("udp") ? QByteArray("RTP/UDP") : QByteArray("RTSP"));
        runClient(runtime, url).print(label + " VideoReceiver -> main thread");
        runReference(url).print(label + " GStreamer alone (handoff)");
        std::printf("%-34s cpu %5.1f %%\n", (label + " gst-launch-1.0 fakesink").constData(), gstLaunchCpu(url));
        sim.terminate();
        sim.waitForFinished(5000);
    }
    return 0;
}
