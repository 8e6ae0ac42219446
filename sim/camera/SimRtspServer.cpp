// gst-rtsp-server includes GIO, whose headers name a member `signals`, which Qt (in the precompiled
// header) defines as a keyword.
#pragma push_macro("signals")
#undef signals
#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/rtsp-server/rtsp-server.h>
#pragma pop_macro("signals")

#include "SimRtspServer.h"

#include "SimCamera.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcSimRtsp, "sortie.sim.rtsp")

namespace sortie::sim {
namespace {

constexpr const char *kAppSrcKey = "sortie-camera-appsrc";

void onUnprepared(GstRTSPMedia *media, gpointer data)
{
    auto *camera = static_cast<SimCamera *>(data);
    if (auto *appsrc = static_cast<GstElement *>(g_object_get_data(G_OBJECT(media), kAppSrcKey))) {
        camera->detach(appsrc);
        g_object_set_data(G_OBJECT(media), kAppSrcKey, nullptr);
    }
    qCInfo(lcSimRtsp).noquote() << camera->name() << "RTSP stream stopped";
}

void onMediaConfigure(GstRTSPMediaFactory *, GstRTSPMedia *media, gpointer data)
{
    auto *camera = static_cast<SimCamera *>(data);
    GstElement *element = gst_rtsp_media_get_element(media);
    GstElement *appsrc = gst_bin_get_by_name_recurse_up(GST_BIN(element), "src");
    gst_object_unref(element);
    if (!appsrc)
        return;
    g_object_set(appsrc, "is-live", TRUE, "format", GST_FORMAT_TIME, "do-timestamp", TRUE, "block", FALSE, "max-buffers", guint64(2), nullptr);
    gst_util_set_object_arg(G_OBJECT(appsrc), "leaky-type", "downstream");
    camera->attach(appsrc);
    g_object_set_data_full(G_OBJECT(media), kAppSrcKey, appsrc, gst_object_unref);
    g_signal_connect(media, "unprepared", G_CALLBACK(onUnprepared), camera);
    qCInfo(lcSimRtsp).noquote() << camera->name() << "RTSP stream started";
}

GstRTSPFilterResult closeClient(GstRTSPServer *, GstRTSPClient *, gpointer)
{
    return GST_RTSP_FILTER_REMOVE;
}

} // namespace

struct SimRtspServer::Impl
{
    GMainContext *context = g_main_context_new();
    GMainLoop *loop = g_main_loop_new(context, FALSE);
    GstRTSPServer *server = gst_rtsp_server_new();
    GSource *source = nullptr;
    std::thread thread;

    ~Impl()
    {
        if (thread.joinable()) {
            gst_rtsp_server_client_filter(server, closeClient, nullptr);
            // The loop runs until the closing clients' sources have been dispatched.
            GSource *quit = g_idle_source_new();
            g_source_set_callback(quit, [](gpointer loop) { g_main_loop_quit(static_cast<GMainLoop *>(loop)); return G_SOURCE_REMOVE; }, loop, nullptr);
            g_source_attach(quit, context);
            g_source_unref(quit);
            thread.join();
        }
        if (source) {
            g_source_destroy(source);
            g_source_unref(source);
        }
        gst_object_unref(server);
        g_main_loop_unref(loop);
        g_main_context_unref(context);
    }
};

SimRtspServer::SimRtspServer()
    : m(std::make_unique<Impl>())
{
    // Clients and medias on the server's own thread and context, no pool of threads of GStreamer's.
    GstRTSPThreadPool *pool = gst_rtsp_server_get_thread_pool(m->server);
    gst_rtsp_thread_pool_set_max_threads(pool, 0);
    g_object_unref(pool);
}

SimRtspServer::~SimRtspServer() = default;

void SimRtspServer::mount(const QString &path, SimCamera *camera)
{
    GstRTSPMountPoints *mounts = gst_rtsp_server_get_mount_points(m->server);
    GstRTSPMediaFactory *factory = gst_rtsp_media_factory_new();
    const QString launch = QStringLiteral("( %1 )").arg(SimCamera::encoderDescription(camera->format()));
    gst_rtsp_media_factory_set_launch(factory, launch.toLatin1().constData());
    gst_rtsp_media_factory_set_shared(factory, TRUE);
    g_signal_connect(factory, "media-configure", G_CALLBACK(onMediaConfigure), camera);
    gst_rtsp_mount_points_add_factory(mounts, ("/" + path).toUtf8().constData(), factory);  // takes the factory
    g_object_unref(mounts);
}

bool SimRtspServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    m_address = address;
    gst_rtsp_server_set_address(m->server, address.toString().toLatin1().constData());
    gst_rtsp_server_set_service(m->server, QByteArray::number(port).constData());
    GError *gerror = nullptr;
    m->source = gst_rtsp_server_create_source(m->server, nullptr, &gerror);
    if (!m->source) {
        *error = QStringLiteral("RTSP port %1: %2").arg(port).arg(gerror ? QString::fromUtf8(gerror->message) : QString());
        g_clear_error(&gerror);
        return false;
    }
    g_source_attach(m->source, m->context);
    m_port = quint16(gst_rtsp_server_get_bound_port(m->server));
    m->thread = std::thread([context = m->context, loop = m->loop] {
        g_main_context_push_thread_default(context);
        g_main_loop_run(loop);
        g_main_context_pop_thread_default(context);
    });
    return true;
}

QString SimRtspServer::url(const QString &path) const
{
    return QStringLiteral("rtsp://%1:%2/%3").arg(m_address.toString()).arg(m_port).arg(path);
}

} // namespace sortie::sim
