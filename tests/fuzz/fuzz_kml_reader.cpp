// KML polygon reader: any bytes are read or refused; a polygon read has at least 3 valid vertices.
#include "KmlFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto polygon = readKmlPolygon(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!polygon.ok())
        return 0;
    if (polygon->polygon.size() < 3)
        std::abort();
    for (const auto &p : polygon->polygon)
        if (!p.isValid())
            std::abort();
    return 0;
}
