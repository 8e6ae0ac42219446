// The VCI fence reader (VciFence.h): any bytes that are JSON are read or refused with a reason;
// every fence read is within the profile's limits, has usable shapes and writes back to itself.
#include "VciFence.h"

#include <cmath>
#include <cstdlib>

using namespace sortie::vci::profile;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const auto body = nlohmann::json::parse(data, data + size, nullptr, false);
    if (body.is_discarded())
        return 0;
    std::string error;
    const auto fence = decodeFence(body, &error);
    if (!fence) {
        if (error.empty())
            std::abort();
        return 0;
    }
    if (!fenceLimitProblem(*fence).empty())
        std::abort();
    for (const FenceItem &item : fence->items) {
        if (item.isCircle() ? !(item.radius > 0) || !item.polygon.empty() : item.polygon.size() < 3)
            std::abort();
        if (item.floor && item.ceiling && item.floor->reference == item.ceiling->reference && !(item.ceiling->altitude > item.floor->altitude))
            std::abort();
    }
    if (!(decodeFence(encodeFence(*fence), nullptr) == *fence))
        std::abort();
    decodeFenceStatus(body);
    return 0;
}
