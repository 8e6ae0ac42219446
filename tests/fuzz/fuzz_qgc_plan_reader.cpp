// QGroundControl .plan reader: any bytes are read or refused; what is read writes a plan that reads
// back, its geofence and rally points unchanged.
#include "QgcPlanFormat.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace sortie::mission::formats;
    const auto route = readQgcPlan(QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!route.ok())
        return 0;
    const auto back = readQgcPlan(writeQgcPlan(route->route));
    if (!back.ok() || !(back->route.fence == route->route.fence))
        std::abort();
    return 0;
}
