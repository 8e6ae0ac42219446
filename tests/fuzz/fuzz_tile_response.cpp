// What a tile server answers (core/maptiles/TileResponse.h): any body is told a raster format or
// Unknown from its first bytes, and any Retry-After value is a wait of zero seconds or more, or
// nothing. The first byte splits the input into a body and a header value.
#include "TileResponse.h"

#include <QDateTime>
#include <QTimeZone>

#include <cmath>
#include <cstdlib>

using namespace sortie::maptiles;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    const size_t split = data[0] % size;
    const QByteArray body(reinterpret_cast<const char *>(data) + 1, qsizetype(split));
    const QByteArray retryAfter(reinterpret_cast<const char *>(data) + 1 + split, qsizetype(size - 1 - split));

    const TileFormat format = sniffTileFormat(body);
    if ((format == TileFormat::Unknown) != formatName(format).isEmpty())
        std::abort();
    if (format == TileFormat::Png && !body.startsWith("\x89PNG"))
        std::abort();

    static const QDateTime now = QDateTime(QDate(2026, 12, 2), QTime(12, 0), QTimeZone::utc());
    if (const auto wait = parseRetryAfter(retryAfter, now)) {
        if (!std::isfinite(*wait) || *wait < 0)
            std::abort();
    }
    return 0;
}
