// The file of the zones the operator drew (CustomZoneFile.h), read at every start: any bytes are
// read or refused; every zone read is a drawn one, and what is read writes back and reads again to
// as many zones with the same server ids. The reader takes a path, so each input goes through a
// file of this process's own.
#include "CustomZoneFile.h"

#include <QDir>
#include <QFile>

#include <cstdlib>
#include <unistd.h>

using namespace sortie::airspace;

namespace {
QString inputPath()
{
    static const QString path = QDir::temp().filePath(QStringLiteral("fuzz_custom_zones-%1.geojson").arg(::getpid()));
    return path;
}

bool writeInput(const QByteArray &bytes)
{
    QFile file(inputPath());
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!writeInput(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size))))
        std::abort();
    const auto read = readCustomZones(inputPath());
    if (!read.ok()) {
        if (read.error().message.isEmpty())
            std::abort();
        return 0;
    }
    for (const Zone &z : read->zones)
        if (z.source != ZoneSource::ServerCustom)
            std::abort();
    if (!writeInput(customZonesJson(read->zones)))
        std::abort();
    const auto again = readCustomZones(inputPath());
    if (!again.ok() || again->zones.size() != read->zones.size())
        std::abort();
    for (size_t i = 0; i < read->zones.size(); ++i)
        if (again->zones[i].serverId != read->zones[i].serverId)
            std::abort();
    return 0;
}
