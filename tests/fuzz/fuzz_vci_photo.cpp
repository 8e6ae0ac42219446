// The VCI photo report (VciPhoto.h, /camera/photo): any bytes that are JSON are a photo or refused
// with a reason (null alone is "none yet", with no reason). A photo read has a whole sequence from 1,
// a position on the globe and finite values, and writes back to itself.
#include "VciPhoto.h"

#include <cmath>
#include <cstdlib>
#include <numbers>

using namespace sortie::vci::profile;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const auto body = nlohmann::json::parse(data, data + size, nullptr, false);
    if (body.is_discarded())
        return 0;
    std::string error;
    const auto photo = decodePhoto(body, &error);
    if (!photo) {
        if (error.empty() != body.is_null())
            std::abort();
        return 0;
    }
    if (!error.empty() || photo->sequence < 1 || photo->time < 0 || !(std::abs(photo->latitude) <= std::numbers::pi / 2)
        || !(std::abs(photo->longitude) <= std::numbers::pi))
        std::abort();
    for (const auto &v : {photo->altitudeAmsl, photo->altitudeAgl, photo->roll, photo->pitch, photo->yaw, photo->gimbalTilt})
        if (v && !std::isfinite(*v))
            std::abort();
    if (!(decodePhoto(encodePhoto(*photo), nullptr) == *photo))
        std::abort();
    return 0;
}
