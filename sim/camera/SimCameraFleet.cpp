#include "SimCameraFleet.h"

#include "VideoRuntime.h"

namespace sortie::sim {

SimCameraFleet::SimCameraFleet(video::VideoRuntime &runtime, SimCameraOptions options, QHostAddress address)
    : m_runtime(runtime)
    , m_options(std::move(options))
    , m_address(std::move(address))
{
}

SimCameraFleet::~SimCameraFleet()
{
    m_rtsp.reset();  // its medias feed from the cameras
}

void SimCameraFleet::addCamera(int number, SimCamera::PoseSource pose)
{
    m_cameras.emplace_back(number, std::make_unique<SimCamera>(QStringLiteral("vehicle/%1").arg(number), m_options.format, std::move(pose)));
}

bool SimCameraFleet::start(QString *error)
{
    if (!m_runtime.isAvailable()) {
        *error = m_runtime.errorString();
        return false;
    }
    if (m_options.udpPort) {
        for (const auto &[number, camera] : m_cameras) {
            const int port = int(*m_options.udpPort) + number - 1;
            if (port > 65535 || !camera->startUdp(m_options.udpHost, quint16(port), error))
                return false;
        }
    }
    if (m_options.rtspPort) {
        m_rtsp = std::make_unique<SimRtspServer>();
        for (const auto &[number, camera] : m_cameras)
            m_rtsp->mount(camera->name(), camera.get());
        if (!m_rtsp->listen(m_address, *m_options.rtspPort, error))
            return false;
    }
    return true;
}

SimCamera *SimCameraFleet::camera(int number) const
{
    for (const auto &[n, camera] : m_cameras)
        if (n == number)
            return camera.get();
    return nullptr;
}

QString SimCameraFleet::rtspUrl(int number) const
{
    return m_rtsp && camera(number) ? m_rtsp->url(camera(number)->name()) : QString();
}

QString SimCameraFleet::udpUrl(int number) const
{
    const SimCamera *c = camera(number);
    return c && c->isSendingUdp() ? QStringLiteral("udp://:%1").arg(c->udpPort()) : QString();
}

QString SimCameraFleet::streamUri(int number) const
{
    const QString rtsp = rtspUrl(number);
    return rtsp.isEmpty() ? udpUrl(number) : rtsp;
}

QStringList SimCameraFleet::describe() const
{
    QStringList lines;
    for (const auto &[number, camera] : m_cameras) {
        QStringList where;
        if (!rtspUrl(number).isEmpty())
            where << rtspUrl(number);
        if (!udpUrl(number).isEmpty())
            where << QStringLiteral("RTP/UDP to %1:%2").arg(m_options.udpHost.toString()).arg(camera->udpPort());
        lines << QStringLiteral("camera %1 %2x%3@%4: %5")
                     .arg(number)
                     .arg(m_options.format.width)
                     .arg(m_options.format.height)
                     .arg(m_options.format.fps)
                     .arg(where.join(QStringLiteral(", ")));
    }
    return lines;
}

} // namespace sortie::sim
