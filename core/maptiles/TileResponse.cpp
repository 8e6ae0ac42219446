#include "TileResponse.h"

#include <QLocale>
#include <QTimeZone>

#include <algorithm>

namespace sortie::maptiles {

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
