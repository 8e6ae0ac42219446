#pragma once

#include "SimCamera.h"

#include <QCommandLineOption>
#include <QHostAddress>

#include <optional>

class QCommandLineParser;

namespace sortie::sim {

// sortie-sim's camera options: --rtsp-port PORT serves each vehicle's camera at
// rtsp://ADDRESS:PORT/vehicle/N (0: a free port; absent: no RTSP), --camera-udp HOST:PORT sends
// vehicle N's RTP/H.264 to PORT+N-1 (absent: none), --camera-size WxH and --camera-fps.
class SimCameraOptions
{
public:
    SimCameraOptions();
    void addTo(QCommandLineParser &parser) const;
    // False with an error naming the option when a value does not parse.
    bool read(const QCommandLineParser &parser, QString *error);
    bool enabled() const { return rtspPort.has_value() || udpPort.has_value(); }

    std::optional<quint16> rtspPort;
    QHostAddress udpHost{QHostAddress::LocalHost};
    std::optional<quint16> udpPort;
    SimCameraFormat format;

private:
    QCommandLineOption m_rtsp;
    QCommandLineOption m_udp;
    QCommandLineOption m_size;
    QCommandLineOption m_fps;
};

} // namespace sortie::sim
