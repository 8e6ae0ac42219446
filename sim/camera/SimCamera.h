#pragma once

#include "SimCameraPicture.h"

#include <QHostAddress>
#include <QMutex>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <functional>
#include <vector>

typedef struct _GstElement GstElement;

namespace sortie::sim {

class FlightModel;

struct SimCameraFormat
{
    int width = 1280;
    int height = 720;
    int fps = 30;
    int bitrateKbps = 4000;
};

// One vehicle's camera: every 1/fps s (a precise timer on this object's thread) it draws the view
// from the vehicle's pose with the capture time stamped in and pushes it to each encoder attached:
// its own RTP/UDP sender (startUdp) and the RTSP medias of the clients watching it (attach, called
// from the RTSP server's thread). With none attached it draws nothing. The encoders are x264 with
// tune=zerolatency and speed-preset=ultrafast, a key frame every second, and the RTP payloader
// repeats SPS/PPS with every key frame, so a receiver that joins late or reconnects decodes within
// a second.
class SimCamera : public QObject
{
    Q_OBJECT

public:
    using PoseSource = std::function<CameraPose()>;
    SimCamera(QString name, SimCameraFormat format, PoseSource pose, QObject *parent = nullptr);
    ~SimCamera() override;

    QString name() const { return m_name; }
    const SimCameraFormat &format() const { return m_format; }
    // appsrc (named src) to the x264 encoder and the payloader (pay0), as a gst-launch fragment: the
    // RTP/UDP sender and the RTSP factory both use it.
    static QString encoderDescription(const SimCameraFormat &format);

    // Sends RTP/H.264 to host:port (udpsink). False with the reason when the pipeline cannot be built.
    bool startUdp(const QHostAddress &host, quint16 port, QString *error);
    void stopUdp();
    bool isSendingUdp() const { return m_udpPipeline != nullptr; }
    quint16 udpPort() const { return m_udpPort; }

    // The RTSP server's thread: a media's appsrc starts and stops taking frames (a reference is kept).
    void attach(GstElement *appsrc);
    void detach(GstElement *appsrc);
    int consumers() const;

    quint64 framesDrawn() const { return m_frames.load(); }

private:
    void produce();
    void drainUdpBus();

    QString m_name;
    SimCameraFormat m_format;
    PoseSource m_pose;
    SimCameraPicture m_picture;
    QTimer m_timer;
    GstElement *m_udpPipeline = nullptr;
    GstElement *m_udpSource = nullptr;
    quint16 m_udpPort = 0;
    mutable QMutex m_mutex;
    std::vector<GstElement *> m_sources;  // guarded by m_mutex; each holds a reference
    std::atomic<quint64> m_frames{0};
};

// The pose of a simulated vehicle's camera, read from its flight model (which must outlive it).
SimCamera::PoseSource poseOf(const FlightModel &model);

} // namespace sortie::sim
