// ZIP archive reader (libzip with Sortie's limits): any bytes are opened or refused with a reason;
// every entry listed is read or refused, and what is inflated stays within the limits.
#include "ZipArchive.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    ZipLimits limits;
    limits.maxEntryBytes = 1024 * 1024;
    limits.maxTotalBytes = 2 * 1024 * 1024;
    auto opened = ZipReader::open(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)), limits);
    if (!opened.ok()) {
        if (opened.error().message.isEmpty())
            std::abort();
        return 0;
    }
    ZipReader reader = std::move(opened).value();
    for (const QString &path : reader.paths()) {
        const auto bytes = reader.read(path);
        if (bytes.ok() && bytes->size() > limits.maxEntryBytes)
            std::abort();
        if (!bytes.ok() && bytes.error().message.isEmpty())
            std::abort();
    }
    if (reader.inflatedBytes() > limits.maxTotalBytes)
        std::abort();
    return 0;
}
