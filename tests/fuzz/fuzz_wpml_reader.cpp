// DJI WPML reader, over a KMZ or a bare waylines document: any bytes are read or refused with a
// reason; a file read gives at least one route, and each route at least one segment.
#include "WpmlFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto read = readWpml(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!read.ok()) {
        if (read.error().message.isEmpty())
            std::abort();
        return 0;
    }
    if (read->routes.empty())
        std::abort();
    for (const auto &route : read->routes)
        if (route.segments.empty())
            std::abort();
    return 0;
}
