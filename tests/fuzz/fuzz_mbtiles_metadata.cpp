// MBTiles metadata (the rows of an offline map pack, core/maptiles): any rows are read without a
// crash; what is kept is within range, and writing it back reads back the same.
// Input: one row a line, name and value split at the first tab (seeds: tst_mbtiles).
#include "MbTilesMetadata.h"

#include <QByteArray>
#include <QList>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::maptiles;
    const QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    QList<QPair<QString, QString>> pairs;
    for (const QByteArray &line : input.split('\n')) {
        const qsizetype tab = line.indexOf('\t');
        if (tab >= 0)
            pairs.append({QString::fromUtf8(line.left(tab)), QString::fromUtf8(line.mid(tab + 1))});
    }
    const MbTilesMetadata meta = MbTilesMetadata::fromPairs(pairs);
    if (meta.minZoom && (*meta.minZoom < 0 || *meta.minZoom > 30))
        std::abort();
    if (meta.maxZoom && (*meta.maxZoom < 0 || *meta.maxZoom > 30))
        std::abort();
    if (meta.minZoom && meta.maxZoom && *meta.minZoom > *meta.maxZoom)
        std::abort();
    if (meta.bounds && !meta.bounds->isValid())
        std::abort();
    const MbTilesMetadata again = MbTilesMetadata::fromPairs(meta.toPairs());
    if (again.minZoom != meta.minZoom || again.maxZoom != meta.maxZoom || again.name != meta.name
        || again.attribution != meta.attribution || bool(again.bounds) != bool(meta.bounds))
        std::abort();
    return 0;
}
