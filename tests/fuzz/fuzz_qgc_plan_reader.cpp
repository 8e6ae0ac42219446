// QGroundControl .plan reader: any bytes are read or refused; what is read writes a plan that reads back.
#include "QgcPlanFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto route = readQgcPlan(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!route.ok())
        return 0;
    if (!readQgcPlan(writeQgcPlan(route->route)).ok())
        std::abort();
    return 0;
}
