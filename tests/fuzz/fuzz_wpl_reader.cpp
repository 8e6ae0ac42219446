// QGC WPL 110 reader: any bytes are read or refused; what is read writes a file that reads back.
#include "WplFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto route = readWpl(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!route.ok())
        return 0;
    if (!readWpl(writeWpl(route->route)).ok())
        std::abort();
    return 0;
}
