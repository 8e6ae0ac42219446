#include "RtpSanity.h"

namespace sortie::video {
namespace {

// Aggregation units: [16-bit size][unit] ... each unit at least `minimum` bytes, all inside.
bool aggregationFits(const uchar *p, int size, int minimum)
{
    if (size < 2 + minimum)
        return false;
    int at = 0;
    while (at < size) {
        if (at + 2 > size)
            return false;
        const int unit = (p[at] << 8) | p[at + 1];
        at += 2;
        if (unit < minimum || at + unit > size)
            return false;
        at += unit;
    }
    return true;
}

} // namespace

bool plausibleH264Payload(const uchar *payload, int size)
{
    if (size < 1)
        return false;
    const int type = payload[0] & 0x1f;
    if (type == 0)
        return false;
    if (type <= 23)
        return true;
    if (type == 24)  // STAP-A
        return aggregationFits(payload + 1, size - 1, 1);
    if (type == 28)  // FU-A: indicator, header, data
        return size >= 3 && !((payload[1] & 0x80) && (payload[1] & 0x40));  // not start and end at once
    return false;    // STAP-B, MTAP16/24, FU-B, reserved
}

bool plausibleH265Payload(const uchar *payload, int size)
{
    if (size < 3)
        return false;
    const int type = (payload[0] >> 1) & 0x3f;
    if (type < 48)
        return true;
    if (type == 48)  // AP
        return aggregationFits(payload + 2, size - 2, 2);
    if (type == 49)  // FU: header (2), FU header, data
        return size >= 4 && !((payload[2] & 0x80) && (payload[2] & 0x40));
    return false;    // PACI, reserved
}

} // namespace sortie::video
