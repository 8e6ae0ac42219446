#include "VideoPackages.h"

#include <QHash>

namespace sortie::video {

QString debianPackageOfElement(const QString &element)
{
    static const QHash<QString, QString> packages = {
        {QStringLiteral("rtspsrc"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("udpsrc"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("udpsink"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("rtpjitterbuffer"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("rtph264depay"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("rtph265depay"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("rtph264pay"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("matroskamux"), QStringLiteral("gstreamer1.0-plugins-good")},
        {QStringLiteral("h264parse"), QStringLiteral("gstreamer1.0-plugins-bad")},
        {QStringLiteral("h265parse"), QStringLiteral("gstreamer1.0-plugins-bad")},
        {QStringLiteral("tsdemux"), QStringLiteral("gstreamer1.0-plugins-bad")},
        {QStringLiteral("decodebin"), QStringLiteral("gstreamer1.0-plugins-base")},
        {QStringLiteral("parsebin"), QStringLiteral("gstreamer1.0-plugins-base")},
        {QStringLiteral("filesink"), QStringLiteral("libgstreamer1.0-0")},
        {QStringLiteral("videoconvert"), QStringLiteral("gstreamer1.0-plugins-base")},
        {QStringLiteral("appsink"), QStringLiteral("gstreamer1.0-plugins-base")},
        {QStringLiteral("appsrc"), QStringLiteral("gstreamer1.0-plugins-base")},
        {QStringLiteral("avdec_h264"), QStringLiteral("gstreamer1.0-libav")},
        {QStringLiteral("avdec_h265"), QStringLiteral("gstreamer1.0-libav")},
        {QStringLiteral("x264enc"), QStringLiteral("gstreamer1.0-plugins-ugly")},
    };
    return packages.value(element);
}

QString debianPackageOfDecoder(const QString &capsName)
{
    // libav decodes every codec a camera sends (H.264, H.265, MJPEG, MPEG-2/4); VA-API's decoders
    // (gstreamer1.0-vaapi, or plugins-bad's va) are an addition where a GPU offers them.
    if (capsName.startsWith(QLatin1String("video/")) || capsName.startsWith(QLatin1String("image/")))
        return QStringLiteral("gstreamer1.0-libav");
    if (capsName.startsWith(QLatin1String("application/x-rtp")))
        return QStringLiteral("gstreamer1.0-plugins-good");
    return {};
}

} // namespace sortie::video
