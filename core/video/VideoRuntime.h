#pragma once

#include <QString>

namespace sortie::video {

// GStreamer, initialised once and explicitly by whoever builds the receivers (the client graph, a
// test, sortie-sim's camera): its constructor calls gst_init_check. A receiver takes one by
// reference, so no pipeline is built before GStreamer is up. GStreamer keeps its own process-wide
// registry (and cannot be initialised twice or shut down and restarted); this object adds no other
// global state, and several may exist (the second init is a no-op inside GStreamer).
class VideoRuntime
{
public:
    VideoRuntime();
    VideoRuntime(const VideoRuntime &) = delete;
    VideoRuntime &operator=(const VideoRuntime &) = delete;

    bool isAvailable() const { return m_error.isEmpty(); }
    QString errorString() const { return m_error; }
    // "GStreamer 1.22.0".
    QString version() const { return m_version; }

private:
    QString m_error;
    QString m_version;
};

} // namespace sortie::video
