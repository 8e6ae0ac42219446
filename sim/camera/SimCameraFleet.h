#pragma once

#include "SimCameraOptions.h"
#include "SimRtspServer.h"

#include <memory>
#include <vector>

namespace sortie::video {
class VideoRuntime;
}

namespace sortie::sim {

// The cameras of sortie-sim's vehicles and how they are served (SimCameraOptions): vehicle N's
// camera at rtsp://ADDRESS:PORT/vehicle/N and as RTP/UDP to PORT+N-1. The runtime (GStreamer's
// initialisation) is the caller's and must outlive the fleet.
class SimCameraFleet
{
public:
    SimCameraFleet(video::VideoRuntime &runtime, SimCameraOptions options, QHostAddress address);
    ~SimCameraFleet();

    // Before start(): vehicle N's camera (N from 1), looking from `pose`.
    void addCamera(int number, SimCamera::PoseSource pose);
    bool start(QString *error);

    SimCamera *camera(int number) const;
    // The URI a vehicle publishes (video_stream_uri): its RTSP URL, else its RTP/UDP one; empty: none.
    QString streamUri(int number) const;
    QString rtspUrl(int number) const;
    QString udpUrl(int number) const;
    QStringList describe() const;

private:
    video::VideoRuntime &m_runtime;
    SimCameraOptions m_options;
    QHostAddress m_address;
    std::vector<std::pair<int, std::unique_ptr<SimCamera>>> m_cameras;
    std::unique_ptr<SimRtspServer> m_rtsp;  // after the cameras: destroyed first
};

} // namespace sortie::sim
