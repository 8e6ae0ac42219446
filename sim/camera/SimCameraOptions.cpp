#include "SimCameraOptions.h"

#include <QCommandLineParser>
#include <QRegularExpression>

namespace sortie::sim {

SimCameraOptions::SimCameraOptions()
    : m_rtsp(QStringLiteral("rtsp-port"),
             QStringLiteral("Serve each vehicle's camera over RTSP on this port as rtsp://ADDRESS:PORT/vehicle/N, published as its video_stream_uri "
                            "(default: off; 0 picks a free one)."),
             QStringLiteral("port"))
    , m_udp(QStringLiteral("camera-udp"),
            QStringLiteral("Send each vehicle's camera as RTP/H.264 over UDP: vehicle N to HOST:PORT+N-1 (default: off)."),
            QStringLiteral("host:port"))
    , m_size(QStringLiteral("camera-size"), QStringLiteral("The cameras' picture, WIDTHxHEIGHT (default 1280x720)."), QStringLiteral("WxH"))
    , m_fps(QStringLiteral("camera-fps"), QStringLiteral("The cameras' frame rate (default 30)."), QStringLiteral("fps"))
{
}

void SimCameraOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOption(m_rtsp);
    parser.addOption(m_udp);
    parser.addOption(m_size);
    parser.addOption(m_fps);
}

bool SimCameraOptions::read(const QCommandLineParser &parser, QString *error)
{
    bool ok = false;
    if (parser.isSet(m_rtsp)) {
        const uint value = parser.value(m_rtsp).toUInt(&ok);
        if (!ok || value > 65535) {
            *error = QStringLiteral("--rtsp-port: expected a port from 0 to 65535, got '%1'").arg(parser.value(m_rtsp));
            return false;
        }
        rtspPort = quint16(value);
    }
    if (parser.isSet(m_udp)) {
        const QString value = parser.value(m_udp);
        const int colon = value.lastIndexOf(QLatin1Char(':'));
        const uint port = value.mid(colon + 1).toUInt(&ok);
        const QHostAddress host(value.left(colon));
        if (colon < 1 || !ok || port < 1 || port > 65535 || host.isNull()) {
            *error = QStringLiteral("--camera-udp: expected HOST:PORT (an IP address), got '%1'").arg(value);
            return false;
        }
        udpHost = host;
        udpPort = quint16(port);
    }
    if (parser.isSet(m_size)) {
        const auto match = QRegularExpression(QStringLiteral("^(\\d{2,4})x(\\d{2,4})$")).match(parser.value(m_size));
        if (!match.hasMatch() || match.captured(1).toInt() < 320 || match.captured(2).toInt() < 180) {
            *error = QStringLiteral("--camera-size: expected WIDTHxHEIGHT of at least 320x180, got '%1'").arg(parser.value(m_size));
            return false;
        }
        format.width = match.captured(1).toInt();
        format.height = match.captured(2).toInt();
    }
    if (parser.isSet(m_fps)) {
        const int fps = parser.value(m_fps).toInt(&ok);
        if (!ok || fps < 1 || fps > 60) {
            *error = QStringLiteral("--camera-fps: expected 1 to 60, got '%1'").arg(parser.value(m_fps));
            return false;
        }
        format.fps = fps;
    }
    return true;
}

} // namespace sortie::sim
