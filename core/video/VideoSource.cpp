#include "VideoSource.h"

#include <QFile>
#include <QHostAddress>
#include <QUrl>
#include <QUrlQuery>

#include <gst/sdp/sdp.h>

namespace sortie::video {
namespace {

using Parsed = VideoSource::Parsed;

Parsed failure(const QString &error)
{
    return Parsed{std::nullopt, error};
}

// Sortie's options: latency (ms), codec (h264, h265), payload (96..127). Unknown keys are an error,
// so a typing mistake is not silently ignored.
QString applyOptions(const QString &options, VideoSource &source, bool rtp)
{
    const QUrlQuery query(options);
    for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
        bool ok = false;
        if (key == QLatin1String("latency")) {
            const int ms = value.toInt(&ok);
            if (!ok || ms < 0 || ms > 10000)
                return VideoSource::tr("latency '%1': expected milliseconds from 0 to 10000").arg(value);
            source.latencyMs = ms;
        } else if (rtp && key == QLatin1String("codec")) {
            const QString codec = value.toLower();
            if (codec == QLatin1String("h264") || codec == QLatin1String("avc"))
                source.codec = VideoCodec::H264;
            else if (codec == QLatin1String("h265") || codec == QLatin1String("hevc"))
                source.codec = VideoCodec::H265;
            else
                return VideoSource::tr("codec '%1': expected h264 or h265").arg(value);
        } else if (rtp && key == QLatin1String("payload")) {
            const int pt = value.toInt(&ok);
            if (!ok || pt < 96 || pt > 127)
                return VideoSource::tr("payload '%1': expected a dynamic RTP payload type from 96 to 127").arg(value);
            source.payloadType = pt;
        } else {
            return VideoSource::tr("unknown option '%1'").arg(key);
        }
    }
    return {};
}

Parsed parseUdp(const QUrl &url, const QString &text, VideoTransport transport)
{
    VideoSource source;
    source.transport = transport;
    source.url = text;
    source.address = url.host();
    if (!source.address.isEmpty() && QHostAddress(source.address).isNull())
        return failure(VideoSource::tr("'%1' is not an IP address to listen on").arg(source.address));
    const int port = url.port(VideoSource::kDefaultUdpPort);
    if (port < 1 || port > 65535)
        return failure(VideoSource::tr("port %1 is out of range").arg(port));
    source.port = quint16(port);
    if (const QString error = applyOptions(url.query(), source, transport == VideoTransport::RtpUdp); !error.isEmpty())
        return failure(error);
    return Parsed{source, {}};
}

Parsed parseRtsp(const QUrl &url, const QString &text)
{
    if (url.host().isEmpty())
        return failure(VideoSource::tr("an RTSP URL needs a host: rtsp://host:8554/path"));
    if (url.port() == 0)
        return failure(VideoSource::tr("port 0 is out of range"));
    VideoSource source;
    source.transport = VideoTransport::Rtsp;
    source.url = text;
    source.tcpOnly = url.scheme() == QLatin1String("rtspt");
    QUrl location = url;
    location.setFragment(QString());
    source.location = location.toString(QUrl::FullyEncoded);
    if (const QString error = applyOptions(url.fragment(), source, false); !error.isEmpty())
        return failure(error);
    return Parsed{source, {}};
}

Parsed parseSdpFile(const QString &path, const QString &text)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return failure(VideoSource::tr("SDP file %1: %2").arg(path, file.errorString()));
    Parsed parsed = VideoSource::fromSdp(file.read(64 * 1024), path);
    if (parsed.source)
        parsed.source->url = text;
    return parsed;
}

} // namespace

QString VideoSource::codecName(VideoCodec codec)
{
    return codec == VideoCodec::H265 ? QStringLiteral("H.265") : QStringLiteral("H.264");
}

QString VideoSource::rtpCaps() const
{
    // i18n: not text below (GStreamer caps)
    return QStringLiteral("application/x-rtp, media=(string)video, clock-rate=(int)90000, encoding-name=(string)%1, payload=(int)%2")
        .arg(codec == VideoCodec::H265 ? QStringLiteral("H265") : QStringLiteral("H264"))
        .arg(payloadType);
}

// i18n: text again
QString VideoSource::describe() const
{
    switch (transport) {
    case VideoTransport::Rtsp: return tcpOnly ? tr("RTSP over TCP %1").arg(QUrl(location).authority()) : tr("RTSP %1").arg(QUrl(location).authority());
    case VideoTransport::RtpUdp: return tr("RTP/UDP %1 port %2").arg(codecName(codec)).arg(port);
    case VideoTransport::MpegTsUdp: return tr("MPEG-TS/UDP port %1").arg(port);
    }
    return {};
}

