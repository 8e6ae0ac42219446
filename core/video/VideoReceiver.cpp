#include "VideoReceiver.h"

#include "FrameStamp.h"
#include "RtpSanity.h"
#include "VideoLog.h"
#include "VideoPackages.h"
#include "VideoRuntime.h"

#include <QDir>
#include <QFile>
#include <QMutexLocker>
#include <QTime>

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/pbutils/missing-plugins.h>
#include <gst/rtp/gstrtpbuffer.h>
#include <gst/video/video.h>

namespace sortie::video {
namespace {

// A decoded frame kept mapped for as long as a QImage shares its memory.
struct MappedFrame
{
    GstSample *sample = nullptr;
    GstVideoFrame frame;
};

void releaseFrame(void *data)
{
    auto *mapped = static_cast<MappedFrame *>(data);
    gst_video_frame_unmap(&mapped->frame);
    gst_sample_unref(mapped->sample);
    delete mapped;
}

bool hasElement(const char *name)
{
    GstElementFactory *factory = gst_element_factory_find(name);
    if (!factory)
        return false;
    gst_object_unref(factory);
    return true;
}

// Whether some decoder of rank marginal or more (what decodebin plugs) takes these caps.
bool hasDecoderFor(const char *capsText)
{
    GList *decoders = gst_element_factory_list_get_elements(GST_ELEMENT_FACTORY_TYPE_DECODER | GST_ELEMENT_FACTORY_TYPE_MEDIA_VIDEO,
                                                            GST_RANK_MARGINAL);
    GstCaps *caps = gst_caps_from_string(capsText);
    GList *matching = gst_element_factory_list_filter(decoders, caps, GST_PAD_SINK, FALSE);
    const bool found = matching != nullptr;
    gst_plugin_feature_list_free(matching);
    gst_plugin_feature_list_free(decoders);
    gst_caps_unref(caps);
    return found;
}

// libav's decoders show the broken pictures of a stream joined between key frames unless told not to.
void onElementAdded(GstBin *, GstBin *, GstElement *element, gpointer)
{
    GstElementFactory *factory = gst_element_get_factory(element);
    if (factory && g_str_has_prefix(GST_OBJECT_NAME(factory), "avdec_") && g_object_class_find_property(G_OBJECT_GET_CLASS(element), "output-corrupt"))
        g_object_set(element, "output-corrupt", FALSE, nullptr);
}

gboolean selectVideoStream(GstElement *, guint, GstCaps *caps, gpointer chosen)
{
    auto *videoChosen = static_cast<bool *>(chosen);
    const GstStructure *s = gst_caps_get_structure(caps, 0);
    const char *media = s ? gst_structure_get_string(s, "media") : nullptr;
    if (*videoChosen || qstrcmp(media, "video") != 0)
        return FALSE;
    *videoChosen = true;
    return TRUE;
}

} // namespace

struct VideoReceiver::Pipeline
{
    VideoReceiver *receiver = nullptr;
    quint64 generation = 0;
    GstElement *pipeline = nullptr;
    GstBus *bus = nullptr;
    bool videoChosen = false;  // RTSP: the first video stream only
    bool h265 = false;

    ~Pipeline()
    {
        if (pipeline) {
            // Joins the streaming threads: no callback runs after this.
            gst_element_set_state(pipeline, GST_STATE_NULL);
            gst_object_unref(pipeline);
        }
        if (bus)
            gst_object_unref(bus);
    }

    // Before the depayloader: a payload it could crash on is dropped (RtpSanity.h).
    static GstPadProbeReturn screenRtp(GstPad *, GstPadProbeInfo *info, gpointer data)
    {
        auto *self = static_cast<Pipeline *>(data);
        GstBuffer *buffer = GST_PAD_PROBE_INFO_BUFFER(info);
        GstRTPBuffer rtp = GST_RTP_BUFFER_INIT;
        bool plausible = false;
        if (buffer && gst_rtp_buffer_map(buffer, GST_MAP_READ, &rtp)) {
            const auto *payload = static_cast<const uchar *>(gst_rtp_buffer_get_payload(&rtp));
            const int size = int(gst_rtp_buffer_get_payload_len(&rtp));
            plausible = self->h265 ? plausibleH265Payload(payload, size) : plausibleH264Payload(payload, size);
            gst_rtp_buffer_unmap(&rtp);
        }
        if (plausible)
            return GST_PAD_PROBE_OK;
        ++self->receiver->m_refused;
        return GST_PAD_PROBE_DROP;
    }

