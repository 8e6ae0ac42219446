// The autosave reader (AutosaveRecord.h), what recovery reads after a crash: any bytes are read or
// refused with a reason, and what is read writes back to the same bytes once written again.
#include "AutosaveRecord.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::client;
    const auto record = decodeAutosave(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!record.ok()) {
        if (record.error().message.isEmpty())
            std::abort();
        return 0;
    }
    const QByteArray once = encodeAutosave(*record);
    const auto again = decodeAutosave(once);
    if (!again.ok() || encodeAutosave(*again) != once)
        std::abort();
    return 0;
}
