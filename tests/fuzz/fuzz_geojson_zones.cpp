// GeoJSON zone reader: any bytes are read or refused; every zone read has a usable shape (valid
// positions, rings of 3 or more, positive radii) and limits in order; a bad feature is a problem,
// never a crash.
#include "ZoneFiles.h"

#include <cmath>
#include <cstdlib>

namespace {
void checkZone(const sortie::airspace::Zone &z)
{
    using namespace sortie::airspace;
    if (const auto *p = std::get_if<ZonePolygons>(&z.shape)) {
        if (p->parts.empty())
            std::abort();
        for (const ZonePolygon &part : p->parts)
            for (const auto &ring : part.rings) {
                if (ring.size() < 3)
                    std::abort();
                for (const auto &g : ring)
                    if (!g.isValid())
                        std::abort();
            }
    } else if (const auto *c = std::get_if<ZoneCircle>(&z.shape)) {
        if (!c->center.isValid() || !(c->radius > 0))
            std::abort();
    } else if (const auto *cone = std::get_if<ZoneConeFrustum>(&z.shape)) {
        if (!cone->center.isValid() || !(cone->bottomRadius > 0) || !(cone->topRadius >= 0) || !z.ceiling)
            std::abort();
    }
    if (z.floor && z.ceiling && !(z.ceiling->metres > z.floor->metres))
        std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const auto read = sortie::airspace::readGeoJsonZones(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!read.ok())
        return 0;
    for (const auto &z : read->zones)
        checkZone(z);
    return 0;
}
