#pragma once

#include <QHostAddress>
#include <QString>

#include <memory>
#include <thread>

namespace sortie::sim {

class SimCamera;

// sortie-sim's RTSP server (gst-rtsp-server): each camera mounted at /<path>, its encoder built when
// the first client asks for it (shared between clients) and fed from the camera's frames. The server
// runs on a GLib main loop of its own context in a thread this object owns, started by listen() and
// stopped (clients closed, thread joined) by the destructor; nothing of it runs on Qt's loop.
// The cameras must outlive the server.
class SimRtspServer
{
public:
    SimRtspServer();
    ~SimRtspServer();
    SimRtspServer(const SimRtspServer &) = delete;
    SimRtspServer &operator=(const SimRtspServer &) = delete;

    // Before listen(): serves `camera` at rtsp://address:port/<path>.
    void mount(const QString &path, SimCamera *camera);
    // Binds the port (0: a free one) and starts the thread.
    bool listen(const QHostAddress &address, quint16 port, QString *error);
    quint16 port() const { return m_port; }
    QString url(const QString &path) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
    QHostAddress m_address;
    quint16 m_port = 0;
};

} // namespace sortie::sim
