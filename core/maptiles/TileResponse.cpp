#include "TileResponse.h"

#include <QCoreApplication>
#include <QLocale>
#include <QNetworkReply>
#include <QTimeZone>

#include <algorithm>

namespace sortie::maptiles {

namespace {
constexpr auto kTooLargeProperty = "sortieTileBodyTooLarge";
}

void limitTileBody(QNetworkReply *reply, qint64 limit)
{
    auto check = [reply, limit](qint64 received, qint64 total) {
        if ((received > limit || total > limit) && !reply->property(kTooLargeProperty).isValid()) {
            reply->setProperty(kTooLargeProperty, limit);
            reply->abort();
        }
    };
    QObject::connect(reply, &QNetworkReply::metaDataChanged, reply, [reply, check] {
        bool ok = false;
        const qint64 length = reply->header(QNetworkRequest::ContentLengthHeader).toLongLong(&ok);
        if (ok)
            check(0, length);
    });
    QObject::connect(reply, &QNetworkReply::downloadProgress, reply, check);
}

QString tileBodyRefusal(const QNetworkReply *reply)
{
    const QVariant limit = reply->property(kTooLargeProperty);
    if (!limit.isValid())
        return {};
    return QCoreApplication::translate("TileResponse", "larger than %1 MiB: not read").arg(double(limit.toLongLong()) / (1 << 20));
}

TileFormat sniffTileFormat(const QByteArray &bytes)
{
    if (bytes.startsWith("\x89PNG\r\n\x1a\n"))
        return TileFormat::Png;
    if (bytes.startsWith("\xff\xd8\xff"))
        return TileFormat::Jpeg;
    if (bytes.size() >= 12 && bytes.startsWith("RIFF") && bytes.mid(8, 4) == "WEBP")
        return TileFormat::Webp;
    if (bytes.startsWith("GIF87a") || bytes.startsWith("GIF89a"))
        return TileFormat::Gif;
    return TileFormat::Unknown;
}

QString formatName(TileFormat format)
{
    switch (format) {
    case TileFormat::Png: return QStringLiteral("png");
    case TileFormat::Jpeg: return QStringLiteral("jpg");
    case TileFormat::Webp: return QStringLiteral("webp");
    case TileFormat::Gif: return QStringLiteral("gif");
    case TileFormat::Unknown: break;
    }
    return {};
}

std::optional<double> parseRetryAfter(const QByteArray &value, const QDateTime &now)
{
    const QByteArray text = value.trimmed();
    if (text.isEmpty())
        return std::nullopt;
    bool isNumber = false;
    const qlonglong seconds = text.toLongLong(&isNumber);
    if (isNumber)
        return seconds >= 0 ? std::optional<double>(double(seconds)) : std::nullopt;
    // IMF-fixdate, e.g. "Wed, 21 Oct 2015 07:28:00 GMT".
    QDateTime when = QLocale::c().toDateTime(QString::fromLatin1(text), QStringLiteral("ddd, dd MMM yyyy HH:mm:ss 'GMT'"));
    if (!when.isValid())
        return std::nullopt;
    when.setTimeZone(QTimeZone::utc());
    return std::max(0.0, now.msecsTo(when) / 1000.0);
}

} // namespace sortie::maptiles
