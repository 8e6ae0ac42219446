// SRTM tile reader: any bytes are a tile or refused (the input as a file, and the input repeated to
// fill a 3″ tile so that the fuzzer controls the heights). A tile that is accepted answers every
// sample with NoData or a height between its lowest and highest posts.
#include "HgtTile.h"

#include <QByteArray>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::terrain;
    const QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    if (HgtTile::fromData(input, {56, 24}, QStringLiteral("fuzz.hgt"), &error))
        std::abort();  // no input under 2.8 MB is a whole tile
    if (error.isEmpty())
        std::abort();
    (void)parseHgtName(QString::fromLatin1(input.left(64)));
    if (size < 8)
        return 0;

    const qsizetype tileBytes = qsizetype(2) * 1201 * 1201;
    // The input repeated, by doubling copies: a byte at a time through operator[] made each run
    // take ~100 ms under the sanitizers (10 runs a second).
    QByteArray tileData(tileBytes, Qt::Uninitialized);
    char *out = tileData.data();
    const qsizetype first = std::min<qsizetype>(input.size(), tileBytes);
    std::memcpy(out, input.constData(), size_t(first));
    for (qsizetype filled = first; filled < tileBytes;) {
        const qsizetype n = std::min(filled, tileBytes - filled);
        std::memcpy(out + filled, out, size_t(n));
        filled += n;
    }
    error.clear();
    const auto tile = HgtTile::fromData(tileData, {56, 24}, QStringLiteral("fuzz.hgt"), &error);
    if (!tile) {
        if (!error.startsWith(QStringLiteral("fuzz.hgt: ")))
            std::abort();
        return 0;
    }
    int lowest = HgtTile::kHighest, highest = HgtTile::kLowest;
    // Every post is two consecutive input bytes (cyclically): bound the heights by all such pairs.
    for (size_t i = 0; i < size; ++i) {
        const int v = int16_t(uint16_t(data[i]) << 8 | data[(i + 1) % size]);
        if (v == HgtTile::kVoid)
            continue;
        lowest = std::min(lowest, v), highest = std::max(highest, v);
    }
    // Sample positions from the input's first bytes, across the whole cell and its edges.
    for (size_t k = 0; k + 3 < size && k < 64; k += 4) {
        const double lat = 56.0 + (uint16_t(data[k]) << 8 | data[k + 1]) / 65535.0;
        const double lon = 24.0 + (uint16_t(data[k + 2]) << 8 | data[k + 3]) / 65535.0;
        const ElevationSample s = tile->sample(lat, lon);
        if (s.status == SampleStatus::Pending)
            std::abort();
        if (s.hasValue() && (!std::isfinite(s.ground) || s.ground < lowest - 1e-6 || s.ground > highest + 1e-6))
            std::abort();
        if (!s.hasValue() && !std::isnan(s.ground))
            std::abort();
    }
    return 0;
}