    static GstFlowReturn onNewSample(GstAppSink *sink, gpointer data)
    {
        auto *self = static_cast<Pipeline *>(data);
        GstSample *sample = gst_app_sink_pull_sample(sink);
        if (!sample)
            return GST_FLOW_OK;
        const qint64 receivedUs = FrameStamp::nowMicros();
        GstVideoInfo info;
        GstCaps *caps = gst_sample_get_caps(sample);
        GstBuffer *buffer = gst_sample_get_buffer(sample);
        if (!caps || !buffer || !gst_video_info_from_caps(&info, caps) || GST_VIDEO_INFO_FORMAT(&info) != GST_VIDEO_FORMAT_BGRx) {
            gst_sample_unref(sample);
            return GST_FLOW_OK;
        }
        auto *mapped = new MappedFrame;
        mapped->sample = sample;
        if (!gst_video_frame_map(&mapped->frame, &info, buffer, GST_MAP_READ)) {
            gst_sample_unref(sample);
            delete mapped;
            return GST_FLOW_OK;
        }
        QImage image(static_cast<const uchar *>(GST_VIDEO_FRAME_PLANE_DATA(&mapped->frame, 0)), GST_VIDEO_FRAME_WIDTH(&mapped->frame),
                     GST_VIDEO_FRAME_HEIGHT(&mapped->frame), GST_VIDEO_FRAME_PLANE_STRIDE(&mapped->frame, 0), QImage::Format_RGB32,
                     releaseFrame, mapped);
        self->receiver->handOver(std::move(image), receivedUs, self->generation);
        return GST_FLOW_OK;
    }
};

VideoReceiver::VideoReceiver(VideoRuntime &runtime, QObject *parent)
    : VideoReceiver(runtime, Options{}, parent)
{
}

VideoReceiver::VideoReceiver(VideoRuntime &runtime, Options options, QObject *parent)
    : QObject(parent)
    , m_runtime(runtime)
    , m_options(options)
{
    m_busTimer.setInterval(m_options.busPollMs);
    connect(&m_busTimer, &QTimer::timeout, this, &VideoReceiver::pollBus);
    m_watchdog.setInterval(std::max(20, std::min(200, m_options.stallMs / 4)));
    connect(&m_watchdog, &QTimer::timeout, this, &VideoReceiver::watch);
}

VideoReceiver::~VideoReceiver()
{
    teardown();
}

QString VideoReceiver::sourceDescription() const
{
    return m_source ? m_source->describe() : QString();
}

void VideoReceiver::setUrl(const QString &url)
{
    const QString trimmed = url.trimmed();
    if (trimmed == m_url && m_state != State::Idle)
        return;
    m_url = trimmed;
    if (trimmed.isEmpty()) {
        m_source.reset();
        emit sourceChanged();
        stop();
        return;
    }
    VideoSource::Parsed parsed = VideoSource::parse(trimmed);
    if (!parsed.source) {
        teardown();
        m_source.reset();
        emit sourceChanged();
        fail(tr("%1: %2").arg(trimmed, parsed.error));
        return;
    }
    setSource(*parsed.source);
}

void VideoReceiver::setSource(const VideoSource &source)
{
    teardown();
    m_source = source;
    m_url = source.url;
    m_lastFrameTime = {};
    m_lastProblem.clear();
    m_error.clear();
    m_missingPackage.clear();
    m_decoderName.clear();
    m_hardware = false;
    emit sourceChanged();
    emit decoderChanged();
    m_watchdog.start();
    build();
}

void VideoReceiver::setRecordingFolder(const QString &folder)
{
    if (folder == m_recordingFolder)
        return;
    m_recordingFolder = folder;
    const bool running = m_pipeline != nullptr;
    teardown();  // closes the file being written
    if (folder.isEmpty() && !m_recordingFile.isEmpty()) {
        m_recordingFile.clear();
        emit recordingChanged();
    }
    if (running)
        build();
    emit recordingChanged();
}

void VideoReceiver::stop()
{
    teardown();
    m_watchdog.stop();
    m_error.clear();
    m_missingPackage.clear();
    setState(State::Idle);
}

VideoFrame VideoReceiver::latestFrame() const
{
    QMutexLocker lock(&m_frameMutex);
    m_frameTaken = true;
    return m_frame;
}

void VideoReceiver::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    qCDebug(lcVideo) << m_url << "state" << state;
    emit stateChanged();
}

