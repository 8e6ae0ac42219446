// .sortie reader: any bytes are read or refused; what is read writes back to the same bytes.
#include "SortieFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto mission = readSortie(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!mission.ok())
        return 0;
    const QByteArray once = writeSortie(*mission);
    const auto again = readSortie(once);
    if (!again.ok() || writeSortie(*again) != once)
        std::abort();
    return 0;
}
