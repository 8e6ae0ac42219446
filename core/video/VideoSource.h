#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace sortie::video {

// Where a stream comes from, as a value parsed from the URL an operator types or a vehicle sends as
// its `video_stream_uri` (docs/video.md, "Sources and URLs"):
//   rtsp://host[:port]/path            RTSP; RTP over UDP, falling back to TCP when nothing arrives
//   rtspt://host[:port]/path           RTSP with RTP interleaved over the TCP connection only
//   udp://[address]:port               RTP over UDP (H.264 by default), port 5600 when none is given;
//                                      the address is the local one to listen on or a multicast group
//   udp+ts://[address]:port            MPEG-TS over UDP (no RTP), whatever codec the stream carries
//   an .sdp file (a path or file://)   RTP over UDP described by the file (port, payload, codec, group)
// Sortie's own options ride where a server never sees them: in an RTSP URL's fragment
// (`rtsp://cam/live#latency=50`), in a udp URL's query (`udp://:5600?codec=h265&payload=97&latency=20`).
enum class VideoTransport { Rtsp, RtpUdp, MpegTsUdp };
struct ParsedVideoSource;
enum class VideoCodec { H264, H265 };

struct VideoSource
{
    Q_DECLARE_TR_FUNCTIONS(VideoSource)

public:
    static constexpr quint16 kDefaultUdpPort = 5600;
    static constexpr int kDefaultLatencyMs = 100;

    VideoTransport transport = VideoTransport::RtpUdp;
    QString url;            // as given (trimmed)
    QString location;       // RTSP: the URL handed to the server (without Sortie's fragment)
    bool tcpOnly = false;   // RTSP: rtspt://
    QString address;        // UDP: the address to listen on or the multicast group; empty: any
    quint16 port = kDefaultUdpPort;
    VideoCodec codec = VideoCodec::H264;  // RTP over UDP: the payload's codec
    int payloadType = 96;
    int latencyMs = kDefaultLatencyMs;    // the jitter buffer's wait for a late packet

    bool operator==(const VideoSource &) const = default;

    // The RTP caps of an RTP/UDP source ("application/x-rtp, media=video, ...").
    QString rtpCaps() const;
    // "RTSP 127.0.0.1:8554", "RTP/UDP H.264 port 5600", "MPEG-TS/UDP port 5000".
    QString describe() const;
    static QString codecName(VideoCodec codec);

    using Parsed = ParsedVideoSource;
    static Parsed parse(const QString &url);
    // The RTP/UDP source an SDP description gives (the text of an .sdp file); `name` is for the errors.
    static Parsed fromSdp(const QByteArray &sdp, const QString &name);
};

struct ParsedVideoSource
{
    std::optional<VideoSource> source;
    QString error;  // a sentence for the operator when there is no source
};

} // namespace sortie::video
