#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <optional>

class QNetworkReply;

namespace sortie::maptiles {

// The largest tile body taken from a server (a 512 px aerial JPEG is a few hundred KiB).
inline constexpr qint64 kMaxTileBodyBytes = 4 << 20;

// Watches a tile's reply as it downloads: once its Content-Length or the bytes received pass
// `limit`, the reply is aborted (a server streaming zeros fills no memory) and marked, so that
// tileBodyRefusal() says why when it finishes. Call right after the request is made.
void limitTileBody(QNetworkReply *reply, qint64 limit = kMaxTileBodyBytes);
// "larger than 4 MiB" for a reply limitTileBody aborted; empty otherwise.
QString tileBodyRefusal(const QNetworkReply *reply);

// What a tile server's bytes are: the raster formats MBTiles holds, told by their first bytes
// (a server's error page or an HTML captive portal is never stored as a tile).
enum class TileFormat { Unknown, Png, Jpeg, Webp, Gif };

TileFormat sniffTileFormat(const QByteArray &bytes);
// "png", "jpg", "webp", "gif" (MBTiles metadata's `format`), empty for Unknown.
QString formatName(TileFormat format);

// Seconds to wait from an HTTP Retry-After value: delta-seconds or an HTTP date (relative to
// `now`); nothing when the header is absent or unreadable.
std::optional<double> parseRetryAfter(const QByteArray &value, const QDateTime &now);

// Whether an HTTP status asks to try again later (429 Too Many Requests, any 5xx).
inline bool isRetryableStatus(int status) { return status == 429 || (status >= 500 && status <= 599); }

} // namespace sortie::maptiles
