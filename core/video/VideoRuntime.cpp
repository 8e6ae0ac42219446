#include "VideoRuntime.h"

#include "VideoLog.h"

#include <QCoreApplication>

#include <gst/gst.h>

namespace sortie::video {

VideoRuntime::VideoRuntime()
{
    GError *error = nullptr;
    if (!gst_init_check(nullptr, nullptr, &error)) {
        m_error = QCoreApplication::translate("sortie::video::VideoRuntime", "GStreamer did not start: %1")
                      .arg(error ? QString::fromUtf8(error->message) : QString());
        g_clear_error(&error);
        qCWarning(lcVideo) << m_error;
        return;
    }
    gchar *version = gst_version_string();
    m_version = QString::fromUtf8(version);
    g_free(version);
    qCDebug(lcVideo) << "initialised" << m_version;
}

} // namespace sortie::video
