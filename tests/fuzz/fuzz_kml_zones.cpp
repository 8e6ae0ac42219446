// KML zone reader: any bytes are read or refused; every zone read is an exclusion polygon whose
// rings have 3 or more valid vertices.
#include "ZoneFiles.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::airspace;
    const auto read = readKmlZones(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!read.ok())
        return 0;
    for (const Zone &z : read->zones) {
        const auto *p = std::get_if<ZonePolygons>(&z.shape);
        if (!p || p->parts.empty() || z.kind != ZoneKind::Exclusion)
            std::abort();
        for (const ZonePolygon &part : p->parts) {
            if (part.rings.empty())
                std::abort();
            for (const auto &ring : part.rings) {
                if (ring.size() < 3)
                    std::abort();
                for (const auto &g : ring)
                    if (!g.isValid())
                        std::abort();
            }
        }
    }
    return 0;
}