VideoSource::Parsed VideoSource::parse(const QString &given)
{
    const QString text = given.trimmed();
    if (text.isEmpty())
        return failure(tr("no video URL"));
    if (text.endsWith(QLatin1String(".sdp"), Qt::CaseInsensitive) && !text.contains(QLatin1String("://")))
        return parseSdpFile(text, text);
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid() || url.scheme().isEmpty())
        return failure(tr("'%1' is not a URL").arg(text));
    const QString scheme = url.scheme().toLower();
    if (scheme == QLatin1String("rtsp") || scheme == QLatin1String("rtspt"))
        return parseRtsp(url, text);
    if (scheme == QLatin1String("udp"))
        return parseUdp(url, text, VideoTransport::RtpUdp);
    if (scheme == QLatin1String("udp+ts"))
        return parseUdp(url, text, VideoTransport::MpegTsUdp);
    if (scheme == QLatin1String("file") && url.path().endsWith(QLatin1String(".sdp"), Qt::CaseInsensitive))
        return parseSdpFile(url.toLocalFile(), text);
    return failure(tr("'%1' is not a video URL Sortie plays: use rtsp://, rtspt://, udp://, udp+ts:// or an .sdp file").arg(url.scheme()));
}

VideoSource::Parsed VideoSource::fromSdp(const QByteArray &sdp, const QString &name)
{
    GstSDPMessage *message = nullptr;
    gst_sdp_message_new(&message);
    const auto freeMessage = qScopeGuard([message] { gst_sdp_message_free(message); });
    if (gst_sdp_message_parse_buffer(reinterpret_cast<const guint8 *>(sdp.constData()), guint(sdp.size()), message) != GST_SDP_OK)
        return failure(tr("SDP file %1 cannot be read as SDP").arg(name));
    for (guint i = 0; i < gst_sdp_message_medias_len(message); ++i) {
        const GstSDPMedia *media = gst_sdp_message_get_media(message, i);
        if (qstrcmp(gst_sdp_media_get_media(media), "video") != 0)
            continue;
        VideoSource source;
        source.transport = VideoTransport::RtpUdp;
        const guint port = gst_sdp_media_get_port(media);
        if (port < 1 || port > 65535)
            return failure(tr("SDP file %1: port %2 is out of range").arg(name).arg(port));
        source.port = quint16(port);
        if (gst_sdp_media_formats_len(media) < 1)
            return failure(tr("SDP file %1: the video has no payload type").arg(name));
        bool ok = false;
        source.payloadType = QString::fromUtf8(gst_sdp_media_get_format(media, 0)).toInt(&ok);
        if (!ok || source.payloadType < 96 || source.payloadType > 127)
            return failure(tr("SDP file %1: payload type %2 is not a dynamic one (96 to 127)").arg(name, QString::fromUtf8(gst_sdp_media_get_format(media, 0))));
        // a=rtpmap:96 H264/90000
        QString encoding;
        for (guint a = 0; a < gst_sdp_media_attributes_len(media); ++a) {
            const GstSDPAttribute *attribute = gst_sdp_media_get_attribute(media, a);
            if (qstrcmp(attribute->key, "rtpmap") != 0 || !attribute->value)
                continue;
            const QString value = QString::fromUtf8(attribute->value);
            if (value.section(QLatin1Char(' '), 0, 0).toInt() == source.payloadType)
                encoding = value.section(QLatin1Char(' '), 1).section(QLatin1Char('/'), 0, 0).toUpper();
        }
        if (encoding == QLatin1String("H264"))
            source.codec = VideoCodec::H264;
        else if (encoding == QLatin1String("H265"))
            source.codec = VideoCodec::H265;
        else
            return failure(encoding.isEmpty() ? tr("SDP file %1: no rtpmap for payload %2").arg(name).arg(source.payloadType)
                                              : tr("SDP file %1: the video is %2, not H.264 or H.265").arg(name, encoding));
        const GstSDPConnection *connection = gst_sdp_media_connections_len(media) > 0 ? gst_sdp_media_get_connection(media, 0)
                                                                                      : gst_sdp_message_get_connection(message);
        if (connection && connection->address) {
            const QHostAddress address(QString::fromUtf8(connection->address).section(QLatin1Char('/'), 0, 0));
            // A multicast group is joined; a unicast address is the sender's, we listen on any.
            if (address.isMulticast())
                source.address = address.toString();
        }
        return Parsed{source, {}};
    }
    return failure(tr("SDP file %1 describes no video").arg(name));
}

} // namespace sortie::video
