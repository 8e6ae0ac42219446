#include "SimCamera.h"

#include "FlightModel.h"
#include "FrameStamp.h"

#include <QLoggingCategory>
#include <QMutexLocker>

#include <algorithm>

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>

Q_LOGGING_CATEGORY(lcSimCamera, "sortie.sim.camera")

namespace sortie::sim {

SimCamera::SimCamera(QString name, SimCameraFormat format, PoseSource pose, QObject *parent)
    : QObject(parent)
    , m_name(std::move(name))
    , m_format(format)
    , m_pose(std::move(pose))
    , m_picture(format.width, format.height)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(std::max(1, 1000 / std::max(1, format.fps)));
    connect(&m_timer, &QTimer::timeout, this, &SimCamera::produce);
    m_timer.start();
}

SimCamera::~SimCamera()
{
    stopUdp();
    QMutexLocker lock(&m_mutex);
    for (GstElement *source : m_sources)
        gst_object_unref(source);
    m_sources.clear();
}

QString SimCamera::encoderDescription(const SimCameraFormat &f)
{
    return QStringLiteral("appsrc name=src caps=\"video/x-raw,format=I420,width=%1,height=%2,framerate=%3/1\" "
                          "! x264enc tune=zerolatency speed-preset=ultrafast key-int-max=%3 bitrate=%4 "
                          "! video/x-h264,profile=constrained-baseline ! rtph264pay name=pay0 pt=96 config-interval=-1 mtu=1400")
        .arg(f.width & ~1)
        .arg(f.height & ~1)
        .arg(f.fps)
        .arg(f.bitrateKbps);
}

bool SimCamera::startUdp(const QHostAddress &host, quint16 port, QString *error)
{
    stopUdp();
    const QString description = QStringLiteral("%1 ! udpsink name=sink sync=false async=false").arg(encoderDescription(m_format));
    GError *gerror = nullptr;
    GstElement *pipeline = gst_parse_launch(description.toLatin1().constData(), &gerror);
    if (!pipeline || gerror) {
        *error = QStringLiteral("camera %1: %2 (x264enc is in gstreamer1.0-plugins-ugly)").arg(m_name, gerror ? QString::fromUtf8(gerror->message) : QString());
        g_clear_error(&gerror);
        if (pipeline)
            gst_object_unref(pipeline);
        return false;
    }
    GstElement *sink = gst_bin_get_by_name(GST_BIN(pipeline), "sink");
    g_object_set(sink, "host", host.toString().toLatin1().constData(), "port", gint(port), nullptr);
    gst_object_unref(sink);
    m_udpSource = gst_bin_get_by_name(GST_BIN(pipeline), "src");
    g_object_set(m_udpSource, "is-live", TRUE, "format", GST_FORMAT_TIME, "do-timestamp", TRUE, "block", FALSE, "max-buffers", guint64(2), nullptr);
    gst_util_set_object_arg(G_OBJECT(m_udpSource), "leaky-type", "downstream");
    if (gst_element_set_state(pipeline, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
        *error = QStringLiteral("camera %1: the RTP/UDP sender did not start").arg(m_name);
        gst_object_unref(m_udpSource);
        m_udpSource = nullptr;
        gst_element_set_state(pipeline, GST_STATE_NULL);
        gst_object_unref(pipeline);
        return false;
    }
    m_udpPipeline = pipeline;
    m_udpPort = port;
    attach(m_udpSource);
    qCInfo(lcSimCamera).noquote() << m_name << "sends RTP/H.264 to" << host.toString() << port;
    return true;
}

void SimCamera::stopUdp()
{
    if (!m_udpPipeline)
        return;
    detach(m_udpSource);
    gst_element_set_state(m_udpPipeline, GST_STATE_NULL);
    gst_object_unref(m_udpSource);
    gst_object_unref(m_udpPipeline);
    m_udpSource = nullptr;
    m_udpPipeline = nullptr;
    m_udpPort = 0;
}

void SimCamera::attach(GstElement *appsrc)
{
    QMutexLocker lock(&m_mutex);
    m_sources.push_back(GST_ELEMENT(gst_object_ref(appsrc)));
}

void SimCamera::detach(GstElement *appsrc)
{
    QMutexLocker lock(&m_mutex);
    const auto it = std::find(m_sources.begin(), m_sources.end(), appsrc);
    if (it == m_sources.end())
        return;
    gst_object_unref(*it);
    m_sources.erase(it);
}

int SimCamera::consumers() const
{
    QMutexLocker lock(&m_mutex);
    return int(m_sources.size());
}

void SimCamera::drainUdpBus()
{
    if (!m_udpPipeline)
        return;
    GstBus *bus = gst_element_get_bus(m_udpPipeline);
    while (GstMessage *message = gst_bus_pop(bus)) {
        if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_ERROR) {
            GError *error = nullptr;
            gst_message_parse_error(message, &error, nullptr);
            qCWarning(lcSimCamera).noquote() << m_name << "RTP/UDP sender:" << (error ? error->message : "");
            g_clear_error(&error);
        }
        gst_message_unref(message);
    }
    gst_object_unref(bus);
}

void SimCamera::produce()
{
    drainUdpBus();
    if (consumers() == 0)
        return;
    GstBuffer *buffer = gst_buffer_new_allocate(nullptr, gsize(m_picture.frameBytes()), nullptr);
    GstMapInfo map;
    if (!gst_buffer_map(buffer, &map, GST_MAP_WRITE)) {
        gst_buffer_unref(buffer);
        return;
    }
    const CameraPose pose = m_pose ? m_pose() : CameraPose{};
    m_picture.draw(map.data, pose);
    // The capture time: the picture is whole now, as a sensor's frame is when it is read out.
    m_picture.stamp(map.data, quint64(video::FrameStamp::nowMicros()));
    gst_buffer_unmap(buffer, &map);
    ++m_frames;
    QMutexLocker lock(&m_mutex);
    for (GstElement *source : m_sources)
        gst_app_src_push_buffer(GST_APP_SRC(source), gst_buffer_ref(buffer));  // takes the reference
    lock.unlock();
    gst_buffer_unref(buffer);
}

SimCamera::PoseSource poseOf(const FlightModel &model)
{
    return [&model] {
        const FlightModel::State &s = model.state();
        return CameraPose{s.latitude, s.longitude, s.heading, s.altitudeAgl - s.floor};
    };
}

} // namespace sortie::sim