void VideoReceiver::fail(const QString &error, const QString &package)
{
    teardown();
    m_watchdog.stop();
    m_error = error;
    m_missingPackage = package;
    qCWarning(lcVideo).noquote() << error;
    m_state = State::Idle;  // stateChanged below even when already in Error with another reason
    setState(State::Error);
}

void VideoReceiver::retryLater(const QString &problem)
{
    qCInfo(lcVideo).noquote() << m_url << problem << "- retrying";
    teardown();
    m_lastProblem = problem;
    m_attemptClock.start();  // the wait before the next attempt
    const State next = m_lastFrameTime.isValid() ? State::Stalled : State::Connecting;
    if (next == m_state)
        emit stateChanged();  // the problem changed
    setState(next);
}

void VideoReceiver::build()
{
    Q_ASSERT(!m_pipeline);
    if (!m_source)
        return;
    if (!m_runtime.isAvailable()) {
        fail(m_runtime.errorString(), QStringLiteral("libgstreamer1.0-0"));
        return;
    }
    const VideoSource &source = *m_source;
    // i18n: not text below (GStreamer pipeline descriptions and caps)
    const bool h265 = source.codec == VideoCodec::H265;
    const bool recording = !m_recordingFolder.isEmpty();
    QStringList elements;
    QString description;
    switch (source.transport) {
    case VideoTransport::Rtsp:
        elements = {QStringLiteral("rtspsrc"), QStringLiteral("decodebin")};
        description = QStringLiteral("rtspsrc name=src ! %1decodebin").arg(recording ? QStringLiteral("parsebin ! tee name=rec ! ") : QString());
        break;
    case VideoTransport::RtpUdp:
        elements = {QStringLiteral("udpsrc"), QStringLiteral("rtpjitterbuffer"),
                    h265 ? QStringLiteral("rtph265depay") : QStringLiteral("rtph264depay"),
                    h265 ? QStringLiteral("h265parse") : QStringLiteral("h264parse"), QStringLiteral("decodebin")};
        description = QStringLiteral("udpsrc name=src ! rtpjitterbuffer name=jitter ! %1 name=depay ! %2 ! %3decodebin")
                          .arg(elements[2], elements[3], recording ? QStringLiteral("tee name=rec ! ") : QString());
        break;
    case VideoTransport::MpegTsUdp:
        elements = {QStringLiteral("udpsrc"), QStringLiteral("tsdemux"), QStringLiteral("decodebin")};
        description = QStringLiteral("udpsrc name=src ! %1decodebin").arg(recording ? QStringLiteral("parsebin ! tee name=rec ! ") : QString());
        break;
    }
    elements << QStringLiteral("videoconvert") << QStringLiteral("appsink");
    if (recording)
        elements << QStringLiteral("parsebin") << QStringLiteral("matroskamux") << QStringLiteral("filesink");
    for (const QString &element : std::as_const(elements)) {
        if (!hasElement(element.toLatin1().constData())) {
            const QString package = debianPackageOfElement(element);
            fail(tr("GStreamer's %1 is missing: install %2").arg(element, package), package);
            return;
        }
    }
    if (source.transport == VideoTransport::RtpUdp && !hasDecoderFor(h265 ? "video/x-h265" : "video/x-h264")) {
        const QString package = debianPackageOfDecoder(QStringLiteral("video/x-h264"));
        fail(tr("No %1 decoder: install %2").arg(VideoSource::codecName(source.codec), package), package);
        return;
    }
    description += QStringLiteral(" ! videoconvert ! video/x-raw,format=BGRx ! appsink name=sink");
    // Recording: the parsed stream as it came, muxed without re-encoding; streamable, so a file cut
    // short (the pipeline rebuilt, the program killed) still plays.
    QString file;
    if (recording) {
        description += QStringLiteral(" rec. ! queue max-size-buffers=0 max-size-bytes=0 max-size-time=2000000000 leaky=downstream"
                                      " ! matroskamux streamable=true ! filesink name=file async=false");
        QDir().mkpath(m_recordingFolder);
        file = QDir(m_recordingFolder).filePath(QStringLiteral("%1-%2.mkv")
                                                    .arg(objectName().isEmpty() ? QStringLiteral("video") : objectName(),
                                                         QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss.zzz'Z'"))));
    }
    // i18n: text again

    GError *error = nullptr;
    GstElement *element = gst_parse_launch(description.toLatin1().constData(), &error);
    if (!element || error) {
        const QString reason = error ? QString::fromUtf8(error->message) : QString();
        g_clear_error(&error);
        if (element)
            gst_object_unref(element);
        fail(tr("The video pipeline could not be built: %1").arg(reason));
        return;
    }
    auto pipeline = std::make_unique<Pipeline>();
    pipeline->receiver = this;
    pipeline->generation = ++m_generation;
    pipeline->pipeline = element;
    pipeline->bus = gst_element_get_bus(element);

    g_signal_connect(element, "deep-element-added", G_CALLBACK(onElementAdded), nullptr);
    GstElement *src = gst_bin_get_by_name(GST_BIN(element), "src");
    if (source.transport == VideoTransport::Rtsp) {
        g_object_set(src, "location", source.location.toUtf8().constData(), "latency", guint(source.latencyMs), "drop-on-latency", TRUE,
                     // nothing over UDP for 2 s: ask for TCP (rtspsrc's own fallback)
                     "timeout", guint64(2'000'000), "tcp-timeout", guint64(5'000'000), nullptr);
        if (source.tcpOnly)
            gst_util_set_object_arg(G_OBJECT(src), "protocols", "tcp");
        g_signal_connect(src, "select-stream", G_CALLBACK(selectVideoStream), &pipeline->videoChosen);
    } else {
        const QByteArray address = source.address.isEmpty() ? QByteArrayLiteral("0.0.0.0") : source.address.toLatin1();
        GstCaps *caps = gst_caps_from_string(source.transport == VideoTransport::RtpUdp ? source.rtpCaps().toLatin1().constData()
                                                                                         : "video/mpegts, systemstream=(boolean)true"); // i18n: not text (caps)
        g_object_set(src, "port", gint(source.port), "address", address.constData(), "caps", caps, "buffer-size", gint(4 << 20), nullptr);
        gst_caps_unref(caps);
        if (GstElement *jitter = gst_bin_get_by_name(GST_BIN(element), "jitter")) {
            g_object_set(jitter, "latency", guint(source.latencyMs), "drop-on-latency", TRUE, nullptr);
            gst_object_unref(jitter);
        }
        if (GstElement *depay = gst_bin_get_by_name(GST_BIN(element), "depay")) {
            pipeline->h265 = h265;
            GstPad *pad = gst_element_get_static_pad(depay, "sink");
            gst_pad_add_probe(pad, GST_PAD_PROBE_TYPE_BUFFER, &Pipeline::screenRtp, pipeline.get(), nullptr);
            gst_object_unref(pad);
            gst_object_unref(depay);
        }
    }
    gst_object_unref(src);

    if (GstElement *fileSink = gst_bin_get_by_name(GST_BIN(element), "file")) {
        g_object_set(fileSink, "location", QFile::encodeName(file).constData(), nullptr);
        gst_object_unref(fileSink);
    }
    if (file != m_recordingFile) {
        m_recordingFile = file;
        emit recordingChanged();
    }
    GstElement *sink = gst_bin_get_by_name(GST_BIN(element), "sink");
    g_object_set(sink, "drop", TRUE, "max-buffers", guint(1), "sync", FALSE, "emit-signals", FALSE, "enable-last-sample", FALSE, nullptr);
    GstAppSinkCallbacks callbacks{};
    callbacks.new_sample = &Pipeline::onNewSample;
    gst_app_sink_set_callbacks(GST_APP_SINK(sink), &callbacks, pipeline.get(), nullptr);
    gst_object_unref(sink);

    m_pipeline = std::move(pipeline);
    ++m_attempts;
    m_frameThisAttempt = false;
    m_attemptClock.start();
    if (m_state != State::Stalled)
        setState(State::Connecting);
    qCDebug(lcVideo).noquote() << "attempt" << m_attempts << "on" << source.describe() << ":" << description;
    if (gst_element_set_state(element, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE)
        qCDebug(lcVideo) << "PLAYING refused; the bus says why";
    m_busTimer.start();
}

void VideoReceiver::teardown()
{
    m_busTimer.stop();
    // A recording ends with an end of stream through its muxer: what its queue still holds (up to
    // 2 s) is written and the file closed, rather than dropped by the stop. Bounded, so a stalled
    // pipeline cannot hold the GUI thread.
    if (m_pipeline && !m_recordingFile.isEmpty()) {
        gst_element_send_event(m_pipeline->pipeline, gst_event_new_eos());
        if (GstMessage *end = gst_bus_timed_pop_filtered(m_pipeline->bus, GST_SECOND, GstMessageType(GST_MESSAGE_EOS | GST_MESSAGE_ERROR)))
            gst_message_unref(end);
    }
    m_pipeline.reset();
}

void VideoReceiver::pollBus()
{
    while (m_pipeline) {
        GstMessage *message = gst_bus_pop(m_pipeline->bus);
        if (!message)
            return;
        const auto unref = qScopeGuard([message] { gst_message_unref(message); });
        switch (GST_MESSAGE_TYPE(message)) {
        case GST_MESSAGE_ELEMENT:
            if (gst_is_missing_plugin_message(message)) {
                gchar *what = gst_missing_plugin_message_get_description(message);
                gchar *detail = gst_missing_plugin_message_get_installer_detail(message);
                const QString description = QString::fromUtf8(what);
                // "gstreamer|1.0|app|H.264 decoder|decoder-video/x-h264, ..."
                const QString caps = QString::fromUtf8(detail).section(QLatin1Char('|'), 4).section(QLatin1Char('-'), 1).section(QLatin1Char(','), 0, 0);
                g_free(what);
                g_free(detail);
                QString package = debianPackageOfDecoder(caps);
                if (package.isEmpty())
                    package = QStringLiteral("gstreamer1.0-plugins-bad");
                fail(tr("No %1: install %2").arg(description, package), package);
                return;
            }
            break;
        case GST_MESSAGE_ERROR: {
            GError *error = nullptr;
            gchar *debug = nullptr;
            gst_message_parse_error(message, &error, &debug);
            const QString text = QString::fromUtf8(error->message);
            const bool missing = error->domain == GST_CORE_ERROR && error->code == GST_CORE_ERROR_MISSING_PLUGIN;
            qCDebug(lcVideo).noquote() << GST_OBJECT_NAME(GST_MESSAGE_SRC(message)) << text << debug;
            g_clear_error(&error);
            g_free(debug);
            if (missing)
                fail(tr("A GStreamer plugin is missing: %1").arg(text), QStringLiteral("gstreamer1.0-plugins-bad"));
            else
                retryLater(text);
            return;
        }
        case GST_MESSAGE_EOS:
            retryLater(tr("the stream ended"));
            return;
        case GST_MESSAGE_WARNING: {
            GError *error = nullptr;
            gst_message_parse_warning(message, &error, nullptr);
            qCDebug(lcVideo).noquote() << "warning:" << (error ? error->message : "");
            g_clear_error(&error);
            break;
        }
        default:
            break;
        }
    }
}

void VideoReceiver::watch()
{
    if (m_state == State::Error || m_state == State::Idle)
        return;
    if (!m_pipeline) {
        if (m_attemptClock.elapsed() >= m_options.reconnectMs)
            build();
        return;
    }
    if (m_frameThisAttempt) {
        if (m_frameClock.elapsed() > m_options.stallMs) {
            setState(State::Stalled);
            retryLater(tr("no frame for %1 s").arg(m_options.stallMs / 1000.0, 0, 'f', 1));
        }
        return;
    }
    const int attemptMs = m_source && m_source->transport == VideoTransport::Rtsp ? m_options.rtspAttemptMs
                                                                                   : std::max(m_options.stallMs, m_options.reconnectMs);
    if (m_attemptClock.elapsed() > attemptMs)
        retryLater(m_lastFrameTime.isValid() ? tr("no frame since the last attempt") : tr("nothing received yet"));
}

void VideoReceiver::handOver(QImage image, qint64 receivedUs, quint64 generation)
{
    {
        QMutexLocker lock(&m_frameMutex);
        if (!m_frameTaken)
            ++m_dropped;
        m_frame = VideoFrame{std::move(image), receivedUs, ++m_received};
        m_frameTaken = false;
    }
    if (!m_notifyPending.exchange(true))
        QMetaObject::invokeMethod(this, [this, generation] { onFrameArrived(generation); }, Qt::QueuedConnection);
}

void VideoReceiver::onFrameArrived(quint64 generation)
{
    m_notifyPending = false;
    if (!m_pipeline || generation != m_pipeline->generation)
        return;  // a frame of a pipeline torn down since
    m_frameThisAttempt = true;
    m_frameClock.start();
    m_lastFrameTime = QDateTime::currentDateTime();
    QSize size;
    {
        QMutexLocker lock(&m_frameMutex);
        size = m_frame.image.size();
    }
    if (m_decoderName.isEmpty() || size != m_frameSize) {
        m_frameSize = size;
        findDecoder();
    }
    if (m_state != State::Playing) {
        m_lastProblem.clear();
        setState(State::Playing);
    }
    emit frameReady();
}

void VideoReceiver::findDecoder()
{
    if (!m_pipeline)
        return;
    GstIterator *it = gst_bin_iterate_recurse(GST_BIN(m_pipeline->pipeline));
    GValue item = G_VALUE_INIT;
    for (bool done = false; !done;) {
        switch (gst_iterator_next(it, &item)) {
        case GST_ITERATOR_OK: {
            auto *element = GST_ELEMENT(g_value_get_object(&item));
            if (GstElementFactory *factory = gst_element_get_factory(element)) {
                const QString klass = QString::fromUtf8(gst_element_factory_get_metadata(factory, GST_ELEMENT_METADATA_KLASS));
                if (klass.contains(QLatin1String("Decoder")) && klass.contains(QLatin1String("Video"))) {
                    m_decoderName = QString::fromUtf8(GST_OBJECT_NAME(factory));
                    m_hardware = klass.contains(QLatin1String("Hardware"));
                    done = true;
                }
            }
            g_value_reset(&item);
            break;
        }
        case GST_ITERATOR_RESYNC:
            gst_iterator_resync(it);
            break;
        default:
            done = true;
        }
    }
    g_value_unset(&item);
    gst_iterator_free(it);
    qCInfo(lcVideo).noquote() << m_url << "decoded by" << m_decoderName << (m_hardware ? "(hardware)" : "(software)") << m_frameSize;
    emit decoderChanged();
}

QString VideoReceiver::statusText() const
{
    switch (m_state) {
    case State::Idle:
        return m_url.isEmpty() ? tr("No video URL") : tr("Video stopped");
    case State::Connecting:
        return m_lastProblem.isEmpty() ? tr("Connecting to %1…").arg(sourceDescription())
                                       : tr("Connecting to %1… (%2)").arg(sourceDescription(), m_lastProblem);
    case State::Playing:
        return tr("%1, %2×%3, %4 decoding (%5)")
            .arg(sourceDescription())
            .arg(m_frameSize.width())
            .arg(m_frameSize.height())
            .arg(m_hardware ? tr("hardware") : tr("software"), m_decoderName);
    case State::Stalled: {
        const qint64 seconds = m_lastFrameTime.secsTo(QDateTime::currentDateTime());
        const QString elapsed = QTime(0, 0).addSecs(int(std::min<qint64>(seconds, 86399))).toString(seconds >= 3600 ? QStringLiteral("hh:mm:ss") : QStringLiteral("mm:ss"));
        return tr("No video since %1 (%2); reconnecting").arg(m_lastFrameTime.toString(QStringLiteral("hh:mm:ss")), elapsed);
    }
    case State::Error:
        return m_error;
    }
    return {};
}

} // namespace sortie::video
